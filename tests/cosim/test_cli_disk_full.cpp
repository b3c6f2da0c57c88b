// `flexehd run` on a full disk (docs/results-format.md, "When a write fails"): the run stops at
// the first write that fails, says "the disk is full (… ENOSPC)" in words, history.csv keeps
// whole rows only (the failed row cut back, never written twice), and no VTK error text
// reaches the terminal. The disk is a small tmpfs mounted in a user namespace of its own
// (`unshare -rm`) that another process fills once the run is under way; where the machine does
// not allow that, the test says so and is skipped.
#include "CliRunner.hpp"
#include "../TestScratch.hpp"
#include "TestFiles.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using namespace flexehd;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {

// hd.yaml on the coarse grid, 1000 cycles at most and never periodic, writing to `out`, VTK
// snapshots every `vtkDeg` (0: none): on a small disk it fills the disk long before it ends.
std::string endlessCase(const fs::path& dir, const fs::path& out, const std::string& vtkDeg) {
    return test::coarseHdCase(dir, out,
                              {{"max_cycles: 5", "max_cycles: 1000"},
                               {"periodicity_tolerance: 1.0e-6", "periodicity_tolerance: 1.0e-15"},
                               {"vtk_every_deg: 10.0", "vtk_every_deg: " + vtkDeg}});
}

bool userNamespacesWork() { return std::system("unshare -rm true >/dev/null 2>&1") == 0; }

struct DiskFullRun {
    int status;
    std::string err;
    double seconds;
    fs::path kept;  // the output folder as the run left it, copied off the disk
};

// Runs the case with its output folder on a tmpfs of `kib` KiB; once the run has begun writing
// (history.csv exists: the run has passed its output estimate), another process fills the disk
// up to `leaveBytes` free, as a disk that fills while a run is under way. Copies what the run left.
DiskFullRun runOnFillingDisk(const fs::path& dir, const std::string& vtkDeg, int kib, long leaveBytes) {
    const fs::path disk = dir / "disk", kept = dir / "kept";
    fs::create_directories(disk);
    const std::string casePath = endlessCase(dir, disk / "out", vtkDeg);
    const std::string d = disk.string();
    const std::string inner =
        "mount -t tmpfs -o size=" + std::to_string(kib) + "k tmpfs " + d + " || exit 99; " +
        test::timeLimited(std::string(FLEXEHD_BINARY) + " run --quiet " + casePath, 120) + " 2>" +
        (dir / "stderr.txt").string() + " & pid=$!; " +
        "while [ ! -s " + d + "/out/history.csv ] && kill -0 $pid 2>/dev/null; do sleep 0.05; done; " +
        "avail=$(df -B1 --output=avail " + d + " | tail -1); n=$(( (avail - " + std::to_string(leaveBytes) +
        ") / 1024 )); [ $n -gt 0 ] && dd if=/dev/zero of=" + d + "/filler bs=1024 count=$n 2>/dev/null; " +
        "wait $pid; rc=$?; cp -r " + d + "/out " + kept.string() + "; exit $rc";
    const auto start = std::chrono::steady_clock::now();
    const int status = std::system(("unshare -rm sh -c '" + inner + "'").c_str());
    DiskFullRun r;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream e(dir / "stderr.txt");
    r.err.assign(std::istreambuf_iterator<char>(e), {});
    r.kept = kept;
    return r;
}

// Every data line of history.csv has the header's number of fields and ends with a newline.
void expectWholeRows(const fs::path& history, const std::string& what) {
    std::ifstream h(history);
    ASSERT_TRUE(h.good()) << what << ": no history.csv";
    std::stringstream all;
    all << h.rdbuf();
    const std::string text = all.str();
    ASSERT_FALSE(text.empty()) << what;
    EXPECT_EQ(text.back(), '\n') << what << ": history.csv ends in a partial line";
    std::istringstream lines(text);
    std::string line;
    std::getline(lines, line);
    const auto fields = std::count(line.begin(), line.end(), ',') + 1;
    int rows = 0;
    while (std::getline(lines, line)) {
        if (line.empty() || line[0] == '#') continue;
        EXPECT_EQ(std::count(line.begin(), line.end(), ',') + 1, fields) << what << ", row " << rows + 1 << ": " << line;
        ++rows;
    }
    EXPECT_GT(rows, 0) << what;
}

}  // namespace

TEST(CliDiskFull, HistoryFillingTheDiskStopsTheRunWithWholeRowsAndTheReasonInWords) {
    if (!userNamespacesWork()) GTEST_SKIP() << "this machine does not allow `unshare -rm` (user namespaces)";
    const fs::path dir = test::scratchDir() / "history";
    fs::create_directories(dir);
    const DiskFullRun r = runOnFillingDisk(dir, "0", 4096, 0);
    EXPECT_FALSE(test::failedByTimeLimit(r.status, "the run on a full disk", 120)) << "it computed on";
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_LT(r.seconds, 60.0) << "the run did not stop at the first failed write";
    EXPECT_THAT(r.err, HasSubstr("history.csv"));
    EXPECT_THAT(r.err, HasSubstr("the disk is full (no space left on device, ENOSPC)"));
    expectWholeRows(r.kept / "history.csv", "history on a full disk");
    std::cout << "what the user reads: " << r.err;
}

TEST(CliDiskFull, SnapshotsFillingTheDiskStopTheRunWithoutVtkText) {
    if (!userNamespacesWork()) GTEST_SKIP() << "this machine does not allow `unshare -rm` (user namespaces)";
    const fs::path dir = test::scratchDir() / "snapshots";
    fs::create_directories(dir);
    const DiskFullRun r = runOnFillingDisk(dir, "2.0", 32768, 20 * 1024);  // room for rows, not a snapshot
    EXPECT_FALSE(test::failedByTimeLimit(r.status, "the run on a full disk", 120)) << "it computed on";
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_THAT(r.err, HasSubstr("ENOSPC"));
    EXPECT_THAT(r.err, Not(HasSubstr("vtkExecutive")));
    EXPECT_THAT(r.err, Not(HasSubstr("vtkXML")));
    EXPECT_THAT(r.err, Not(HasSubstr("ERROR: In")));
    expectWholeRows(r.kept / "history.csv", "history beside snapshots on a full disk");
}
