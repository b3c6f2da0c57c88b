// The film–structure fixed-point accelerators (docs/coupling.md §1) on affine maps H(y) = A y + b,
// where both are exact in finitely many iterations.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "cosim/coupling/CouplingAccelerator.hpp"

using namespace flexehd;

namespace {

// Iterates y ← acc.next(y, H(y)) from y = 0; returns the residual ‖H(y) − y‖ after `passes` passes.
template <int N>
double residualAfter(cosim::CouplingAccelerator& acc, const Eigen::Matrix<double, N, N>& A,
                     const Eigen::Matrix<double, N, 1>& b, int passes) {
    Eigen::Matrix<double, N, 1> y = Eigen::Matrix<double, N, 1>::Zero();
    for (int k = 0; k < passes; ++k) y = acc.next(y, A * y + b);
    return (A * y + b - y).norm();
}

}  // namespace

TEST(CouplingAccelerator, FirstPassIsTheRelaxedStep) {
    for (auto method : {cosim::CouplingAcceleration::IqnIls, cosim::CouplingAcceleration::Aitken}) {
        auto acc = cosim::makeCouplingAccelerator(method, 0.25);
        const Eigen::Vector2d y(1.0, 2.0), Hy(3.0, -2.0);
        EXPECT_EQ(acc->next(y, Hy), Eigen::Vector2d(1.5, 1.0));
        acc->next(Hy, y);
        acc->reset();  // a new history: the relaxed step again
        EXPECT_EQ(acc->next(y, Hy), Eigen::Vector2d(1.5, 1.0));
    }
}

TEST(CouplingAccelerator, IqnIlsSolvesAnAffineMapOfDimensionN) {
    // A divergent plain iteration (spectral radius > 1): the least-squares model is exact once it
    // has n difference columns.
    Eigen::Matrix3d A;
    A << 1.5, 0.2, -0.1, 0.3, -0.8, 0.4, 0.0, 0.5, 0.9;
    const Eigen::Vector3d b(1.0, -2.0, 0.5);
    auto acc = cosim::makeCouplingAccelerator(cosim::CouplingAcceleration::IqnIls);
    EXPECT_LT(residualAfter<3>(*acc, A, b, 5), 1e-10);
}

TEST(CouplingAccelerator, AitkenSolvesAnAffineMapOfOneEigenvalue) {
    // y = −2 y + b (fixed point b/3): plain iteration diverges, Aitken's secant step is exact.
    const Eigen::Matrix2d A = -2.0 * Eigen::Matrix2d::Identity();
    const Eigen::Vector2d b(3.0, 6.0);
    auto acc = cosim::makeCouplingAccelerator(cosim::CouplingAcceleration::Aitken);
    EXPECT_LT(residualAfter<2>(*acc, A, b, 3), 1e-12);
}
