// Piston secondary motion: crank-slider kinematics, the equations of motion (docs/dynamics.md),
// and the rigid-body (HD) co-simulation: no-motion limit, force and moment balance at every step
// (recomputed from history.csv quantities), time-step convergence, the kinetic energy of the
// secondary motion against a point-mass model, and the crank angle of the outputs.
#include "cosim/engine/CrankKinematics.hpp"
#include "cosim/results/CycleMetrics.hpp"
#include "cosim/engine/PistonDynamics.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "SmallEngineCase.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace flexehd::cosim;
using flexehd::test::smallCase;

TEST(CrankKinematics, MatchesClosedFormAndFiniteDifferences) {
    const double r = 0.043, l = 0.1435, c = 0.0;
    const CrankKinematics k(2 * r, l, c, 1000.0);
    for (double d : {0.0, 37.0, 90.0, 180.0, 271.0, 400.0}) {
        const double phi = d * std::numbers::pi / 180.0;
        const double z = r * std::cos(phi) + std::sqrt(l * l - r * r * std::sin(phi) * std::sin(phi));
        EXPECT_NEAR(k.at(d).position, z, 1e-14);
    }
    // Offset crank: velocity and acceleration vs central differences in time.
    const CrankKinematics ko(2 * r, l, 0.001, 1000.0);
    const double h = 1e-3;  // degrees
    const double dt = h * ko.secondsPerDegree();
    for (double d : {10.0, 100.0, 200.0, 359.0}) {
        const double zp = ko.at(d + h).position, z0 = ko.at(d).position, zm = ko.at(d - h).position;
        EXPECT_NEAR(ko.at(d).velocity, (zp - zm) / (2 * dt), 1e-6 * std::abs(ko.omega() * r));
        EXPECT_NEAR(ko.at(d).acceleration, (zp - 2 * z0 + zm) / (dt * dt), 1e-4 * ko.omega() * ko.omega() * r);
    }
    EXPECT_NEAR(ko.tdcPosition(), std::sqrt((l + r) * (l + r) - 1e-6), 1e-15);
    EXPECT_NEAR(ko.at(90.0).sinRod, (r + 0.001) / l, 1e-15);
    EXPECT_THROW(CrankKinematics(0.2, 0.09, 0.0, 1000.0), std::invalid_argument);
}

// Free-body check of the equations (docs/dynamics.md §2) against hand-evaluated terms.
TEST(PistonDynamics, EquationsMatchTheFreeBodyBalance) {
    EngineCase c = smallCase();
    c.piston.cgX = 0.002;
    c.engine.pinOffset = 0.0008;
    const PistonDynamics d(c.piston, c.engine, 9.81);
    CrankState k;
    k.acceleration = -3000.0;
    k.tanRod = 0.2;
    k.sinRod = 0.2 / std::sqrt(1.04);
    const FilmAction f{150.0, -20.0, 3.0};
    const double Fg = 10000.0, mp = 0.32, mpin = 0.10, xg = 0.002, zg = 0.006, Ig = 2.6e-4, A = -3000.0 + 9.81;
    const Eigen::Matrix2d M = d.mass(k);
    EXPECT_DOUBLE_EQ(M(0, 0), mp + mpin);
    EXPECT_DOUBLE_EQ(M(0, 1), mp * (zg + xg * 0.2));
    EXPECT_DOUBLE_EQ(M(1, 0), mp * zg);
    EXPECT_DOUBLE_EQ(M(1, 1), Ig + mp * (xg * xg + zg * zg));
    const Eigen::Vector2d rhs = d.force(k, Fg, f);
    EXPECT_DOUBLE_EQ(rhs[0], 150.0 + 0.2 * ((mp + mpin) * A + Fg + 20.0));
    EXPECT_DOUBLE_EQ(rhs[1], 3.0 - 0.0008 * Fg + mp * xg * A);
    // The rod force closes the axial balance of piston + pin for any tilt acceleration.
    const double tiltAcc = 123.0;
    const double side = d.sideForce(k, Fg, f, tiltAcc);
    const double rodAxial = side / k.tanRod;  // F_R cos ψ
    EXPECT_NEAR(mp * (A - xg * tiltAcc) + mpin * A, -Fg + f.fz + rodAxial, 1e-9);
    EXPECT_NEAR(d.gasForce(1.0e5 + 1.0e6), 1.0e6 * std::numbers::pi * 0.086 * 0.086 / 4, 1e-6);
}

// The slap energy (kineticEnergy, CycleMetrics, summary.json) against a rigid body built from
// point masses: four masses m_p/4 at G ± (a, 0) and G ± (0, b) in the x–z plane have their CG at G
// and I_g = m_p (a² + b²)/2. Each point's velocity relative to the primary motion is
// (ė, 0, 0) + ω × r with ω = (0, β̇, 0) and r its position from the pin axis; the pin moves with ė.
TEST(PistonDynamics, KineticEnergyOfAPointMassModel) {
    const double mp = 0.32, mpin = 0.10, a = 0.020, b = 0.030;
    const double Ig = mp * (a * a + b * b) / 2;
    for (const auto& [xg, zg] : {std::pair{0.0, 0.0}, std::pair{0.0, 0.012}, std::pair{0.003, -0.008},
                                 std::pair{-0.002, 0.015}}) {
        EngineCase c = smallCase();
        c.piston.mass = mp;
        c.piston.pinMass = mpin;
        c.piston.inertia = Ig;
        c.piston.cgX = xg;
        c.piston.cgZ = zg;
        const PistonDynamics d(c.piston, c.engine);
        for (const auto& [v, w] : {std::pair{0.05, 0.0}, std::pair{0.0, 3.0}, std::pair{0.05, 3.0},
                                   std::pair{-0.04, 2.5}}) {
            const Eigen::Vector3d omega(0.0, w, 0.0);
            double T = 0.5 * mpin * v * v;
            for (const Eigen::Vector3d& r : {Eigen::Vector3d(xg + a, 0, zg), Eigen::Vector3d(xg - a, 0, zg),
                                             Eigen::Vector3d(xg, 0, zg + b), Eigen::Vector3d(xg, 0, zg - b)}) {
                const Eigen::Vector3d u = Eigen::Vector3d(v, 0, 0) + omega.cross(r);
                T += 0.5 * (mp / 4) * u.squaredNorm();
            }
            EXPECT_NEAR(d.kineticEnergy(v, w), T, 1e-12 * T) << "x_g " << xg << ", z_g " << zg << ", v " << v << ", w " << w;
        }
    }
}

// With no gas force, no offsets and an (almost) straight rod nothing pushes the piston sideways:
// the lateral shift and the tilt stay at the level of the residual rod angle (tan ψ < 5e-8).
TEST(PistonSimulation, NoDrivingLoadsNoSecondaryMotion) {
    EngineCase c = smallCase();
    c.engine.rodLength = 1.0e6;
    c.piston.cgX = 0.0;
    for (auto& s : c.cylinderPressure) s.pressure = c.engine.crankcasePressure;
    c.grid = {16, 48};
    PistonSimulation sim(c);
    const auto rec = sim.run({}, 720.0);
    ASSERT_GT(rec.size(), 100u);
    for (const auto& r : rec) {
        EXPECT_LT(std::abs(r.lateral), 1e-9) << r.crankDeg;
        EXPECT_LT(std::abs(r.tilt), 1e-8) << r.crankDeg;
        EXPECT_GT(r.minFilm, 0.99 * c.piston.clearance);  // the profile only adds to the clearance
    }
}

// At every converged step the equations of motion hold with the recorded film loads and side
// force: the accelerations are recomputed from the recorded velocities and times (BDF2), the
// driving terms from the case by hand.
TEST(PistonSimulation, ForceAndMomentBalanceAtEveryStep) {
    EngineCase c = smallCase();
    c.piston.cgX = 0.002;
    c.engine.pinOffset = 0.0008;
    c.grid = {16, 48};
    PistonSimulation sim(c);
    const auto rec = sim.run({}, 480.0);
    const CrankKinematics& kin = sim.kinematics();
    const CylinderPressure trace(c.cylinderPressure);
    const double mp = c.piston.mass, mpin = c.piston.pinMass, xg = c.piston.cgX, zg = c.piston.cgZ, Ig = c.piston.inertia;
    const double area = std::numbers::pi * c.engine.bore * c.engine.bore / 4;
    double worstF = 0, worstM = 0, maxSide = 0;
    for (std::size_t i = 2; i < rec.size(); ++i) {
        const auto &r = rec[i], &r1 = rec[i - 1], &r2 = rec[i - 2];
        const double dt = r.time - r1.time, w = dt / (r1.time - r2.time);
        const double a0 = (1 + 2 * w) / (1 + w), a1 = -(1 + w), a2 = w * w / (1 + w);
        const double ea = (a0 * r.lateralVelocity + a1 * r1.lateralVelocity + a2 * r2.lateralVelocity) / dt;
        const double ba = (a0 * r.tiltRate + a1 * r1.tiltRate + a2 * r2.tiltRate) / dt;
        const CrankState k = kin.at(r.crankDeg);
        const double A = k.acceleration + 9.81;
        const double Fg = (trace(r.crankDeg) - c.engine.crankcasePressure) * area;
        const double lateral = (mp + mpin) * ea + mp * zg * ba - (r.filmForce + r.contactForce + r.sideForce);
        const double moment = (Ig + mp * (xg * xg + zg * zg)) * ba + mp * zg * ea -
                              (r.filmMoment - c.engine.pinOffset * Fg + mp * xg * A);
        worstF = std::max(worstF, std::abs(lateral));
        worstM = std::max(worstM, std::abs(moment));
        maxSide = std::max(maxSide, std::abs(r.sideForce));
    }
    std::printf("worst lateral imbalance %.3g N, moment %.3g N m, max side force %.0f N\n", worstF, worstM, maxSide);
    EXPECT_GT(maxSide, 500.0);  // firing: a real load case
    EXPECT_LT(worstF, 1e-3 * maxSide);
    EXPECT_LT(worstM, 1e-3 * maxSide * 0.02);
}

// The rigid motion's Jacobian kept from step to step (coupling.keep_jacobian, the default)
// against the same run with a Jacobian formed by differences at every step: both Newton
// iterations meet the same convergence test, so they give the same motion to far below the step's
// error tolerance over a fired cycle with its slaps, and the kept one needs fewer film solves
// (each new Jacobian costs two).
TEST(PistonSimulation, AKeptJacobianGivesTheMotionOfOneFormedEveryStep) {
    auto runWith = [](bool keep, int& solves) {
        EngineCase c = smallCase();
        c.grid = {16, 48};
        c.coupling.keepJacobian = keep;
        PistonSimulation sim(c);
        const auto rec = sim.run({}, 720.0);
        solves = 0;
        for (const auto& r : rec) solves += r.couplingIterations;
        return rec;
    };
    int keptSolves = 0, freshSolves = 0;
    const auto kept = runWith(true, keptSolves), fresh = runWith(false, freshSolves);
    ASSERT_GT(fresh.size(), 500u);
    const TimeSpec tol = smallCase().time;
    double dLateral = 0, dTilt = 0, range = 0;
    for (const auto& r : kept) {
        // The fresh run's motion at this crank angle, linear between its steps.
        auto hi = std::lower_bound(fresh.begin(), fresh.end(), r.time, [](const auto& a, double t) { return a.time < t; });
        if (hi == fresh.begin() || hi == fresh.end()) continue;
        const auto lo = hi - 1;
        const double w = (r.time - lo->time) / (hi->time - lo->time);
        dLateral = std::max(dLateral, std::abs(r.lateral - (lo->lateral + w * (hi->lateral - lo->lateral))));
        dTilt = std::max(dTilt, std::abs(r.tilt - (lo->tilt + w * (hi->tilt - lo->tilt))));
        range = std::max(range, std::abs(r.lateral));
    }
    std::printf("kept Jacobian: %d film solves, formed every step: %d; largest difference lateral %.3g m, "
                "tilt %.3g rad (largest lateral shift %.3g m; error tolerances %.3g m, %.3g rad)\n",
                keptSolves, freshSolves, dLateral, dTilt, range, tol.lateralTolerance, tol.tiltTolerance);
    EXPECT_GT(range, 20e-6);  // the piston crosses its clearance: the slaps are in the cycle
    EXPECT_LT(dLateral, 0.1 * tol.lateralTolerance);
    EXPECT_LT(dTilt, 0.1 * tol.tiltTolerance);
    EXPECT_LT(keptSolves, 0.75 * freshSolves);
}

// Time-step convergence over the firing slap (300°–420°) at fixed steps (error control off):
// BDF2 is second order, so halving the step divides the error by about four.
TEST(PistonSimulation, TimeStepConvergence) {
    auto runAt = [](double stepDeg) {
        EngineCase c = smallCase();
        c.grid = {16, 48};
        c.time.startDeg = 300.0;
        c.time.maxStepDeg = stepDeg;
        c.time.lateralTolerance = 1.0;  // no error control: every step = maxStep
        c.time.tiltTolerance = 1.0;
        c.output.vtkEveryDeg = 5.0;     // snapshot angles are hit exactly
        PistonSimulation sim(c);
        std::vector<double> e;
        sim.run({.onStep = {}, .onSnapshot = [&](const Snapshot& s) { e.push_back(s.lateral); }, .onCycleEnd = {}, .progress = {}}, 120.0);
        return e;
    };
    const auto ref = runAt(0.03125), e1 = runAt(0.5), e2 = runAt(0.25), e3 = runAt(0.125);
    ASSERT_EQ(ref.size(), e1.size());
    double d1 = 0, d2 = 0, d3 = 0, scale = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
        d1 = std::max(d1, std::abs(e1[i] - ref[i]));
        d2 = std::max(d2, std::abs(e2[i] - ref[i]));
        d3 = std::max(d3, std::abs(e3[i] - ref[i]));
        scale = std::max(scale, std::abs(ref[i]));
    }
    std::printf("max lateral error: %.3g, %.3g, %.3g m (scale %.3g m); ratios %.2f %.2f\n", d1, d2, d3, scale, d1 / d2, d2 / d3);
    EXPECT_GT(scale, 20e-6);
    EXPECT_GT(d1 / d2, 3.0);
    EXPECT_GT(d2 / d3, 3.0);
    EXPECT_LT(d3, 0.01 * scale);
}

// history.csv, summary.json and the VTK series give the crank angle of the four-stroke cycle
// (0 = gas-exchange TDC), not the angle turned since time.start_deg. The run starts at 700° and
// crosses 720° = 0°; the crank turns at 6 n °/s (n in rev/min), so a record at time t since the
// start is at 700° + 6 n t, reduced to 0–720.
TEST(PistonSimulation, OutputsGiveTheTrueCrankAngleWhateverTheStart) {
    EngineCase c = smallCase();
    c.grid = {16, 48};
    c.time.startDeg = 700.0;
    c.output.vtkEveryDeg = 10.0;
    PistonSimulation sim(c);
    std::vector<Snapshot> snaps;
    const auto rec = sim.run({.onStep = {}, .onSnapshot = [&](const Snapshot& s) { snaps.push_back(s); }, .onCycleEnd = {}, .progress = {}},
                             40.0);
    ASSERT_GT(rec.size(), 20u);
    auto expected = [&](double time) {
        const double phi = 700.0 + 6.0 * c.engine.speedRpm * time;
        return phi > 720.0 + 1e-9 ? phi - 720.0 : phi;
    };
    int wrapped = 0;
    for (const auto& r : rec) {
        EXPECT_NEAR(r.crankDeg, expected(r.time), 1e-6) << "t = " << r.time << " s";
        wrapped += r.crankDeg < 360.0;
    }
    EXPECT_GT(wrapped, 5);  // the points after 720° are written as 0–20°
    EXPECT_NEAR(rec.back().crankDeg, 20.0, 1e-6);
    // The summary's angles come from the records.
    const CycleMetrics m = cycleMetrics(rec, sim.dynamics(), 1.0);
    auto lowest = std::min_element(rec.begin(), rec.end(), [](const auto& x, const auto& y) { return x.minFilm < y.minFilm; });
    EXPECT_NEAR(m.minFilmDeg, expected(lowest->time), 1e-6);
    // Snapshots every 10° from the start: crank angles 710, 720, 10, 20; the VTK time is the
    // continuous angle 710 … 740.
    ASSERT_EQ(snaps.size(), 4u);
    const double crank[] = {710.0, 720.0, 10.0, 20.0};
    for (std::size_t i = 0; i < snaps.size(); ++i) {
        EXPECT_NEAR(snaps[i].crankDeg, crank[i], 1e-6) << i;
        EXPECT_NEAR(snaps[i].continuousDeg, 710.0 + 10.0 * double(i), 1e-6) << i;
    }
}

// Snapshots closer together than time.min_step_deg do not shorten the steps below it: the
// angles that would need it are skipped, the others are hit exactly, and every snapshot reaches
// the callback as it is taken, followed by the cycle's end.
TEST(PistonSimulation, SnapshotsNeverForceAStepBelowTheSmallest) {
    EngineCase c = smallCase();
    c.grid = {16, 48};
    c.output.vtkEveryDeg = 0.01;
    c.time.minStepDeg = 0.035;
    PistonSimulation sim(c);
    std::vector<double> angles;
    int ends = 0, reported = 0;
    SimulationCallbacks cb;
    cb.onSnapshot = [&](const Snapshot& s) {
        EXPECT_EQ(ends, 0) << "snapshots arrive before the cycle's end";
        angles.push_back(s.continuousDeg);
    };
    cb.onCycleEnd = [&](int, int snapshots, bool last) {
        ++ends;
        reported = snapshots;
        EXPECT_TRUE(last);
    };
    sim.run(cb, 5.0);
    EXPECT_EQ(ends, 1);
    EXPECT_EQ(reported, int(angles.size()));
    EXPECT_GE(sim.statistics().minStepDeg, c.time.minStepDeg - 1e-12);
    ASSERT_GT(angles.size(), 20u);
    for (std::size_t i = 1; i < angles.size(); ++i) {
        const double k = angles[i] / 0.01;
        EXPECT_NEAR(k, std::round(k), 1e-6) << "snapshot " << i << " at " << angles[i] << " deg is on the 0.01° raster";
        EXPECT_GE(angles[i] - angles[i - 1], c.time.minStepDeg - 1e-9) << i;
    }
}

// The periodicity error (docs/coupling.md §1) compares the two cycles at the same crank angle
// also when the written crank angle wraps (start_deg = 300: 300 … 720, 0 … 300). Recomputed
// here from the records of both cycles, matched by time: the crank turns at constant speed, so
// cycle 2 at time t meets cycle 1 at t − 720°/(6 n °/s).
TEST(PistonSimulation, PeriodicityErrorComparesTheSameCrankAngle) {
    EngineCase c = smallCase();
    c.grid = {16, 48};
    c.time.startDeg = 300.0;
    c.time.maxCycles = 2;
    c.time.periodicityTolerance = 1e-12;  // run both cycles
    c.output.vtkEveryDeg = 0.0;
    PistonSimulation sim(c);
    std::vector<StepRecord> all;
    sim.run({.onStep = [&](const StepRecord& r) { all.push_back(r); }, .onSnapshot = {}, .onCycleEnd = {}, .progress = {}});
    ASSERT_EQ(sim.statistics().cycles, 2);
    std::vector<StepRecord> one, two;
    for (const auto& r : all) (r.cycle == 1 ? one : two).push_back(r);
    ASSERT_GT(one.size(), 100u);
    ASSERT_GT(two.size(), 100u);
    // The history holds each step once: cycle 1's last step is the boundary point, which opens
    // cycle 2's comparison too (at the crank angle where cycle 1 started).
    two.insert(two.begin(), one.back());
    const double period = 720.0 / (6.0 * c.engine.speedRpm);  // s
    const double reach = std::max(c.piston.skirtTop, -c.piston.skirtBottom);
    double err = 0.0;
    for (const auto& r : two) {
        const double t = r.time - period;
        auto b = std::lower_bound(one.begin(), one.end(), t, [](const StepRecord& x, double v) { return x.time < v; });
        if (b == one.end()) b = one.end() - 1;
        const auto a = b == one.begin() ? b : b - 1;
        const double w = b->time > a->time ? std::clamp((t - a->time) / (b->time - a->time), 0.0, 1.0) : 0.0;
        const double e = a->lateral + w * (b->lateral - a->lateral), beta = a->tilt + w * (b->tilt - a->tilt);
        err = std::max(err, std::abs(r.lateral - e) + std::abs(r.tilt - beta) * reach);
    }
    std::printf("periodicity error %.6g m (recomputed %.6g m)\n", sim.statistics().periodicityError, err);
    EXPECT_GT(err, 1e-8);  // the first cycle starts at rest: the two cycles differ
    EXPECT_NEAR(sim.statistics().periodicityError, err, 1e-3 * err);
}

// When the iteration cannot converge the diagnosis reports the film solves the failed attempt
// made: with coupling.max_iterations = 1, one pass plus the two of the finite-difference
// Jacobian, 3 in all. Starting at 90° (large rod angle and inertia) one pass is not enough, the
// step is quartered below time.min_step_deg and the run stops.
TEST(PistonSimulation, NonConvergenceReportsTheFilmSolvesMade) {
    EngineCase c = smallCase();
    c.grid = {16, 48};
    c.time.startDeg = 90.0;
    c.time.minStepDeg = 0.05;  // the first step, 0.1°, retried at 0.025°: below
    c.coupling.maxIterations = 1;
    PistonSimulation sim(c);
    try {
        sim.run({}, 10.0);
        FAIL() << "the run should stop";
    } catch (const std::runtime_error& e) {
        const std::string m = e.what();
        std::printf("%s\n", m.c_str());
        EXPECT_NE(m.find("coupling.max_iterations = 1 passes (3 film solves"), std::string::npos) << m;
        EXPECT_NE(m.find("at crank angle 90.0000 deg"), std::string::npos) << m;
    }
}
