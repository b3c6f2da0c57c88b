// A ring's radial equilibrium (docs/ring-pack.md): under a constant load and no contact the
// parabolic face squeezes its film out as the closed form of the squeeze film says; with the
// Greenwood–Tripp asperities, no gas and no sliding, the film settles to the gap where the
// asperities alone carry the tension (the root of the asperity law, found independently).
#include "cosim/ringpack/RingAxialMotion.hpp"
#include "cosim/ringpack/RingRadialMotion.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

using namespace flexehd;
using namespace flexehd::cosim;

// Squeeze under a constant load W′ of the infinite parabola of vertex radius R: ḣ = −W′ h^1.5 /
// (3√2 π η R^1.5), so h^−1/2 grows linearly: h^−1/2 = h0^−1/2 + W′ t/(6√2 π η R^1.5).
TEST(RingRadialMotion, ConstantLoadSqueezesTheFilmOutAsTheClosedForm) {
    const double h0 = 1e-6, R = 0.02, eta = 0.01, W = 300.0;
    const double half = 40.0 * std::sqrt(2.0 * R * h0);  // ±40 √(2R h0): ±80 at h0/4
    const lube::RingFaceProfile face = lube::RingFaceProfile::barrel(2.0 * half, half * half / (2.0 * R));
    const double rate = W / (6.0 * std::sqrt(2.0) * std::numbers::pi * eta * std::pow(R, 1.5));
    const double tEnd = (1.0 / std::sqrt(0.25 * h0) - 1.0 / std::sqrt(h0)) / rate;  // to h0/4
    std::vector<double> growth;
    for (int N : {50, 100, 200}) {
        const RingRadialMotion ring(lube::RingFilm(face, lube::Lubricant(eta), 1601), std::nullopt, W);
        double h = h0;
        for (int s = 0; s < N; ++s) h = ring.step(h, tEnd / N, lube::RingFilmState{}, 0.0).minimumGap;
        growth.push_back((1.0 / std::sqrt(h) - 1.0 / std::sqrt(h0)) / (rate * tEnd));
        std::printf("N %d: h(t) %.5g m (closed form %.5g), growth of h^-1/2 / closed form %.5f\n", N, h, 0.25 * h0,
                    growth.back());
    }
    // Backward Euler: first order in Δt (successive differences halve); the limit within the film's
    // spatial error of the closed form (RingFilm's squeeze test: 1.2e-3 to 4e-3 at the face's
    // ΔX = 0.05 at h0 to 0.1 at h0/4, in units of √(2R h)).
    const double ratio = (growth[0] - growth[1]) / (growth[1] - growth[2]);
    std::printf("difference ratio %.3f\n", ratio);
    EXPECT_NEAR(ratio, 2.0, 0.2);
    const double extrapolated = 2.0 * growth[2] - growth[1];
    EXPECT_NEAR(extrapolated, 1.0, 3e-3);
}

TEST(RingRadialMotion, WithoutGasAndSlidingTheFilmSettlesOnTheAsperities) {
    const lube::RingFaceProfile face = lube::RingFaceProfile::barrel(1.5e-3, 5e-6, 0.1e-3);
    const lube::GreenwoodTripp asperity(0.3e-6, 0.6e-3, 1.111e8, 49.1e9);
    const double T = 150.0;  // N/m: 0.1 MPa elastic pressure over the 1.5 mm face
    const RingRadialMotion ring(lube::RingFilm(face, lube::Lubricant(0.01), 301), asperity, T);
    double h = 3e-6;
    RingRadialStep s;
    for (int k = 0; k < 400; ++k) {
        s = ring.step(h, 1e-2, lube::RingFilmState{}, 0.0);
        h = s.minimumGap;
    }
    // The gap where the asperity law alone carries T: bisection on Simpson's rule of p_c over the face.
    auto carried = [&](double g) {
        const int n = 4000;
        const double dx = (face.upper() - face.lower()) / n;
        double w = 0.0;
        for (int i = 0; i <= n; ++i)
            w += (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0)) * asperity.pressure(g + face.drop(face.lower() + i * dx));
        return w * dx / 3.0;
    };
    double lo = 1e-9, hi = 3e-6;
    for (int it = 0; it < 100; ++it) (carried(0.5 * (lo + hi)) > T ? lo : hi) = 0.5 * (lo + hi);
    const double hStar = 0.5 * (lo + hi);
    std::printf("settled gap %.6g m (asperity balance %.6g m), film load %.3g N/m, squeeze %.3g m/s\n", h, hStar,
                s.filmLoad, s.squeezeRate);
    EXPECT_LT(s.filmLoad, 1e-6 * T);
    EXPECT_NEAR(h / hStar, 1.0, 1e-5);
}

// The asperity load from its table against Simpson's rule of the Greenwood–Tripp pressure over
// the face, between the table's nodes, from mean planes 2σ apart into each other to 8σ apart.
TEST(RingRadialMotion, TheAsperityLoadTableFollowsTheLaw) {
    const lube::RingFaceProfile face = lube::RingFaceProfile::barrel(1.5e-3, 5e-6, 0.1e-3);
    const lube::GreenwoodTripp law(0.3e-6, 0.6e-3, 1.111e8, 49.1e9);
    const RingRadialMotion ring(lube::RingFilm(face, lube::Lubricant(0.01), 51), law, 150.0);
    double worst = 0.0;
    for (double lambda = -1.996; lambda < 6.0; lambda += 0.0731) {
        const double h = lambda * 0.3e-6;
        const int n = 4000;
        const double dx = (face.upper() - face.lower()) / n;
        double w = 0.0;
        for (int i = 0; i <= n; ++i)
            w += (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0)) * law.pressure(h + face.drop(face.lower() + i * dx));
        w *= dx / 3.0;
        worst = std::max(worst, std::abs(ring.asperityLoad(h) / w - 1.0));
    }
    std::printf("largest relative difference of the tabulated asperity load %.3g\n", worst);
    EXPECT_LT(worst, 1e-4);
}

TEST(RingRadialMotion, BadInputIsNamed) {
    const lube::RingFaceProfile face = lube::RingFaceProfile::barrel(1.5e-3, 5e-6);
    EXPECT_THROW(RingRadialMotion(lube::RingFilm(face, lube::Lubricant(0.01), 51), std::nullopt, -1.0),
                 std::invalid_argument);
    const RingRadialMotion ring(lube::RingFilm(face, lube::Lubricant(0.01), 51), std::nullopt, 100.0);
    EXPECT_THROW(ring.step(0.0, 1e-3, lube::RingFilmState{}, 0.0), std::invalid_argument);
    // With asperities the mean planes may overlap (a gap below zero), but the gap must be a number.
    const RingRadialMotion rough(lube::RingFilm(face, lube::Lubricant(0.01), 51),
                                 lube::GreenwoodTripp(0.3e-6, 0.6e-3, 1.111e8, 49.1e9), 100.0);
    EXPECT_THROW(rough.step(std::nan(""), 1e-3, lube::RingFilmState{}, 0.0), std::invalid_argument);
    EXPECT_THROW(rough.step(1e-6, 0.0, lube::RingFilmState{}, 0.0), std::invalid_argument);
}

// The ring's travel across its groove under a constant lifting force from rest on the lower flank:
// z = F t²/(2m), so it reaches the upper flank at t = √(2 m c / F); the semi-implicit step is first
// order in Δt. Pressed on a flank, the flank carries the force; it lifts when the force turns.
TEST(RingAxialMotion, CrossesTheGrooveInTheFreeFlightTimeAndRestsOnTheFlanks) {
    const double m = 0.04, c = 40e-6, F = 2.0;  // kg/m (a 1.5 x 3.5 mm steel ring), m, N/m
    const double tCross = std::sqrt(2.0 * m * c / F);
    std::vector<double> err;
    for (int N : {100, 200, 400}) {
        RingAxialMotion ring(m, c);
        const double dt = 2.0 * tCross / (N + 0.37);  // the crossing between steps
        double arrival = -1.0;
        for (int s = 1; s <= N; ++s) {
            ring.step(dt, F);
            if (arrival < 0.0 && ring.onUpperFlank()) arrival = s * dt;
        }
        ASSERT_GT(arrival, 0.0);
        err.push_back(std::abs(arrival / tCross - 1.0));
        EXPECT_DOUBLE_EQ(ring.flankForce(), -F);  // the upper flank holds it
        std::printf("N %d: arrival %.6g s (free flight %.6g s), error %.3g\n", N, arrival, tCross, err.back());
    }
    for (double e : err) EXPECT_GT(e, 0.0);
    EXPECT_LT(err.back(), 2.0 * 2.0 / 400);  // within two steps of the free-flight time
    for (std::size_t k = 1; k < err.size(); ++k) EXPECT_NEAR(std::log2(err[k - 1] / err[k]), 1.0, 0.2);
    RingAxialMotion ring(m, c);
    ring.step(1e-4, -5.0);
    EXPECT_TRUE(ring.onLowerFlank());
    EXPECT_DOUBLE_EQ(ring.flankForce(), 5.0);
    ring.step(1e-4, 5.0);
    EXPECT_FALSE(ring.onLowerFlank());
    EXPECT_GT(ring.velocity(), 0.0);
    EXPECT_THROW(RingAxialMotion(0.0, c), std::invalid_argument);
}
