// RunProgress: the progress lines of a run. The estimate of the cycles left assumes geometric
// convergence of the periodicity error, e_k = e_{k−1} ρ: with e = 1e-4, 1e-5 m and a tolerance
// of 1e-7 m, ρ = 0.1 and two more cycles reach 1e-7.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cosim/coupling/RunProgress.hpp"

using flexehd::cosim::RunProgress;
using ::testing::HasSubstr;
using ::testing::Not;

TEST(RunProgress, EstimatesTheCyclesLeftFromThePeriodicityTrend) {
    RunProgress p(10, 1e-7);
    p.startCycle(1, 0.0);
    EXPECT_THAT(p.cycleDoneLine(2.0, std::nullopt), HasSubstr("periodicity is judged from cycle 2 on"));
    EXPECT_FALSE(p.cyclesLeftEstimate());
    p.startCycle(2, 2.0);
    EXPECT_THAT(p.stepLine(180.0, 0.5, 3.0, 1e-6, 1e-3, 4, 0.5),
                AllOf(HasSubstr("cycle 2 (at most 10)"), HasSubstr("this cycle 1.0 of ~2.0 s (1.0 s left)")));
    const std::string second = p.cycleDoneLine(4.0, 1e-4);
    EXPECT_THAT(second, Not(HasSubstr("more cycle")));  // one error: no trend yet
    p.startCycle(3, 4.0);
    const std::string third = p.cycleDoneLine(6.0, 1e-5);
    EXPECT_EQ(p.cyclesLeftEstimate(), 2);
    EXPECT_THAT(third, AllOf(HasSubstr("about 2 more cycles (~4 s)"), HasSubstr("done in 2.0 s")));
    p.startCycle(4, 6.0);
    EXPECT_THAT(p.cycleDoneLine(8.0, 5e-8), HasSubstr("periodic"));
    EXPECT_EQ(p.cyclesLeftEstimate(), 0);
}

TEST(RunProgress, AGrowingErrorRunsToMaxCycles) {
    RunProgress p(5, 1e-7);
    p.startCycle(1, 0.0);
    p.cycleDoneLine(1.0, std::nullopt);
    p.startCycle(2, 1.0);
    p.cycleDoneLine(2.0, 1e-5);
    p.startCycle(3, 2.0);
    EXPECT_THAT(p.cycleDoneLine(3.0, 2e-5), HasSubstr("about 2 more cycles (~2 s), up to time.max_cycles"));
    p.startCycle(5, 4.0);
    EXPECT_THAT(p.cycleDoneLine(5.0, 3e-5), HasSubstr("NOT periodic after time.max_cycles"));
}
