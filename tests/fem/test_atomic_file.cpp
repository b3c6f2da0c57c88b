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
