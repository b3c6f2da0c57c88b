// AitkenRelaxation (lube/AitkenRelaxation.hpp): on a linear map its second relaxed step is the
// secant step, which lands on a scalar fixed point exactly; ω stays within its bounds; reset()
// starts over; on a linear contraction in several dimensions it needs fewer iterations than the
// plain iteration.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "lube/AitkenRelaxation.hpp"

using flexehd::lube::AitkenRelaxation;

namespace {

Eigen::VectorXd scalar(double v) { return Eigen::VectorXd::Constant(1, v); }
Eigen::VectorXd G(const Eigen::VectorXd& x) { return 0.9 * x.array() + 1.0; }  // fixed point 10

}  // namespace

TEST(AitkenRelaxation, SecondStepLandsOnAScalarLinearFixedPoint) {
    AitkenRelaxation a(1.0);
    Eigen::VectorXd x = scalar(0.0);
    x = a.next(x, G(x));  // ω₁ = 1: the plain step, 1
    EXPECT_DOUBLE_EQ(x[0], 1.0);
    x = a.next(x, G(x));  // ω = −1 · 1 · (−0.1) / 0.01 = 10: 1 + 10 · 0.9
    EXPECT_NEAR(x[0], 10.0, 1e-12);
    EXPECT_NEAR(a.relaxation(), 10.0, 1e-12);
}

TEST(AitkenRelaxation, RelaxationStaysWithinItsBoundsAndResetStartsOver) {
    AitkenRelaxation a(0.5, 0.05, 4.0);
    Eigen::VectorXd x = scalar(0.0);
    x = a.next(x, G(x));  // 0.5
    EXPECT_DOUBLE_EQ(x[0], 0.5);
    const Eigen::VectorXd before = x;
    x = a.next(x, G(x));  // unbounded ω would be 10: held at 4
    EXPECT_DOUBLE_EQ(a.relaxation(), 4.0);
    EXPECT_NEAR(x[0], before[0] + 4.0 * (G(before)[0] - before[0]), 1e-12);
    a.reset();
    EXPECT_DOUBLE_EQ(a.relaxation(), 0.5);
    EXPECT_DOUBLE_EQ(a.next(scalar(0.0), G(scalar(0.0)))[0], 0.5);
}

TEST(AitkenRelaxation, NeedsFewerIterationsThanThePlainIterationOnALinearContraction) {
    // x = M x + b with M = diag(0.95, 0.9, 0.8) rotated: fixed point (I − M)⁻¹ b.
    Eigen::Matrix3d Q;
    Q = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const Eigen::Matrix3d M = Q * Eigen::Vector3d(0.95, 0.9, 0.8).asDiagonal() * Q.transpose();
    const Eigen::Vector3d b(1.0, -2.0, 0.5);
    const Eigen::Vector3d exact = (Eigen::Matrix3d::Identity() - M).lu().solve(b);
    auto iterations = [&](bool relaxed) {
        AitkenRelaxation a(1.0);
        Eigen::VectorXd x = Eigen::VectorXd::Zero(3);
        for (int k = 1; k <= 1000; ++k) {
            const Eigen::VectorXd gx = M * x + b;
            x = relaxed ? a.next(x, gx) : gx;
            if ((x - exact).norm() < 1e-10 * exact.norm()) return k;
        }
        return 1001;
    };
    const int plain = iterations(false), aitken = iterations(true);
    EXPECT_LT(plain, 1001);
    EXPECT_LT(aitken, plain / 2) << "plain " << plain << ", Aitken " << aitken;
}
