// ShearStressFactor (the Couette shear between rough surfaces, Patir & Cheng 1979) against its
// definition evaluated by quadrature: the mean of h/h_T over the local gaps h_T = h − δ of the
// polynomial height density f(δ) = 35/(96σ) (1 − δ²/9σ²)³ on |δ| ≤ 3σ. With x = δ/3σ, z = h/3σ
// it is (35/32) z ∫ (1 − x²)³/(z − x) dx; where the surfaces' heights reach across the film
// (z ≤ 1) the integrand's singular part (1 − z²)³/(z − x) is cut off at the local gap ε = σ/100
// (z − x ≥ 1/300) and its regular part ((1 − x²)³ − (1 − z²)³)/(z − x) taken up to x = z. Also
// its slope against differences, the smooth limit and the finite shear at contact.
#include <gtest/gtest.h>

#include <cmath>

#include "lube/ShearStressFactor.hpp"

using flexehd::lube::ShearStressFactor;

namespace {

// Simpson's rule for g over [a, b] (n even).
template <class G>
double simpson(const G& g, double a, double b, int n = 20000) {
    const double d = (b - a) / n;
    double sum = g(a) + g(b);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * g(a + i * d);
    return sum * d / 3.0;
}

double definition(double H) {
    const double z = H / 3.0, cube = std::pow(1.0 - z * z, 3);
    if (z > 1.0)  // ∫ over x ∈ [−1, 1] in s = ln(z − x): smooth
        return 35.0 / 32.0 * z * simpson([&](double s) {
            const double x = z - std::exp(s);
            return std::pow(1.0 - x * x, 3);  // (1 − x²)³/(z − x) · (z − x)
        }, std::log(z - 1.0), std::log(z + 1.0));
    const double singular = cube * simpson([](double) { return 1.0; }, std::log(1.0 / 300.0), std::log(z + 1.0));
    const double regular = simpson([&](double x) {
        const double t = z - x;  // ((1 − x²)³ − (1 − z²)³)/t, its limit 6z(1 − z²)² at t = 0
        return t > 1e-12 ? (std::pow(1.0 - x * x, 3) - cube) / t : 6.0 * z * std::pow(1.0 - z * z, 2);
    }, -1.0, z);
    return 35.0 / 32.0 * z * (singular + regular);
}

}  // namespace

TEST(ShearStressFactor, IsTheMeanOfTheLocalCouetteShearOverTheRoughness) {
    for (const double H : {0.01, 0.05, 0.3, 1.0, 2.0, 2.99, 3.01, 4.5, 8.9, 9.1, 15.0, 40.0, 300.0}) {
        double phi, d;
        ShearStressFactor::ofFilmParameter(H, phi, d);
        const double expected = definition(H);
        std::printf("H %6.2f  phi_f %.8f  quadrature %.8f\n", H, phi, expected);
        EXPECT_NEAR(phi, expected, 1e-7 * expected) << "H = " << H;
    }
}

// What the film integrals use: the closed form's tables (H ≤ 90) and expansion (beyond).
TEST(ShearStressFactor, TheInterpolatedFactorIsTheClosedForm) {
    double worst = 0.0, worstSlope = 0.0;
    for (double H = 0.0; H <= 200.0; H += H < 20.0 ? 0.000731 : 0.0731) {
        double phi, d, phiT, dT;
        ShearStressFactor::ofFilmParameter(H, phi, d);
        ShearStressFactor::interpolated(H, phiT, dT);
        worst = std::max(worst, std::abs(phiT - phi));
        worstSlope = std::max(worstSlope, std::abs(dT - d));
    }
    std::printf("interpolated against the closed form: value %.3g, slope %.3g\n", worst, worstSlope);
    EXPECT_LT(worst, 1e-9);
    EXPECT_LT(worstSlope, 1e-5);
}

TEST(ShearStressFactor, ItsSlopeIsTheDifferenceQuotient) {
    for (const double H : {0.02, 0.7, 2.5, 3.0, 3.5, 8.0, 9.0, 12.0, 60.0}) {
        double phi, d, phiP, dP, phiM, dM;
        const double step = 1e-4 * std::max(H, 1.0);
        ShearStressFactor::ofFilmParameter(H, phi, d);
        ShearStressFactor::ofFilmParameter(H + step, phiP, dP);
        ShearStressFactor::ofFilmParameter(H - step, phiM, dM);
        EXPECT_NEAR(d, (phiP - phiM) / (2.0 * step), 1e-6 * std::max(std::abs(d), 1e-2)) << "H = " << H;
    }
    const ShearStressFactor rough(0.6e-6);
    for (const double h : {0.03e-6, 1.0e-6, 3.0e-6, 10.0e-6}) {
        double c, dc, cP, dcP, cM, dcM;
        rough.couette(h, c, dc);
        rough.couette(h * (1 + 1e-6), cP, dcP);
        rough.couette(h * (1 - 1e-6), cM, dcM);
        EXPECT_NEAR(dc, (cP - cM) / (2e-6 * h), 1e-5 * std::abs(dc) + 1e-6 * c / h) << "h = " << h;
    }
}

// Smooth surfaces: the Couette shear ηΔV/h; far from contact the rough factor tends to it (as
// 1 + 1/(9z²), the expansion of the closed form for large z); at
// contact the rough shear stays finite, (35/32)(ln 300 − 55/60)/(3σ) per unit ηΔV, the shear of
// a smooth film of about 0.57σ (a smooth film floored at 0.05σ would shear 11 times that).
TEST(ShearStressFactor, SmoothFarAndFiniteAtContact) {
    const ShearStressFactor smooth(0.0), rough(0.6e-6);
    double c, dc;
    smooth.couette(2e-6, c, dc);
    EXPECT_DOUBLE_EQ(c, 1.0 / 2e-6);
    EXPECT_DOUBLE_EQ(smooth.factor(1e-9), 1.0);
    const double z = 1000.0 / 3.0;  // H = 1000: φ_f = 1 + 1/(9z²) + O(z⁻⁴)
    EXPECT_NEAR(rough.factor(0.6e-3), 1.0 + 1.0 / (9.0 * z * z), 1e-10);
    const double limit = 35.0 / 32.0 * (std::log(300.0) - 55.0 / 60.0) / (3.0 * 0.6e-6);
    rough.couette(0.0, c, dc);
    EXPECT_NEAR(c, limit, 1e-5 * limit);
    rough.couette(-0.2e-6, c, dc);  // overlapping surfaces: the contact limit
    EXPECT_NEAR(c, limit, 1e-5 * limit);
    rough.couette(0.03e-6, c, dc);  // the skirt's film floor, 0.05σ
    EXPECT_NEAR(c, limit, 0.02 * limit);
    EXPECT_THROW(ShearStressFactor(-1e-6), std::invalid_argument);
}
