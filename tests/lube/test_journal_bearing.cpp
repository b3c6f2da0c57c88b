// lube::JournalBearing with the supply groove away from the maximum film and with a starved
// supply (docs/lube.md §8). With the groove at 270° from the maximum film (in the diverging
// film) the mass-conserving film ruptures past the minimum film and re-forms inside the bearing,
// in the converging film ahead of the maximum film — the case where the film fraction is
// transported through the cavitated zone and the reformation boundary is found by the solver.
#include "lube/JournalBearing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace flexehd::lube;

namespace {

JournalBearingSpec grooveAt270(int nTheta, int nZ, SolverKind solver) {
    JournalBearingSpec s;
    s.eccentricity = 0.6;
    s.cavitation = BearingCavitation::MassConserving;
    s.solver = solver;
    s.grooveAngleDeg = 270.0;
    s.circumferentialNodes = nTheta;
    s.axialNodes = nZ;
    s.tolerance = 1e-10;
    return s;
}

}  // namespace

// Two methods of the project on the same discrete problem: the active-set (semismooth Newton,
// sparse LU) and the projected Gauss–Seidel sweeps of Ausas et al. Both stop at the residual
// 1e-10; the loads and the friction then agree far below 1e-6.
TEST(JournalBearingGroove, At270DegreesActiveSetMatchesGaussSeidel) {
    const JournalBearingResult a = JournalBearing(grooveAt270(64, 17, SolverKind::ActiveSet)).solve();
    const JournalBearingResult g = JournalBearing(grooveAt270(64, 17, SolverKind::Psor)).solve();
    std::printf("groove 270 deg, 64x17: active set W %.9g N (%d LU), Gauss-Seidel W %.9g N (%d sweeps); "
                "cavitated %.3f\n",
                a.load, a.iterations, g.load, g.iterations, a.cavitatedFraction);
    EXPECT_DOUBLE_EQ(a.grooveAngleDeg, 270.0);
    EXPECT_GT(a.cavitatedFraction, 0.05);  // a ruptured film, re-forming inside the bearing
    EXPECT_NEAR(a.load, g.load, 1e-6 * a.load);
    EXPECT_NEAR(a.attitudeDeg, g.attitudeDeg, 1e-5);
    EXPECT_NEAR(a.frictionTorque, g.frictionTorque, 1e-6 * std::abs(a.frictionTorque));
    EXPECT_NEAR(a.inletFlow, g.inletFlow, 1e-6 * std::abs(a.inletFlow));
}

// The grid limit on 128×33, 256×65, 512×129. The film fraction is transported by first-order
// upwinding, so the friction torque and the attitude angle (which the cavitated zone's extent
// sets) must converge at first order: the measured order within [0.8, 1.3], and the first-order
// Richardson limits of the coarse pair and of the fine pair must agree to a fifth of the fine
// pair's difference (in the asymptotic range they differ by the higher-order remainder only). The load is pre-asymptotic on
// these grids (its differences change sign below 128×33); it must settle to 1e-3 of itself.
// The multigrid method of the mass-conserving film (the bearing's default) against the active set
// at 270°, where the film re-forms inside the bearing: the same discrete problem, so the loads and
// the friction agree to the tolerance's effect.
TEST(JournalBearingGroove, At270DegreesMultigridMatchesActiveSet) {
    const JournalBearingResult a = JournalBearing(grooveAt270(64, 17, SolverKind::ActiveSet)).solve();
    const JournalBearingResult m = JournalBearing(grooveAt270(64, 17, SolverKind::Multigrid)).solve();
    std::printf("groove 270: load %.9g / %.9g N, torque %.9g / %.9g N m\n", a.load, m.load, a.frictionTorque,
                m.frictionTorque);
    EXPECT_NEAR(m.load / a.load, 1.0, 1e-6);
    EXPECT_NEAR(m.frictionTorque / a.frictionTorque, 1.0, 1e-6);
}

TEST(JournalBearingGroove, At270DegreesConvergesToTheGridLimit) {
    double W[3], M[3], A[3];
    for (int r = 0; r < 3; ++r) {
        const int nt = 128 << r, nz = 32 * (1 << r) + 1;
        const JournalBearingResult b = JournalBearing(grooveAt270(nt, nz, SolverKind::ActiveSet)).solve();
        W[r] = b.load;
        M[r] = b.frictionTorque;
        A[r] = b.attitudeDeg;
    }
    auto order = [](const double* v) { return std::log2((v[0] - v[1]) / (v[1] - v[2])); };
    const double pm = order(M), pa = order(A);
    const double limitCoarse = 2.0 * M[1] - M[0], limitFine = 2.0 * M[2] - M[1];
    std::printf("groove 270 deg: torque %.6g %.6g %.6g N m (order %.2f, first-order limits %.6g, %.6g); attitude %.4f %.4f %.4f deg "
                "(order %.2f); W %.6g %.6g %.6g N\n",
                M[0], M[1], M[2], pm, limitCoarse, limitFine, A[0], A[1], A[2], pa, W[0], W[1], W[2]);
    EXPECT_GT(pm, 0.8);
    EXPECT_LT(pm, 1.3);
    EXPECT_GT(pa, 0.8);
    EXPECT_LT(pa, 1.3);
    EXPECT_LT(std::abs(limitCoarse - limitFine), 0.2 * std::abs(M[2] - M[1]));
    EXPECT_LT(std::abs(W[2] - W[1]), 1e-3 * W[2]);
}

// A starved supply: the groove's oil fills part of the gap. Less oil carries less load and
// leaves more of the film cavitated.
TEST(JournalBearingGroove, StarvedSupplyCarriesLessLoad) {
    JournalBearingSpec s;
    s.eccentricity = 0.6;
    s.cavitation = BearingCavitation::MassConserving;
    s.solver = SolverKind::ActiveSet;
    s.circumferentialNodes = 128;
    s.axialNodes = 33;
    const JournalBearingResult flooded = JournalBearing(s).solve();
    double previous = flooded.load, previousCav = flooded.cavitatedFraction;
    for (const double f : {0.8, 0.5, 0.3}) {
        s.supplyFraction = f;
        const JournalBearingResult r = JournalBearing(s).solve();
        std::printf("supply fraction %.1f: W %.6g N, cavitated %.3f, inlet flow %.4g m^3/s\n", f, r.load,
                    r.cavitatedFraction, r.inletFlow);
        EXPECT_LT(r.load, previous) << f;
        EXPECT_GT(r.cavitatedFraction, previousCav) << f;
        previous = r.load;
        previousCav = r.cavitatedFraction;
    }
}

// The mass balance of the steady mass-conserving film: the oil leaving the groove returns to it
// round the bearing or leaves through the ends. The flows are the scheme's face fluxes (the
// Couette flow carries the upstream node's film fraction), so without side leakage (infinitely
// long) they balance to round-off; with open ends the side flow is extrapolated to the edge and
// the end rows' half cells carry flow the scheme does not balance, so the imbalance is O(Δz):
// it must halve with the grid.
TEST(JournalBearingGroove, MassConservingFlowsBalance) {
    for (const double groove : {0.0, 270.0}) {
        JournalBearingSpec s = grooveAt270(128, 2, SolverKind::ActiveSet);
        s.grooveAngleDeg = groove;
        s.infinitelyLong = true;
        const JournalBearingResult r = JournalBearing(s).solve();
        EXPECT_NEAR(r.inletFlow, r.returnFlow, 1e-10 * r.inletFlow) << groove;
        s.infinitelyLong = false;
        double imbalance[2];
        for (int g = 0; g < 2; ++g) {
            s.circumferentialNodes = 128 << g;
            s.axialNodes = 32 * (1 << g) + 1;
            const JournalBearingResult f = JournalBearing(s).solve();
            imbalance[g] = std::abs(f.inletFlow - f.returnFlow - f.sideFlow) / f.inletFlow;
        }
        std::printf("groove %g deg: long bearing in %.6g out %.6g m^3/s; finite imbalance %.3g, %.3g\n", groove,
                    r.inletFlow, r.returnFlow, imbalance[0], imbalance[1]);
        EXPECT_GT(imbalance[0] / imbalance[1], 1.7) << groove;
        EXPECT_LT(imbalance[0] / imbalance[1], 2.3) << groove;
    }
}
