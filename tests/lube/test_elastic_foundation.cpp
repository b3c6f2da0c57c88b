// lube::ElasticFoundation: the hard contact of a coating below h = 0 (docs/lube.md §5).
//  * The layer stiffness is the uniaxial-strain (constrained) modulus over the thickness. It is
//    checked against the same modulus written from the Lamé constants, λ + 2μ with
//    λ = Eν/((1+ν)(1−2ν)), μ = E/(2(1+ν)) — an independent expression of the bonded layer's law.
//  * The load–interference law of a flat punch of area A pressed δ into the layer, F = K A δ
//    (Winkler: every point of the layer carries K times its own compression), by summing the
//    pressure over a grid of nodes of the punch face.
#include "lube/ElasticFoundation.hpp"

#include <gtest/gtest.h>

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

TEST(ElasticFoundation, RejectsNonPhysicalInput) {
    EXPECT_THROW(ElasticFoundation(0.0), std::invalid_argument);
    EXPECT_THROW(ElasticFoundation(-1.0), std::invalid_argument);
    EXPECT_THROW(ElasticFoundation::layerStiffness(8e9, 0.5, 1e-5), std::invalid_argument);
    EXPECT_THROW(ElasticFoundation::layerStiffness(8e9, 0.3, 0.0), std::invalid_argument);
    EXPECT_THROW(ElasticFoundation::layerStiffness(-1.0, 0.3, 1e-5), std::invalid_argument);
}
