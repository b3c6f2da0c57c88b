// The energy balance of the skirt film over a periodic cycle (docs/results-format.md,
// "Friction"): the dissipated power that history.csv reports, integrated from the film's
// velocity and pressure fields (∫[φηΔV²/h + h³|∇p|²/(12η)] dA + boundary friction power),
// must equal the mechanical work the walls do on the film, formed from the forces and the
// velocities — a second, independent route. In the piston-fixed frame of the film grid the
// liner slides at −ż and does the work F_liner,z · ż; the piston's lateral shift and tilt
// squeeze the film and do −(F_x ė + M_y β̇). The asperity contact is elastic: its work
// vanishes over a periodic cycle.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cosim/coupling/PistonSimulation.hpp"
#include "SmallEngineCase.hpp"

using namespace flexehd;
using namespace flexehd::cosim;

TEST(FilmEnergy, DissipationEqualsTheWorkOfTheWallsOverAPeriodicCycle) {
    EngineCase c = test::smallCase();
    c.time.maxCycles = 3;
    c.output.vtkEveryDeg = 0.0;
    PistonSimulation sim(c);
    const std::vector<StepRecord> cycle = sim.run();
    ASSERT_TRUE(sim.statistics().periodic) << "periodicity error " << sim.statistics().periodicityError;
    ASSERT_GE(cycle.size(), 100u);

    // Trapezoidal time integrals over the cycle, as CycleMetrics integrates the dissipation.
    double dissipated = 0.0, liner = 0.0, squeeze = 0.0, pistonShear = 0.0;
    auto at = [&](const StepRecord& r, double& diss, double& lin, double& sq, double& ps) {
        const double zdot = sim.kinematics().at(r.crankDeg).velocity;
        diss = r.dissipatedPower;
        lin = (r.linerHydrodynamicFriction + r.linerBoundaryFriction) * zdot;
        sq = -((r.filmForce + r.contactForce) * r.lateralVelocity + r.filmMoment * r.tiltRate);
        ps = -r.frictionForce * zdot;
    };
    for (std::size_t k = 1; k < cycle.size(); ++k) {
        double d0, l0, s0, p0, d1, l1, s1, p1;
        at(cycle[k - 1], d0, l0, s0, p0);
        at(cycle[k], d1, l1, s1, p1);
        const double dt = cycle[k].time - cycle[k - 1].time;
        dissipated += 0.5 * (d0 + d1) * dt;
        liner += 0.5 * (l0 + l1) * dt;
        squeeze += 0.5 * (s0 + s1) * dt;
        pistonShear += 0.5 * (p0 + p1) * dt;
        EXPECT_GE(cycle[k].dissipatedPower, 0.0) << "at " << cycle[k].crankDeg << " deg";
        EXPECT_GE(cycle[k].boundaryFrictionPower, 0.0) << "at " << cycle[k].crankDeg << " deg";
    }
    std::printf("  per cycle: dissipated %.5f J; work of the liner %.5f J + squeeze %.5f J = %.5f J "
                "(the piston's axial shear work alone: %.5f J)\n",
                dissipated, liner, squeeze, liner + squeeze, pistonShear);
    ASSERT_GT(dissipated, 0.0);
    EXPECT_GT(squeeze, 0.0) << "the squeeze film damps the secondary motion";
    EXPECT_NEAR((liner + squeeze) / dissipated, 1.0, 0.01);
}
