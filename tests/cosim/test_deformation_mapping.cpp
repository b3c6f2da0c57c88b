// Deformation mapping (cosim/mapping/DeformationMapping): Clough–Tocher C¹ interpolation of nodal
// fields onto the film grid. Polynomial reproduction, continuity across θ = ±π, convergence.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cosim/mapping/DeformationMapping.hpp"
#include "cosim/mapping/MovingGridMapping.hpp"
#include "fem/MeshReader.hpp"

using namespace flexehd;
using cosim::DeformationMapping;
using lube::FilmGrid;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string sleevePath() { return std::string(FLEXEHD_SOURCE_DIR) + "/tests/cosim/data/sleeve.geo"; }

const fem::Mesh& sleeve(double size) {
    static const fem::Mesh m8 = fem::readMesh(sleevePath(), {2, 0.008});
    if (size == 0.008) return m8;
    static const fem::Mesh m4 = fem::readMesh(sleevePath(), {2, 0.004});
    if (size == 0.004) return m4;
    static const fem::Mesh m2 = fem::readMesh(sleevePath(), {2, 0.002});
    return m2;
}

const fem::Mesh& piston() {
    static const fem::Mesh m =
        fem::readMesh(std::string(FLEXEHD_SOURCE_DIR) + "/meshes/piston.geo", {2, 0.0065});
    return m;
}

template <typename F>
Eigen::VectorXd nodal(const fem::Mesh& m, F f) {
    Eigen::VectorXd v = Eigen::VectorXd::Zero(m.numNodes());
    for (int n = 0; n < m.numNodes(); ++n)
        v(n) = f(m.nodes(2, n), std::atan2(m.nodes(1, n), m.nodes(0, n)));
    return v;
}

template <typename F>
double maxError(const FilmGrid& g, const DeformationMapping& map, const Eigen::VectorXd& u, F f) {
    const Eigen::VectorXd ug = map.scalar() * u;
    std::vector<char> out(static_cast<std::size_t>(g.size()), 0);
    for (int k : map.outsideNodes()) out[static_cast<std::size_t>(k)] = 1;
    double e = 0.0;
    for (int k = 0; k < g.size(); ++k)
        if (!out[static_cast<std::size_t>(k)])
            e = std::max(e, std::abs(ug(k) - f(g.z(g.axialIndex(k)), g.theta(g.thetaIndex(k)))));
    return e;
}

double wrap(double a) { return a - 2.0 * kPi * std::round(a / (2.0 * kPi)); }

}  // namespace

// Quadratics in (z, s = R θ) on the piston skirt panels, one of them across θ = ±π.
TEST(DeformationMapping, ReproducesQuadraticsOnTheSkirtPanels) {
    const fem::Mesh& m = piston();
    const double R = 0.043;
    for (double centre : {0.0, kPi}) {
        auto f = [&](double z, double th) {
            const double s = R * wrap(th - centre);
            return 1e-5 * (1.0 + 30.0 * z - 20.0 * s + 900.0 * z * z + 500.0 * z * s - 700.0 * s * s);
        };
        const FilmGrid g = FilmGrid::arc(R, FilmGrid::uniform(-0.025, 0.0108, 37), centre - 0.69, centre + 0.69, 71);
        const DeformationMapping map(m, "skirt", g);
        EXPECT_TRUE(map.outsideNodes().empty());
        EXPECT_LE(maxError(g, map, nodal(m, f), f), 1e-12 * 1e-5) << "panel at " << centre;
        // A cubic is not reproduced (gradients come from a quadratic fit): the test can fail.
        auto c = [&](double z, double th) { return f(z, th) + 1e-5 * 3e4 * std::pow(R * wrap(th - centre), 3); };
        EXPECT_GT(maxError(g, map, nodal(m, c), c), 1e-11);
    }
}

// Full circumference: quadratics in z and rigid translations (radial operator) exactly.
TEST(DeformationMapping, FullCircumferenceAndRadialComponent) {
    const fem::Mesh& m = sleeve(0.008);
    const FilmGrid g = FilmGrid::fullCircumference(0.043, FilmGrid::uniform(-0.03, 0.02, 26), 90, 0.05);
    const DeformationMapping map(m, "outer", g);
    EXPECT_TRUE(map.outsideNodes().empty());
    auto f = [](double z, double) { return 2e-5 * (1.0 - 30.0 * z + 2000.0 * z * z); };
    EXPECT_LE(maxError(g, map, nodal(m, f), f), 1e-17);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * m.numNodes());
    for (int n = 0; n < m.numNodes(); ++n) u.segment<3>(3 * n) << 1e-5, -2e-5, 7e-6;
    const Eigen::VectorXd ur = map.radial() * u;
    for (int k = 0; k < g.size(); ++k) {
        const double th = g.theta(g.thetaIndex(k));
        ASSERT_NEAR(ur(k), 1e-5 * std::cos(th) - 2e-5 * std::sin(th), 1e-18) << k;
    }
}

// C¹ across θ = ±π (the atan2 seam) and across the triangle edges: on a fine arc through the
// seam the second differences stay bounded (a kink δ in the slope would give δ / h = δ · 1e5).
TEST(DeformationMapping, C1AcrossTheSeamAndTheEdges) {
    const fem::Mesh& m = sleeve(0.008);
    auto f = [](double z, double th) { return 0.78 + std::cos(3.0 * (z + th)) + 50.0 * z * std::sin(th); };
    const double h = 1e-5, a = kPi - 0.3, b = kPi + 0.3;
    const int n = static_cast<int>(std::lround((b - a) / h)) + 1;
    const FilmGrid g = FilmGrid::arc(0.043, {-0.011, -0.01}, a, b, n);
    const DeformationMapping map(m, "outer", g);
    EXPECT_TRUE(map.outsideNodes().empty());
    const Eigen::VectorXd v = map.scalar() * nodal(m, f);
    double d2max = 0.0, seamJump = 0.0;
    for (int j = 1; j + 1 < n; ++j) {
        const double d2 = std::abs(v(j + 1) - 2.0 * v(j) + v(j - 1)) / (h * h);
        d2max = std::max(d2max, d2);
        if (std::abs(g.theta(j) - kPi) < 1.5 * h) seamJump = std::max(seamJump, d2);
    }
    std::printf("  max |f''| of the interpolant over [pi-0.3, pi+0.3]: %.2f (exact field: <= 9.6); at the seam %.2f\n",
                d2max, seamJump);
    EXPECT_LE(d2max, 1e3);
    EXPECT_NEAR(v(g.index(0, (n - 1) / 2)), f(-0.011, kPi), 1e-2);  // value at the seam
}

// Convergence on 0.78 + cos(10 (z + θ)) under mesh refinement (sizes 8, 4, 2 mm).
TEST(DeformationMapping, ConvergenceOrder) {
    auto f = [](double z, double th) { return 0.78 + std::cos(10.0 * (z + th)); };
    const FilmGrid g = FilmGrid::fullCircumference(0.043, FilmGrid::uniform(-0.0299, 0.0199, 41), 360);
    double prev = 0.0;
    for (double size : {0.008, 0.004, 0.002}) {
        const fem::Mesh& m = sleeve(size);
        const DeformationMapping map(m, "outer", g);
        const double e = maxError(g, map, nodal(m, f), f);
        if (prev > 0.0) {
            const double order = std::log2(prev / e);
            std::printf("  size %.3f m: max error %.3e, order %.2f\n", size, e, order);
            EXPECT_GT(order, 2.5);
        } else {
            std::printf("  size %.3f m: max error %.3e\n", size, e);
        }
        prev = e;
    }
}

TEST(DeformationMapping, DegenerateInputs) {
    const fem::Mesh& m = sleeve(0.008);
    const FilmGrid away = FilmGrid::fullCircumference(0.043, FilmGrid::uniform(0.1, 0.2, 5), 16);
    EXPECT_THAT([&] { DeformationMapping(m, "outer", away); },
                ::testing::ThrowsMessage<std::invalid_argument>(::testing::HasSubstr("surface 'outer'")));
    const FilmGrid g = FilmGrid::fullCircumference(0.043, FilmGrid::uniform(-0.02, 0.01, 5), 16);
    EXPECT_THAT([&] { DeformationMapping(m, "ends", g); },
                ::testing::ThrowsMessage<std::invalid_argument>(::testing::HasSubstr("not a cylinder")));
    // Grid longer than the sleeve: the rows beyond its ends are outside (empty).
    const FilmGrid longer = FilmGrid::fullCircumference(0.043, FilmGrid::uniform(-0.04, 0.03, 8), 16);
    const DeformationMapping map(m, "outer", longer);
    EXPECT_EQ(map.outsideNodes().size(), 2u * 16u);  // rows z = -0.04 and 0.03
}

// Liner with a moving grid (cosim/mapping/MovingGridMapping): bore-fixed Clough–Tocher rows, cubic
// Hermite in z to the shifted rows. u = (g(z), 0, 0) with g quadratic is reproduced exactly
// (u_r = g(z + s) cos θ); a smooth field agrees with the operator rebuilt at each offset.
TEST(MovingGridMapping, LinerDeformationAtAnyOffset) {
    const fem::Mesh& m = sleeve(0.008);
    std::vector<double> z;
    for (int i = 0; i <= 24; ++i) z.push_back(-0.006 + 0.012 * std::pow(i / 24.0, 1.2));
    const FilmGrid g = FilmGrid::fullCircumference(0.040, z, 72, 0.1);
    const cosim::MovingGridMapping map(m, "inner", g, -0.030, 0.020, 101);
    auto quad = [](double zz) { return 1e-5 * (1.0 - 30.0 * zz + 2000.0 * zz * zz); };
    Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * m.numNodes()), w = u;
    for (int n = 0; n < m.numNodes(); ++n) {
        const double zz = m.nodes(2, n), th = std::atan2(m.nodes(1, n), m.nodes(0, n));
        u(3 * n) = quad(zz);
        w(3 * n) = 1e-5 * std::cos(60.0 * zz + th);
        w(3 * n + 1) = 1e-5 * std::sin(40.0 * zz - 2.0 * th);
    }
    for (double offset : {0.0, 0.00123, -0.0171, 0.0139, -0.024, 0.014}) {
        const Eigen::VectorXd ur = map.radialDisplacement(u, offset);
        double e = 0.0;
        for (int k = 0; k < g.size(); ++k)
            e = std::max(e, std::abs(ur(k) - quad(g.z(g.axialIndex(k)) + offset) * std::cos(g.theta(g.thetaIndex(k)))));
        EXPECT_LE(e, 1e-12 * 1e-5) << "offset " << offset;
        const Eigen::VectorXd direct = DeformationMapping(m, "inner", g, offset).radial() * w;
        const double d = (map.radialDisplacement(w, offset) - direct).cwiseAbs().maxCoeff() / 1e-5;
        std::printf("  offset %+.5f m: quadratic max error %.1e m, smooth field vs rebuilt %.1e (relative)\n",
                    offset, e, d);
        EXPECT_LE(d, 5e-4);
    }
    EXPECT_THROW((void)map.radialDisplacement(u, -0.0245), std::out_of_range);
}
