// lube::ElasticFoundation: the hard contact of a coating below h = 0 (docs/lube.md §5).
//  * The layer stiffness is the uniaxial-strain (constrained) modulus over the thickness. It is
//    checked against the same modulus written from the Lamé constants, λ + 2μ with
//    λ = Eν/((1+ν)(1−2ν)), μ = E/(2(1+ν)) — an independent expression of the bonded layer's law.
//  * The load–interference law of a flat punch of area A pressed δ into the layer, F = K A δ
//    (Winkler: every point of the layer carries K times its own compression), by summing the
//    pressure over a grid of nodes of the punch face.
//  * The damped layer (Hunt & Crossley 1975; Lankarani & Nikravesh 1990): a punch of mass m
//    striking the layer at v₀ leaves it at e v₀, for any m, area, stiffness and v₀ — the
//    definition of the coefficient of restitution — integrated here by the symplectic Euler
//    method in small steps (an integrator independent of the factor's own Runge–Kutta solve);
//    as e → 1 the factor tends to Lankarani & Nikravesh's (3/4)(1 − e²), the energy a linear
//    spring's half-sine impact loses to the damping term; its slope equals central differences.
#include "lube/ElasticFoundation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

using flexehd::lube::ElasticFoundation;

TEST(ElasticFoundation, LayerStiffnessIsTheConstrainedModulusOverTheThickness) {
    for (const double nu : {0.0, 0.25, 0.3, 0.45}) {
        const double E = 8e9, t = 15e-6;
        const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
        EXPECT_NEAR(ElasticFoundation::layerStiffness(E, nu, t), (lambda + 2 * mu) / t, 1e-12 * (lambda + 2 * mu) / t)
            << "nu = " << nu;
    }
    // ν = 0: no lateral constraint effect, K = E / t.
    EXPECT_DOUBLE_EQ(ElasticFoundation::layerStiffness(8e9, 0.0, 1e-5), 8e14);
}

TEST(ElasticFoundation, PressureIsLinearInTheInterferenceAndZeroWithoutIt) {
    const double K = ElasticFoundation::layerStiffness(8e9, 0.3, 15e-6);
    const ElasticFoundation f(K);
    const int n = 20;
    const double side = 5e-3, area = side * side / (n * n);  // 5 mm square punch, n × n nodes
    for (const double delta : {1e-9, 0.2e-6, 1e-6}) {
        double F = 0.0;
        for (int i = 0; i < n * n; ++i) F += f.pressure(-delta) * area;
        EXPECT_NEAR(F, K * side * side * delta, 1e-12 * K * side * side * delta) << "delta = " << delta;
        EXPECT_DOUBLE_EQ(f.pressureSlope(-delta), -K);
    }
    EXPECT_EQ(f.pressure(0.0), 0.0);
    EXPECT_EQ(f.pressure(1e-6), 0.0);
    EXPECT_EQ(f.pressureSlope(1e-6), 0.0);
}

namespace {

// A punch of mass m (kg) and face area A (m²) striking the layer at v0 (m/s): its rebound speed
// (m/s). The film thickness is the punch's height above the layer's surface, h = −δ.
double reboundOfAPunch(const ElasticFoundation& f, double m, double A, double v0) {
    const double omega = std::sqrt(f.stiffness() * A / m);  // undamped contact frequency
    const double dt = 2e-5 * M_PI / omega;
    double h = 0.0, v = -v0, impact = 0.0;  // v = ḣ
    for (int n = 0; n < 1'000'000; ++n) {
        const double approach = -v;
        impact = std::max(impact, approach);
        v += f.pressure(h, approach, impact) * A / m * dt;
        h += v * dt;
        if (h >= 0.0) return v;
    }
    return std::nan("");
}

}  // namespace

TEST(ElasticFoundation, AnImpactOnTheDampedLayerReboundsAtTheStatedRestitution) {
    const double K = ElasticFoundation::layerStiffness(8e9, 0.3, 15e-6);
    for (const double e : {0.2, 0.5, 0.8, 0.95}) {
        const ElasticFoundation f(K, e);
        for (const double m : {0.05, 0.4})
            for (const double v0 : {1e-3, 0.1, 2.0}) {
                const double A = 1e-4;
                EXPECT_NEAR(reboundOfAPunch(f, m, A, v0) / v0, e, 2e-3) << "e = " << e << ", m = " << m << ", v0 = " << v0;
            }
    }
    // Elastic: all the energy comes back.
    EXPECT_NEAR(reboundOfAPunch(ElasticFoundation(K), 0.4, 1e-4, 0.5) / 0.5, 1.0, 1e-3);
}

TEST(ElasticFoundation, DampingFactorTendsToLankaraniNikraveshNearAnElasticImpact) {
    EXPECT_EQ(ElasticFoundation::hysteresisFactor(1.0), 0.0);
    for (const double e : {0.99, 0.999}) {
        const double ln = 0.75 * (1.0 - e * e);
        EXPECT_NEAR(ElasticFoundation::hysteresisFactor(e) / ln, 1.0, 2.0 * (1.0 - e)) << "e = " << e;
    }
    // Farther from 1 the factor grows faster than (3/4)(1 − e²) (its estimate from the elastic
    // half-sine under-counts the damping): monotone in e.
    double last = 0.0;
    for (const double e : {0.95, 0.8, 0.6, 0.4, 0.2}) {
        const double chi = ElasticFoundation::hysteresisFactor(e);
        EXPECT_GT(chi, 0.75 * (1.0 - e * e)) << "e = " << e;
        EXPECT_GT(chi, last) << "e = " << e;
        last = chi;
    }
}

TEST(ElasticFoundation, DampedSlopeEqualsDifferences) {
    const double K = ElasticFoundation::layerStiffness(8e9, 0.3, 15e-6);
    const ElasticFoundation f(K, 0.6);
    const double dt = 1e-5, h0 = -0.3e-6, hOld = -0.1e-6, impact = 0.05;
    // Backward Euler: the approach −ḣ = −(h − h_old)/Δt (here 0.02 m/s, below the impact speed).
    const auto approach = [&](double h) { return -(h - hOld) / dt; };
    const auto p = [&](double h) { return f.pressure(h, approach(h), impact); };
    const double dh = 1e-12;
    const double fd = (p(h0 + dh) - p(h0 - dh)) / (2 * dh);
    EXPECT_NEAR(f.pressureSlope(h0, approach(h0), impact, 1.0 / dt), fd, 1e-6 * std::abs(fd));
    // Rebounding fast enough the damping cancels the elastic pressure: no adhesion.
    EXPECT_EQ(f.pressure(h0, -10.0, impact), 0.0);
    EXPECT_EQ(f.pressureSlope(h0, -10.0, impact, 1.0 / dt), 0.0);
}

TEST(ElasticFoundation, RejectsNonPhysicalInput) {
    EXPECT_THROW(ElasticFoundation(0.0), std::invalid_argument);
    EXPECT_THROW(ElasticFoundation(-1.0), std::invalid_argument);
    EXPECT_THROW(ElasticFoundation(1e14, 0.0), std::invalid_argument);
    EXPECT_THROW(ElasticFoundation(1e14, 1.2), std::invalid_argument);
    EXPECT_THROW(ElasticFoundation::layerStiffness(8e9, 0.5, 1e-5), std::invalid_argument);
    EXPECT_THROW(ElasticFoundation::layerStiffness(8e9, 0.3, 0.0), std::invalid_argument);
    EXPECT_THROW(ElasticFoundation::layerStiffness(-1.0, 0.3, 1e-5), std::invalid_argument);
}
