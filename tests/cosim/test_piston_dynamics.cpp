// Piston secondary motion: crank-slider kinematics, the equations of motion (docs/dynamics.md),
// and the rigid-body (HD) co-simulation: no-motion limit, force and moment balance at every step
// (recomputed from history.csv quantities), and time-step convergence.
#include "cosim/CrankKinematics.hpp"
#include "cosim/PistonDynamics.hpp"
#include "cosim/PistonSimulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace flexehd::cosim;

namespace {

// A small engine close to the example (86 × 86 mm), with a synthetic firing pressure trace.
EngineCase smallCase() {
    EngineCase c;
    c.engine = EngineSpec{};
    c.engine.rodLength = 0.1435;
    c.piston.mass = 0.32;
    c.piston.pinMass = 0.10;
    c.piston.inertia = 2.6e-4;
    c.piston.cgX = 0.0;
    c.piston.cgZ = 0.006;
    c.piston.skirtTop = 0.0108;
    c.piston.skirtBottom = -0.025;
    c.piston.clearance = 50e-6;
    c.piston.skirtHalfAngle = 40.0 * std::numbers::pi / 180.0;
    for (double z = -0.025; z <= 0.01081; z += 0.0358 / 8) {
        const double s = (z - (-0.008)) / 0.018;
        c.piston.profile.push_back({z, 20e-6 * s * s});
    }
    c.lubricant.viscosity = 0.008;
    c.contact.compositeModulus = 5.6e10;
    for (int d = 0; d <= 720; d += 2) {
        const double x = (d - 372.0) / 28.0;
        c.cylinderPressure.push_back({double(d), 1.0e5 + 3.4e6 * std::exp(-x * x)});
    }
    c.grid.axialNodes = 24;
    c.grid.circumferentialNodes = 72;
    c.time.maxCycles = 1;
    return c;
}

}  // namespace

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
        sim.run({.onStep = {}, .onSnapshot = [&](const Snapshot& s) { e.push_back(s.lateral); }, .progress = {}}, 120.0);
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
