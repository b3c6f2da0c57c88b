// ModalPropagator (the exact response of a held reduced body to a force linear over each step,
// docs/modal.md) against closed forms and against the BDF2 integrator it stands beside:
//  - one damped mode under a ramp force from rest: the closed-form response, at steps from a
//    hundredth of the period to ten periods, to round-off;
//  - one mode ringing freely at a step of three periods: exact amplitude and phase, where BDF2
//    at the same step has damped it away (the reason the liner's acoustic record uses it);
//  - the samples within a step agree with a step of that length, and the step is affine in the
//    end force: respond(f) = loadResponse(f) + respond(0);
//  - five coupled modes with a held interface and non-proportional damping (the damping couples
//    the held body's modes): BDF2 converges at second order to the propagator's response;
//  - a body that can still move rigidly, and a critically damped mode, are refused.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <utility>

#include <gtest/gtest.h>

#include "modal/HeldModalDynamics.hpp"
#include "modal/ModalPropagator.hpp"
#include "OscillatorModes.hpp"

using namespace flexehd::modal;

namespace {
constexpr double kPi = std::numbers::pi;

ReducedBody modes(const Eigen::VectorXd& omega, double zeta) { return flexehd::test::oscillatorModes(omega, zeta); }

/// x'' + 2ζω x' + ω² x = a t from rest: x and x'.
Eigen::Vector2d rampResponse(double w, double zeta, double a, double t) {
    const double wd = w * std::sqrt(1 - zeta * zeta);
    const double c1 = 2 * zeta * a / (w * w * w), c2 = (zeta * w * c1 - a / (w * w)) / wd;
    const double e = std::exp(-zeta * w * t), c = std::cos(wd * t), s = std::sin(wd * t);
    const double x = a / (w * w) * (t - 2 * zeta / w) + e * (c1 * c + c2 * s);
    const double v = a / (w * w) + e * (-zeta * w * (c1 * c + c2 * s) + wd * (-c1 * s + c2 * c));
    return {x, v};
}

ModalStepStart startOf(Eigen::VectorXd q, Eigen::VectorXd v, Eigen::VectorXd f, double dt) {
    ModalStepStart s;
    s.dt = dt;
    s.y = std::move(q);
    s.w = std::move(v);
    s.f = std::move(f);
    return s;
}
}  // namespace

TEST(ModalPropagator, OneModeUnderARampIsExactAtAnyStep) {
    const double w = 2 * kPi * 800.0, zeta = 0.05, a = 3.0e6;  // N/s per unit modal mass
    const ModalPropagator prop(modes(Eigen::VectorXd::Constant(1, w), zeta), {});
    ModalPropagator p = prop;
    const double period = 2 * kPi / w;
    Eigen::VectorXd q = Eigen::VectorXd::Zero(1), v = q, qn;
    double t = 0.0, err = 0.0, scale = 0.0;
    for (const double h : {0.01, 0.3, 1.0, 10.0, 0.07, 2.5, 0.01}) {  // in periods
        const double dt = h * period;
        p.beginStep(startOf(q, v, Eigen::VectorXd::Constant(1, a * t), dt));
        const Eigen::VectorXd fEnd = Eigen::VectorXd::Constant(1, a * (t + dt));
        p.respond(fEnd, qn);
        v = p.velocity(qn, fEnd);
        q = qn;
        t += dt;
        const Eigen::Vector2d exact = rampResponse(w, zeta, a, t);
        err = std::max({err, std::abs(q[0] - exact[0]), std::abs(v[0] - exact[1]) / w});
        scale = std::max(scale, std::abs(exact[0]));
    }
    std::printf("ramp over steps of 0.01 to 10 periods: max error / max |x| = %.3g\n", err / scale);
    EXPECT_LT(err, 1e-11 * scale);
}

// The work over the steps of the ramp (exact, by parts) against the energy balance of the closed
// form: W = ½ ẋ² + ½ ω² x² at the end + ∫ 2ζω ẋ² dt (Simpson, 20 000 intervals).
TEST(ModalPropagator, TheWorkOverItsStepsIsTheEnergyTheModeStoredAndDamped) {
    const double w = 2 * kPi * 800.0, zeta = 0.05, a = 3.0e6;
    ModalPropagator p(modes(Eigen::VectorXd::Constant(1, w), zeta), {});
    const double period = 2 * kPi / w;
    Eigen::VectorXd q = Eigen::VectorXd::Zero(1), v = q, qn;
    double t = 0.0, work = 0.0;
    for (const double h : {0.3, 1.7, 0.05, 4.0, 0.9}) {
        const double dt = h * period;
        const Eigen::VectorXd fStart = Eigen::VectorXd::Constant(1, a * t), fEnd = Eigen::VectorXd::Constant(1, a * (t + dt));
        p.beginStep(startOf(q, v, fStart, dt));
        p.respond(fEnd, qn);
        work += p.workOver(q, v, fStart, fEnd, dt, qn);
        v = p.velocity(qn, fEnd);
        q = qn;
        t += dt;
    }
    const int n = 20000;
    double damped = 0.0;
    for (int k = 0; k <= n; ++k) {
        const double weight = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        damped += weight * 2 * zeta * w * std::pow(rampResponse(w, zeta, a, t * k / n)[1], 2);
    }
    damped *= t / (3.0 * n);
    const Eigen::Vector2d end = rampResponse(w, zeta, a, t);
    const double stored = 0.5 * end[1] * end[1] + 0.5 * w * w * end[0] * end[0];
    std::printf("work %.9g, stored %.9g + damped %.9g = %.9g\n", work, stored, damped, stored + damped);
    EXPECT_NEAR(work, stored + damped, 1e-9 * work);
}

TEST(ModalPropagator, AModeRingsAtAStepOfThreePeriodsWhereBdf2DampsIt) {
    const double w = 2 * kPi * 4400.0, zeta = 0.02;  // the example liner's first held mode
    const ReducedBody b = modes(Eigen::VectorXd::Constant(1, w), zeta);
    ModalPropagator p(b, {});
    HeldModalDynamics bdf2(b, {});
    const double dt = 3.0 * 2 * kPi / w;
    Eigen::VectorXd q = Eigen::VectorXd::Constant(1, 1e-6), v = Eigen::VectorXd::Zero(1), zero = v, qn;
    Eigen::VectorXd qb = q, qbOld = q, vb = v, vbOld = v;
    const int steps = 10;
    for (int k = 0; k < steps; ++k) {
        p.beginStep(startOf(q, v, zero, dt));
        p.respond(zero, qn);
        v = p.velocity(qn, zero);
        q = qn;
        ModalStepStart s = startOf(qb, vb, zero, dt);
        if (k > 0) s.a0 = 1.5, s.a1 = -2.0, s.a2 = 0.5, s.yBefore = qbOld, s.wBefore = vbOld;
        bdf2.beginStep(s);
        bdf2.respond(zero, qn);
        qbOld = qb, vbOld = vb;
        vb = bdf2.velocity(qn, zero);
        qb = qn;
    }
    // Free decay: x = x0 e^{−ζωt}(cos ω_d t + ζ/√(1−ζ²) sin ω_d t).
    const double t = steps * dt, wd = w * std::sqrt(1 - zeta * zeta);
    const double exact = 1e-6 * std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t));
    std::printf("after 30 periods in 10 steps: exact %.6e, propagator %.6e, BDF2 %.3e\n", exact, q[0], qb[0]);
    EXPECT_NEAR(q[0], exact, 1e-12 * 1e-6);
    EXPECT_LT(std::abs(qb[0]), 0.1 * std::abs(exact));  // BDF2 has damped it numerically
}

TEST(ModalPropagator, SamplesWithinAStepAgreeWithTheStepAndTheStepIsAffineInTheEndForce) {
    Eigen::VectorXd omega(3);
    omega << 900, 2500, 7000;
    ReducedBody b = modes(2 * kPi * omega, 0.03);
    ModalPropagator p(b, {});
    const Eigen::Vector3d q0(1e-6, -2e-7, 5e-8), v0(1e-3, 2e-3, -1e-3), f0(1e3, -2e3, 4e3), f1(-3e3, 1e3, 2e3);
    const double dt = 1e-4;
    Eigen::VectorXd q, qZero, g;
    for (const double tau : {2.5e-5, 7e-5, 1e-4}) {
        p.beginStep(startOf(q0, v0, f0, tau));
        // The force at τ along the line from f0 (at 0) to f1 (at Δt).
        const Eigen::VectorXd fTau = f0 + (f1 - f0) * (tau / dt);
        p.respond(fTau, q);
        const Eigen::VectorXd v = p.velocity(q, fTau);
        Eigen::MatrixXd qWithin, vWithin;
        p.responseWithin(q0, v0, f0, f1, dt, {tau}, qWithin, vWithin);
        EXPECT_LT((vWithin.col(0) - v).norm(), 1e-12 * v.norm()) << "tau " << tau;
        EXPECT_LT((qWithin.col(0) - q).norm(), 1e-12 * q.norm()) << "tau " << tau;
        p.respond(Eigen::VectorXd::Zero(3), qZero);
        p.loadResponse(fTau, g);
        EXPECT_LT((q - qZero - g).norm(), 1e-14 * q.norm()) << "tau " << tau;
    }
}

// Five modes, one held interface mixing them (two constraints), damping ratios 0.01–0.3 per mode:
// on the three free coordinates the damping does not diagonalise with the stiffness. The force
// ramps for 2 ms; BDF2 at 1/64 … 1/256 of the shortest held period converges at second order to
// the propagator's answer at 20 steps.
TEST(ModalPropagator, Bdf2ConvergesToItOnAHeldBodyWithCoupledDamping) {
    Eigen::VectorXd omega(5);
    omega << 200, 450, 900, 2000, 5000;
    omega *= 2 * kPi;
    ReducedBody b = modes(omega, 0.0);
    b.dampingRatios << 0.01, 0.3, 0.05, 0.2, 0.02;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    b.interfaces.resize(1);
    b.interfaceMotion = Eigen::MatrixXd::Zero(6, 5);
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 5; ++j) b.interfaceMotion(i, j) = u(rng);
    Eigen::VectorXd f(5);
    for (int j = 0; j < 5; ++j) f[j] = 1e3 * u(rng);
    const double T = 2e-3;
    ModalPropagator p(b, {0});
    Eigen::VectorXd q = Eigen::VectorXd::Zero(5), v = q, qn;
    for (int k = 0; k < 20; ++k) {
        const double t = k * T / 20;
        p.beginStep(startOf(q, v, f * (t / T), T / 20));
        p.respond(f * ((t + T / 20) / T), qn);
        v = p.velocity(qn, f * ((t + T / 20) / T));
        q = qn;
    }
    EXPECT_LT((b.interfaceMotion * q).norm(), 1e-12 * q.norm());
    std::vector<double> errors;
    for (const int n : {640, 1280, 2560}) {
        HeldModalDynamics d(b, {0});
        Eigen::VectorXd x = Eigen::VectorXd::Zero(5), xOld = x, w = x, wOld = x, xn;
        for (int k = 0; k < n; ++k) {
            ModalStepStart s = startOf(x, w, Eigen::VectorXd(), T / n);
            if (k > 0) s.a0 = 1.5, s.a1 = -2.0, s.a2 = 0.5, s.yBefore = xOld, s.wBefore = wOld;
            d.beginStep(s);
            d.respond(f * ((k + 1.0) / n), xn);
            xOld = x, wOld = w;
            w = d.velocity(xn, Eigen::VectorXd());
            x = xn;
        }
        errors.push_back((x - q).norm() / q.norm());
    }
    std::printf("BDF2 against the propagator: %.3g, %.3g, %.3g\n", errors[0], errors[1], errors[2]);
    EXPECT_LT(errors.back(), 1e-3);
    for (std::size_t k = 1; k < errors.size(); ++k) {
        EXPECT_GT(errors[k - 1] / errors[k], 3.5);
        EXPECT_LT(errors[k - 1] / errors[k], 4.5);
    }
}

TEST(ModalPropagator, RigidMotionAndCriticalDampingAreRefused) {
    Eigen::VectorXd omega(2);
    omega << 0.0, 100.0;
    EXPECT_THROW(ModalPropagator(modes(omega, 0.0), {}), std::runtime_error);
    Eigen::VectorXd two(2);
    two << 100.0, 100.0;
    try {
        ModalPropagator(modes(two, 1.0), {});
        FAIL() << "a critically damped pair was accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("critically"), std::string::npos) << e.what();
    }
    // An interface that holds every mode: no response, no failure.
    ReducedBody fixedBody = modes(Eigen::VectorXd::Constant(1, 100.0), 0.1);
    fixedBody.interfaces.resize(1);
    fixedBody.interfaceMotion = Eigen::MatrixXd::Constant(6, 1, 1.0);
    ModalPropagator fixed(fixedBody, {0});
    fixed.beginStep(startOf(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Zero(1), Eigen::VectorXd::Ones(1), 1e-3));
    Eigen::VectorXd qFixed;
    fixed.respond(Eigen::VectorXd::Constant(1, 5.0), qFixed);
    EXPECT_EQ(qFixed.size(), 1);
    EXPECT_EQ(qFixed[0], 0.0);
    ModalPropagator p(modes(Eigen::VectorXd::Constant(1, 100.0), 0.1), {});
    Eigen::VectorXd q;
    EXPECT_THROW(p.respond(Eigen::VectorXd::Zero(1), q), std::logic_error);
    EXPECT_THROW(p.beginStep(startOf(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Zero(1), Eigen::VectorXd(), 0.0)),
                 std::invalid_argument);
}
