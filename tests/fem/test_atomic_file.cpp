// writeAtomically: the file appears complete or not at all, and no NAME.tmp stays behind —
// neither when the writer fails nor when the finished file cannot take the target's place
// (here the target is a directory, as when summary.json cannot be written).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "fem/AtomicFile.hpp"

namespace fs = std::filesystem;

TEST(AtomicFile, LeavesNoTemporaryFileBehind) {
    const fs::path dir = fs::temp_directory_path() / ("flexehd_atomic_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "summary.json");  // a directory where the file should go
    auto write = [](const std::string& tmp) { std::ofstream(tmp) << "{}\n"; };
    EXPECT_THROW(flexehd::fem::writeAtomically((dir / "summary.json").string(), write), std::runtime_error);
    EXPECT_FALSE(fs::exists(dir / "summary.json.tmp"));
    EXPECT_THROW(flexehd::fem::writeAtomically((dir / "a.txt").string(),
                                               [](const std::string& tmp) {
                                                   std::ofstream(tmp) << "half";
                                                   throw std::runtime_error("writer failed");
                                               }),
                 std::runtime_error);
    EXPECT_FALSE(fs::exists(dir / "a.txt.tmp"));
    EXPECT_FALSE(fs::exists(dir / "a.txt"));
    flexehd::fem::writeAtomically((dir / "b.txt").string(), write);
    EXPECT_TRUE(fs::exists(dir / "b.txt"));
    EXPECT_FALSE(fs::exists(dir / "b.txt.tmp"));
    fs::remove_all(dir);
}

// What a killed run leaves (NAME.EXT.tmp of an output format, also in subdirectories) is removed
// by the next run into the directory; other .tmp files are not ours and stay.
TEST(AtomicFile, StaleTemporariesOfOutputsAreRemoved) {
    const fs::path dir = fs::temp_directory_path() / ("flexehd_stale_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "vtk");
    fs::create_directories(dir / "modes");
    for (const char* f : {"summary.json.tmp", "history.csv.tmp", "vtk/film_0003.vts.tmp", "modes/mode_007.vtu.tmp",
                          "modes/modes.pvd.tmp", "modes/modes.fingerprint.tmp", "notes.tmp", "draft.txt.tmp",
                          "summary.json"})
        std::ofstream(dir / f) << "x";
    fs::create_directories(dir / "kept.vtu.tmp");  // a directory, not a file
    EXPECT_EQ(flexehd::fem::removeStaleTemporaries(dir.string()), 6);
    for (const char* f : {"summary.json.tmp", "history.csv.tmp", "vtk/film_0003.vts.tmp", "modes/mode_007.vtu.tmp",
                          "modes/modes.pvd.tmp", "modes/modes.fingerprint.tmp"})
        EXPECT_FALSE(fs::exists(dir / f)) << f;
    for (const char* f : {"notes.tmp", "draft.txt.tmp", "summary.json", "kept.vtu.tmp"})
        EXPECT_TRUE(fs::exists(dir / f)) << f;
    EXPECT_EQ(flexehd::fem::removeStaleTemporaries((dir / "absent").string()), 0);
    fs::remove_all(dir);
}
