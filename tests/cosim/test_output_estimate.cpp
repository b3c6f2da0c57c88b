// What a run will write, judged before it starts (docs/results-format.md, "How much a run
// writes"; cosim/run/OutputEstimate): the estimate against a real run's files, the refusal of a
// time.max_step_deg that forces ~1e9 steps per cycle, and the progress line that a run of tiny
// steps prints every ~10 s of wall time (cosim/coupling/RunProgress, ProgressPacer).
#include "CliRunner.hpp"
#include "../TestScratch.hpp"
#include "TestFiles.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cosim/casefile/CaseFile.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "cosim/coupling/RunProgress.hpp"
#include "cosim/run/OutputEstimate.hpp"

namespace fs = std::filesystem;
using namespace flexehd;
using ::testing::HasSubstr;

namespace {

// hd.yaml on the coarse grid (24 x 72) into DIR/out, with `time` lines replaced.
std::string coarseCase(const fs::path& dir, const std::string& maxStep, const std::string& minStep = "1.0e-3",
                       const std::string& maxCycles = "5") {
    return test::coarseHdCase(dir, dir / "out",
                              {{"max_step_deg: 0.5", "max_step_deg: " + maxStep},
                               {"min_step_deg: 1.0e-3", "min_step_deg: " + minStep},
                               {"max_cycles: 5", "max_cycles: " + maxCycles}});
}

std::uintmax_t bytesUnder(const fs::path& dir) {
    std::uintmax_t n = 0;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) n += e.file_size();
    return n;
}

}  // namespace

// (a) The estimate of one cycle against the files a real 1-cycle run writes: history.csv and
// the vtk/ folder each within a factor of 2.
TEST(OutputEstimate, MatchesTheFilesOfARealCycleWithinAFactorOfTwo) {
    const fs::path dir = test::scratchDir();
    const std::string casePath = coarseCase(dir, "0.5", "1.0e-3", "1");
    const test::CommandResult r = test::runFlexehd("run --quiet " + casePath);
    ASSERT_EQ(r.status, 0) << r.err;
    const double history = double(fs::file_size(dir / "out" / "history.csv"));
    const double vtk = double(bytesUnder(dir / "out" / "vtk"));

    const cosim::EngineCase c = cosim::readCaseFile(casePath);
    const cosim::PistonSimulation sim(c);
    const cosim::OutputLayout layout = cosim::outputLayout(c, sim);
    EXPECT_EQ(layout.filmPoints, 73 * 24);  // closed at the seam
    const cosim::OutputEstimate e = cosim::estimateOutput(layout);
    EXPECT_DOUBLE_EQ(e.stepsPerCycle, 1440.0);
    EXPECT_DOUBLE_EQ(e.snapshotsPerCycle, 72.0);
    std::printf("history.csv: estimated %.0f bytes, written %.0f; vtk/: estimated %.0f bytes, written %.0f\n",
                e.historyBytesPerCycle, history, e.vtkBytesPerCycle, vtk);
    EXPECT_GT(e.historyBytesPerCycle, history / 2);
    EXPECT_LT(e.historyBytesPerCycle, history * 2);
    EXPECT_GT(e.vtkBytesPerCycle, vtk / 2);
    EXPECT_LT(e.vtkBytesPerCycle, vtk * 2);
    EXPECT_NEAR(e.totalBytes, e.historyBytesPerCycle + e.vtkBytesPerCycle, 1.0);  // one cycle, rigid bodies
}

// (b) time.max_step_deg 1e-6 forces 7.2e8 steps per cycle, ~2e11 bytes of history.csv: the run is
// refused at once, naming the key and the estimate, and writes no history.
TEST(OutputEstimate, ATinyMaxStepIsRefusedBeforeTheRun) {
    const fs::path dir = test::scratchDir();
    const std::string casePath = coarseCase(dir, "1.0e-6", "1.0e-7");
    const auto t0 = std::chrono::steady_clock::now();
    const test::CommandResult r = test::runFlexehd("run " + casePath, 30);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_LT(seconds, 10.0);
    EXPECT_THAT(r.err, HasSubstr("time.max_step_deg"));
    EXPECT_THAT(r.err, HasSubstr("7.2e+08 steps per cycle"));
    EXPECT_THAT(r.err, HasSubstr("history.csv ~"));
    EXPECT_THAT(r.err, ::testing::ContainsRegex("history.csv ~[0-9.]+ GB per cycle"));
    EXPECT_FALSE(fs::exists(dir / "out" / "history.csv"));
}

// The verdicts without a run: a cycle beyond the free space is refused, a total beyond it or
// above ~10 GB warned about, each naming the key to change.
TEST(OutputEstimate, RefusesAndWarnsByTheFreeSpace) {
    cosim::OutputLayout l;
    l.maxStepDeg = 0.01;  // 72000 rows per cycle
    l.historyColumns = 23;
    l.vtkEveryDeg = 0.1;  // 7200 snapshots
    l.filmPoints = 145 * 48;
    l.filmFields = 5;
    l.maxCycles = 100;
    const cosim::OutputEstimate e = cosim::estimateOutput(l);
    const cosim::OutputVerdict tight = cosim::judgeOutput(l, e, e.bytesPerCycle / 2);
    EXPECT_THAT(tight.refusal, HasSubstr("exceeds the"));
    EXPECT_THAT(tight.refusal, HasSubstr("output.vtk_every_deg"));
    const cosim::OutputVerdict roomy = cosim::judgeOutput(l, e, e.bytesPerCycle * 3);
    EXPECT_TRUE(roomy.refusal.empty());
    ASSERT_FALSE(roomy.warnings.empty());
    EXPECT_THAT(roomy.warnings[0], HasSubstr("time.max_cycles"));
    l.vtkEveryDeg = 10.0;
    l.maxCycles = 5;
    const cosim::OutputEstimate small = cosim::estimateOutput(l);
    const cosim::OutputVerdict fine = cosim::judgeOutput(l, small, 1e12);
    EXPECT_TRUE(fine.refusal.empty());
    EXPECT_TRUE(fine.warnings.empty());
}

// The pacer: a line once 10 s of wall time passed since the last one, with the crank angle,
// the steps and the time to the cycle's end.
TEST(ProgressPacer, PrintsALineEveryIntervalOfWallTime) {
    cosim::ProgressPacer p(5, 0.0);
    p.linePrinted(0.0);
    EXPECT_FALSE(p.stepAccepted(1, 0.001, 0.001, 5.0));
    const auto line = p.stepAccepted(1, 0.002, 0.001, 10.5);
    ASSERT_TRUE(line);
    EXPECT_THAT(*line, HasSubstr("crank 0.002 deg"));
    EXPECT_THAT(*line, HasSubstr("2 steps this cycle"));
    EXPECT_THAT(*line, HasSubstr("to the cycle's end"));
    EXPECT_FALSE(p.stepAccepted(1, 0.003, 0.001, 15.0));
    EXPECT_TRUE(p.stepAccepted(1, 0.004, 0.001, 21.0));
}

// (c) A run of tiny steps (time.max_step_deg 1e-4: 7.2e6 steps per cycle, allowed with a warning;
// 30° of crank — the step loop's own line spacing — take ~50 s on the coarse grid) prints a
// progress line by wall time within 16 s.
TEST(OutputEstimate, ASlowRunPrintsProgressByWallTime) {
    const fs::path dir = test::scratchDir();
    const std::string casePath = coarseCase(dir, "1.0e-4", "1.0e-5");
    const fs::path errFile = dir / "stderr.txt";
    const std::string cmd = "timeout --preserve-status --kill-after=20s -s INT 16 " + std::string(FLEXEHD_BINARY) +
                            " run " + casePath + " >/dev/null 2>" + errFile.string();
    const int status = std::system(cmd.c_str());
    std::ifstream e(errFile);
    const std::string err((std::istreambuf_iterator<char>(e)), {});
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 128 + SIGINT) << err;
    EXPECT_THAT(err, HasSubstr("steps this cycle"));
    EXPECT_THAT(err, HasSubstr("to the cycle's end at this pace"));
    EXPECT_THAT(err, HasSubstr("time.max_step_deg 0.0001 forces at least 7.2e+06 steps per cycle"));  // the warning
}
