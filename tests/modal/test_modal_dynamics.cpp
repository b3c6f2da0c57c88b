// Modal superposition and time integration on synthetic reduced bodies against
// closed-form responses.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "modal/ModalDamping.hpp"
#include "modal/ModalSuperposition.hpp"

using namespace flexehd::modal;

namespace {
ReducedBody oscillators(double w1, double w2, double zeta) {
    ReducedBody b;
    b.shapes = Eigen::MatrixXd::Identity(6, 2);
    b.massMatrix = Eigen::MatrixXd::Identity(2, 2);
    b.stiffnessMatrix = Eigen::Vector2d(w1 * w1, w2 * w2).asDiagonal();
    b.dampingRatios = Eigen::Vector2d::Constant(zeta);
    b.frequenciesHz = Eigen::Vector2d(w1, w2) / (2 * std::numbers::pi);
    b.rigidBody = {0, 0};
    return b;
}
}  // namespace

// Undamped oscillator under a step force F: q = F/ω² (1 - cos ωt). The trapezoidal rule is
// second order: the error falls ~4x when Δt halves.
TEST(ModalDynamics, StepResponseOfUndampedOscillatorSecondOrder) {
    const double w = 2 * std::numbers::pi * 50.0, F = 3.0, T = 0.013;
    const ReducedBody b = oscillators(w, 2 * w, 0.0);
    double err[2];
    for (int r = 0; r < 2; ++r) {
        const int steps = 400 << r;
        ModalDynamics dyn(b, T / steps);
        dyn.setState(Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), Eigen::Vector2d(F, 0));
        for (int s = 0; s < steps; ++s) dyn.step(Eigen::Vector2d(F, 0));
        err[r] = std::abs(dyn.q()(0) - F / (w * w) * (1 - std::cos(w * T))) / (F / (w * w));
    }
    EXPECT_LT(err[1], 1e-3);
    EXPECT_NEAR(err[0] / err[1], 4.0, 0.5);
}

// Damped free vibration: q = e^{-ζωt}(cos ω_d t + ζω/ω_d sin ω_d t), ω_d = ω√(1-ζ²).
TEST(ModalDynamics, DampedFreeVibration) {
    const double w = 2 * std::numbers::pi * 20.0, zeta = 0.05, T = 0.1;
    const ReducedBody b = oscillators(w, w, zeta);
    ModalDynamics dyn(b, T / 4000);
    dyn.setState(Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero());
    for (int s = 0; s < 4000; ++s) dyn.step(Eigen::Vector2d::Zero());
    const double wd = w * std::sqrt(1 - zeta * zeta);
    const double exact = std::exp(-zeta * w * T) * (std::cos(wd * T) + zeta * w / wd * std::sin(wd * T));
    EXPECT_NEAR(dyn.q()(0), exact, 1e-4);
}

TEST(ModalSuperposition, QuasiStaticIsStaticDeflectionAndForcesTranspose) {
    const ReducedBody b = oscillators(10.0, 20.0, 0.0);
    ModalSuperposition sup(b);
    Eigen::VectorXd f(6);
    f << 1, 2, 3, 4, 5, 6;
    const Eigen::VectorXd g = sup.modalForce(f);
    EXPECT_DOUBLE_EQ(g(0), 1.0);
    EXPECT_DOUBLE_EQ(g(1), 2.0);
    const Eigen::VectorXd q = sup.quasiStatic(g, {});
    EXPECT_NEAR(q(0), 1.0 / 100.0, 1e-15);
    EXPECT_NEAR(q(1), 2.0 / 400.0, 1e-15);
    EXPECT_DOUBLE_EQ(sup.displacement(q)(1), q(1));
}

TEST(ModalDamping, BandsAssignRatiosByFrequencyRigidModesUndamped) {
    ReducedBody b;
    b.frequenciesHz = Eigen::VectorXd(5);
    b.frequenciesHz << 0.0, 900.0, 3000.0, 8000.0, 20000.0;
    b.rigidBody = {1, 0, 0, 0, 0};
    b.shapes = Eigen::MatrixXd::Zero(3, 5);
    assignModalDamping(b, 0.05, {parseDampingBand("10000:0.02"), parseDampingBand("1000:0.01")});
    EXPECT_EQ(b.dampingRatios(0), 0.0);
    EXPECT_EQ(b.dampingRatios(1), 0.01);
    EXPECT_EQ(b.dampingRatios(2), 0.02);
    EXPECT_EQ(b.dampingRatios(3), 0.02);
    EXPECT_EQ(b.dampingRatios(4), 0.05);
    EXPECT_THROW(parseDampingBand("1000"), std::invalid_argument);
    EXPECT_THROW(parseDampingBand("1000:1.5"), std::invalid_argument);
}
