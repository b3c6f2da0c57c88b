// bodies.response: dynamic in the co-simulation: the flexible piston's modal dynamics
// (modal::HeldModalDynamics, BDF2 with the motion's step coefficients) inside the coupling.
//  * The real piston's elastic modes (free-free from ~6 kHz) lie far above the load's frequency
//    content at 1000 rpm (the slap takes ~10° = 1.7 ms): the dynamic run must agree with the
//    quasi-static one — slow loading gives the quasi-static response.
//  * The same body with its modal masses made 1e8 times larger (frequencies 1e4 times lower,
//    below 1 Hz) cannot follow the load over the 70 ms of the run: its elastic film change must
//    stay a small fraction, (ω t)²/2 ≈ 1e-2, of the quasi-static one. This fails if the response
//    is not the dynamic one.
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "modal/ReducedBodyFile.hpp"
#include "CliRunner.hpp"
#include "SmallEngineCase.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace flexehd;
using namespace flexehd::cosim;
namespace fs = std::filesystem;

namespace {

EngineCase flexibleCase(const std::string& pistonFile, ElasticResponse response) {
    EngineCase c = test::smallFlexibleCase(pistonFile);
    c.output.vtkEveryDeg = 10.0;
    c.coupling.response = response;
    return c;
}

struct RunResult {
    std::vector<StepRecord> steps;
    std::vector<Snapshot> snaps;
    double largestElastic = 0.0;  // max over the snapshots and film nodes of |elastic Δh|, m
};

RunResult run(const EngineCase& c, double span) {
    PistonSimulation sim(c);
    RunResult r;
    SimulationCallbacks cb;
    cb.onStep = [&](const StepRecord& s) { r.steps.push_back(s); };
    cb.onSnapshot = [&](const Snapshot& s) { r.snaps.push_back(s); };
    sim.run(cb, span);
    Eigen::VectorXd dh;
    for (const Snapshot& s : r.snaps) {
        sim.contact<SkirtContact>().piston()->filmChange(s.pistonModal, 0.0, dh);
        r.largestElastic = std::max(r.largestElastic, dh.cwiseAbs().maxCoeff());
    }
    return r;
}

/// max |a − b| of the lateral shift at the crank angles both runs visited, and the range of a.
std::pair<double, double> lateralDifference(const RunResult& a, const RunResult& b) {
    double diff = 0.0, lo = 0.0, hi = 0.0;
    for (const StepRecord& x : a.steps) {
        lo = std::min(lo, x.lateral), hi = std::max(hi, x.lateral);
        for (const StepRecord& y : b.steps)
            if (std::abs(x.crankDeg - y.crankDeg) < 1e-9) diff = std::max(diff, std::abs(x.lateral - y.lateral));
    }
    return {diff, hi - lo};
}

}  // namespace

TEST(DynamicResponse, StiffPistonFollowsQuasiStaticallyHeavyPistonLags) {
    const fs::path dir = fs::temp_directory_path() / ("flexehd_dynamic_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string file = (dir / "piston.h5").string();
    const auto red = test::reduceSmallPiston(file);
    ASSERT_EQ(red.status, 0) << red.err;
    modal::ReducedBody heavy = modal::readReducedBody(file);
    heavy.massMatrix *= 1e8;
    const std::string heavyFile = (dir / "heavy.h5").string();
    modal::writeReducedBody(heavy, heavyFile);

    const double span = 420.0;  // through the firing slap
    const RunResult qs = run(flexibleCase(file, ElasticResponse::QuasiStatic), span);
    const RunResult dyn = run(flexibleCase(file, ElasticResponse::Dynamic), span);
    const RunResult lag = run(flexibleCase(heavyFile, ElasticResponse::Dynamic), span);

    const auto [diff, range] = lateralDifference(dyn, qs);
    std::printf("lateral range %.2f um; dynamic - quasi-static: %.3g um; largest elastic dh: quasi-static %.3f um, "
                "dynamic %.3f um, heavy modes %.4f um\n",
                range * 1e6, diff * 1e6, qs.largestElastic * 1e6, dyn.largestElastic * 1e6, lag.largestElastic * 1e6);
    ASSERT_GT(range, 10e-6);
    EXPECT_LT(diff, 0.01 * range);
    EXPECT_GT(diff, 0.0);  // the dynamic response is not the quasi-static one to the last bit
    EXPECT_NEAR(dyn.largestElastic, qs.largestElastic, 0.02 * qs.largestElastic);
    ASSERT_GT(qs.largestElastic, 0.1e-6);
    EXPECT_LT(lag.largestElastic, 0.05 * qs.largestElastic);
    fs::remove_all(dir);
}
