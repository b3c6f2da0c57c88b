// The liner's energy over a recorded run (cosim/results/SurfaceVelocityRecorder, docs/acoustics.md
// §9, `energy`): the work the film and contacts do on the liner, W = ∫ fᵀq̇ dt (exact for the
// force linear between the accepted steps), equals the change of its stored energy ΔE plus the
// energy its modal damping takes, D = ∫ q̇ᵀ C q̇ dt. W − ΔE − D = 0 is an identity of the exact
// response over any span, periodic or not; here D comes from Gauss–Legendre quadrature of the
// exact velocities within each step (modal::DampedEnergyQuadrature), not from W − ΔE, and the
// balance must hold to the quadrature's own error estimate plus the work's round-off.
// The case: the small engine (tests/cosim/SmallEngineCase.hpp) on a flexible liner (meshes/liner.geo
// at 9 mm, cast iron, both seats held, 8 normal modes, ζ = 0.02), two cycles, the balance over the
// second (the recorder's cycle, from the first's end state); recorders with 2, 4, 8 and 16 points
// per step show the rule's convergence.
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "../TestScratch.hpp"
#include "SmallEngineCase.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "cosim/mapping/FlexibleBody.hpp"
#include "cosim/results/SurfaceVelocityRecorder.hpp"
#include "fem/MeshReader.hpp"
#include "modal/CraigBamptonReducer.hpp"
#include "modal/ReducedBodyFile.hpp"

using namespace flexehd;
using namespace flexehd::cosim;

namespace {

std::string reducedLinerFile(const std::string& path) {
    fem::MeshOptions coarse;
    coarse.order = 2;
    coarse.size = 0.009;
    const fem::Mesh m = fem::readMesh(std::string(FLEXEHD_SOURCE_DIR) + "/meshes/liner.geo", coarse);
    modal::CraigBamptonReducer reducer(m, fem::ElasticMaterial{1.1e11, 0.26, 7200.0});
    modal::ReductionSettings rs;
    rs.normalModes = 8;
    modal::ReducedBody body =
        reducer.reduce({modal::parseInterface("top_seat:rbe2"), modal::parseInterface("bottom_seat:rbe2")}, rs);
    for (Eigen::Index k = 0; k < body.numModes(); ++k) body.dampingRatios(k) = body.rigidBody[std::size_t(k)] ? 0.0 : 0.02;
    modal::writeReducedBody(body, path);
    return path;
}

}  // namespace

TEST(LinerEnergy, TheWorkOnTheLinerIsItsStoredChangePlusItsDampedEnergyByQuadrature) {
    const auto dir = test::scratchDir();
    EngineCase c = test::smallCase();
    c.grid = {12, 40};
    c.time.maxCycles = 2;  // the record's cycle: the second, from the first's end state
    c.linerBody.model = BodyModel::Flexible;
    c.linerBody.file = reducedLinerFile((dir / "liner.h5").string());
    c.linerBody.surface = "bore";
    c.linerBody.interface = "top_seat";
    c.linerBody.interfaces = {"top_seat", "bottom_seat"};
    c.acoustics.enabled = true;
    c.output.directory = dir.string();
    PistonSimulation sim(c);
    const FlexibleBody& liner = *sim.linerBody();
    const int offset = sim.pistonBody() ? sim.pistonBody()->modes() : 0;
    std::vector<std::unique_ptr<SurfaceVelocityRecorder>> recorders;
    for (int m : {2, 4, 8, 16}) {
        recorders.push_back(std::make_unique<SurfaceVelocityRecorder>(
            c, liner.body(), liner.heldInterfaces(), offset, (dir / ("acoustics" + std::to_string(m) + ".h5")).string()));
        recorders.back()->integrateDampedEnergy(m);
        sim.addObserver(*recorders.back());
    }
    sim.run();
    const SurfaceVelocityRecorder& r = *recorders.back();
    ASSERT_EQ(sim.statistics().cycles, 2);
    const double W = r.cycleWork(), dE = r.cycleStoredChange();
    ASSERT_GT(r.cycleSteps(), 10);
    ASSERT_GT(W, 0.0);
    std::printf("%d steps: W = %.12g J, dE = %.12g J, W - dE = %.12g J (work scale %.3g J)\n", r.cycleSteps(), W, dE,
                W - dE, r.cycleWorkScale());
    // The bound: each rule's estimate, and the round-off of W (differences of terms of the size
    // of the work scale, each carrying a few ulps of the states) and of ΔE and D.
    const double eps = std::numeric_limits<double>::epsilon();
    const double roundoff = 16.0 * eps * (r.cycleWorkScale() + std::abs(dE) + r.cycleDampedQuadrature());
    std::printf("stored change %.2e of the work; round-off bound %.3e J\n", dE / W, roundoff);
    for (std::size_t i = 0; i < recorders.size(); ++i) {
        const SurfaceVelocityRecorder& ri = *recorders[i];
        const double D = ri.cycleDampedQuadrature(), balance = W - dE - D;
        EXPECT_DOUBLE_EQ(ri.cycleWork(), W);  // the same response in every recorder
        EXPECT_GT(D, 0.0);
        std::printf("%2d/%2d points: D = %.12g J, W - dE - D = %.3e J (%.2e of D), estimate %.3e J\n", 2 << i, 4 << i,
                    D, balance, balance / D, ri.cycleDampedQuadratureError());
        if (i == 0) continue;  // 2 points: not yet in the rule's geometric regime
        EXPECT_LE(std::abs(balance), ri.cycleDampedQuadratureError() + roundoff)
            << (2 << i) << " points: estimate " << ri.cycleDampedQuadratureError() << " J, round-off " << roundoff << " J";
        EXPECT_LT(ri.cycleDampedQuadratureError(), 0.1 * recorders[i - 1]->cycleDampedQuadratureError());  // geometric
    }
}
