// Greenwood–Tripp asperity contact against exact F_{5/2} values (the integral to 6 digits) and K (Greenwood & Tripp 1970).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lube/GreenwoodTripp.hpp"

using flexehd::lube::AsperityFunction;
using flexehd::lube::GreenwoodTripp;

// The reference values are given to 6 significant digits: compare to half a unit of the last digit.
TEST(GreenwoodTripp, ExactF52Values) {
    const double lam[] = {0.0, 0.5, 1.0, 2.0, 3.0};
    const double ref[] = {0.616634, 0.240402, 0.080562, 0.005424, 0.000171};
    const double digit[] = {1e-6, 1e-6, 1e-6, 1e-6, 1e-6};
    for (int i = 0; i < 5; ++i) {
        EXPECT_NEAR(GreenwoodTripp::F52(lam[i]), ref[i], 0.5 * digit[i]) << "lambda " << lam[i];
        EXPECT_NEAR(GreenwoodTripp::integralF(2.5, lam[i]), ref[i], 0.5 * digit[i]);
    }
    // F_0(0) = 1/2 and F_1(0) = (2π)^(-1/2) in closed form.
    EXPECT_NEAR(GreenwoodTripp::integralF(0.0, 0.0), 0.5, 1e-12);
    EXPECT_NEAR(GreenwoodTripp::integralF(1.0, 0.0), 1 / std::sqrt(2 * 3.14159265358979323846), 1e-12);
}

// The table (step 0.01, Hermite on ln F) reproduces direct quadrature between its nodes.
TEST(GreenwoodTripp, TableInterpolationAccuracy) {
    for (double lam = -1.993; lam < 7.9; lam += 0.137) {
        const double direct = GreenwoodTripp::integralF(2.5, lam);
        EXPECT_NEAR(GreenwoodTripp::F52(lam) / direct, 1.0, 1e-7) << "lambda " << lam;
    }
    EXPECT_EQ(GreenwoodTripp::F52(8.5), 0.0);
    // dF_{5/2}/dλ = −(5/2)F_{3/2}: check by central difference.
    const double d = 1e-4, lam = 1.3;
    EXPECT_NEAR(GreenwoodTripp::dF52(lam),
                (GreenwoodTripp::F52(lam + d) - GreenwoodTripp::F52(lam - d)) / (2 * d), 1e-7);
    // The interpolant's derivative against the direct quadrature of −(5/2)F_{3/2}, between the
    // table's nodes and beyond its ends.
    double worst = 0.0;
    for (double l = -2.493; l < 7.9; l += 0.137) {
        const double direct = -2.5 * GreenwoodTripp::integralF(1.5, l);
        worst = std::max(worst, std::abs(GreenwoodTripp::dF52(l) / direct - 1.0));
    }
    std::printf("dF52 from the table: largest relative deviation from quadrature %.2g\n", worst);
    EXPECT_LT(worst, 1e-5);
    EXPECT_EQ(GreenwoodTripp::dF52(8.5), 0.0);
}

// Hu et al. fit: 11% low at λ = 0 and ~4× low at λ = 3 (Hu et al. 1994), fine near λ ≈ 1.
TEST(GreenwoodTripp, HuFitDeviations) {
    EXPECT_NEAR(GreenwoodTripp::F52Hu(0.0) / GreenwoodTripp::F52(0.0), 0.89, 0.01);
    EXPECT_NEAR(GreenwoodTripp::F52(3.0) / GreenwoodTripp::F52Hu(3.0), 3.9, 0.1);
    EXPECT_NEAR(GreenwoodTripp::F52Hu(1.2) / GreenwoodTripp::F52(1.2), 1.0, 0.03);
    EXPECT_EQ(GreenwoodTripp::F52Hu(4.0), 0.0);
}

// K = (16√2π/15)(η_sβσ)²√(σ/β) = 2.3978e-4 for η_sβσ = 0.04, σ/β = 1e-3, and the
// contact pressure p_c = K E* F_{5/2}(h/σ) with the Hertz composite modulus.
TEST(GreenwoodTripp, CoefficientAndPressure) {
    const double sigma = 0.5e-6, beta = sigma / 1e-3, density = 0.04 / (beta * sigma);
    EXPECT_NEAR(GreenwoodTripp::coefficient(sigma, beta, density), 2.3978e-4, 0.5e-8);
    const double E = GreenwoodTripp::compositeModulus(210e9, 0.3, 210e9, 0.3);
    EXPECT_NEAR(E, 210e9 / (2 * (1 - 0.09)), 1.0);
    const GreenwoodTripp gt(sigma, beta, density, E);
    EXPECT_NEAR(gt.pressure(sigma) / (2.3978e-4 * E * 0.080562), 1.0, 1e-4);
    EXPECT_LT(gt.pressureSlope(sigma), 0.0);
    const GreenwoodTripp hu(sigma, beta, density, E, AsperityFunction::HuFit);
    EXPECT_NEAR(hu.pressure(0.0) / gt.pressure(0.0), 0.89, 0.01);
    EXPECT_THROW(GreenwoodTripp(0.0, beta, density, E), std::invalid_argument);
    EXPECT_THROW(GreenwoodTripp::compositeModulus(210e9, 0.6, 210e9, 0.3), std::invalid_argument);
}
