// FilmLoadGradient (the load's derivatives with respect to nodal pressure, film thickness and
// contact pressure) against central differences of integrateFilm itself, in random directions:
// a non-periodic arc with a non-uniform axial grid, masked nodes, pressure-dependent viscosity,
// film fraction, contact pressure and boundary friction, and a periodic full circle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "lube/FilmLoadGradient.hpp"
#include "tests/lube/LubeTestSupport.hpp"

using namespace flexehd::lube;
using flexehd::lube::test::kPi;

namespace {

Eigen::Matrix<double, 6, 1> load(const FilmGrid& g, const FilmState& f, const Lubricant& lub,
                                 const Eigen::VectorXd& p, FilmIntegralOptions opt, const Eigen::VectorXd& pc) {
    opt.contactPressure = &pc;
    const FilmLoads L = integrateFilm(g, f, lub, p, opt);
    Eigen::Matrix<double, 6, 1> out;
    out << L.totalForce(), L.moment;
    return out;
}

// max over the six rows of |G δ − FD δ| relative to the largest |FD δ| row of its kind (force, moment).
void expectMatchesDifferences(const FilmGrid& g, const FilmState& f, const Lubricant& lub, const Eigen::VectorXd& p,
                              const FilmIntegralOptions& opt, const Eigen::VectorXd& pc, unsigned seed) {
    const int n = g.size();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::VectorXd dp(n), dh(n), dc(n);
    for (int k = 0; k < n; ++k) {
        dp[k] = 1e5 * u(rng);
        dh[k] = 1e-6 * u(rng);
        dc[k] = 1e4 * u(rng);
    }
    const FilmLoadGradient G = filmLoadGradient(g, f, lub, p, opt);
    const double s = 1e-3;  // of the directions above: δh ≤ 1 nm, δp ≤ 100 Pa (differences: truncation
                            // ~(δh/h)² ≤ 1e-8, round-off of the large pressure load below 1e-9)
    FilmState fp = f, fm = f;
    fp.h += s * dh;
    fm.h -= s * dh;
    const Eigen::Matrix<double, 6, 1> fd =
        (load(g, fp, lub, p + s * dp, opt, pc + s * dc) - load(g, fm, lub, p - s * dp, opt, pc - s * dc)) / (2 * s);
    const Eigen::VectorXd lin = G.change(dp, dh, dc);
    const double fScale = fd.head<3>().cwiseAbs().maxCoeff(), mScale = fd.tail<3>().cwiseAbs().maxCoeff();
    ASSERT_GT(fScale, 0.0);
    ASSERT_GT(mScale, 0.0);
    for (int r = 0; r < 6; ++r)
        EXPECT_NEAR(lin[r], fd[r], 1e-7 * (r < 3 ? fScale : mScale)) << "row " << r;
    // Each kind of direction alone (the parts are separate).
    const Eigen::VectorXd onlyH = G.change(Eigen::MatrixXd(), dh, Eigen::MatrixXd());
    const Eigen::Matrix<double, 6, 1> fdH = (load(g, fp, lub, p, opt, pc) - load(g, fm, lub, p, opt, pc)) / (2 * s);
    for (int r = 0; r < 6; ++r)
        EXPECT_NEAR(onlyH[r], fdH[r], 1e-7 * std::max(fdH.cwiseAbs().maxCoeff(), 1e-30)) << "thickness part, row " << r;
    // Pressure and contact changes on a few nodes only (a starved film's; the product takes their
    // rows alone): the dense products of the gradient's rows.
    Eigen::MatrixXd sparseP = Eigen::MatrixXd::Zero(n, 2), sparseC = Eigen::MatrixXd::Zero(n, 2);
    for (int k = 0; k < n; k += 11) {
        sparseP.row(k) << dp[k], -0.5 * dp[k];
        sparseC.row(k) << dc[k], 2.0 * dc[k];
    }
    const Eigen::MatrixXd few = G.change(sparseP, Eigen::MatrixXd(), sparseC);
    const Eigen::MatrixXd dense = Eigen::MatrixXd(G.pressure) * sparseP + Eigen::MatrixXd(G.contactPressure) * sparseC;
    EXPECT_LE((few - dense).norm(), 1e-13 * dense.norm());
    // The same changes given on their nodes (NodeColumns), with the thickness part: the dense
    // products of every row.
    Eigen::MatrixXd dh2(n, 2);
    dh2 << dh, 0.3 * dh;
    const Eigen::MatrixXd onNodes =
        G.change(NodeColumns::fromDense(sparseP), dh2, NodeColumns::fromDense(sparseC));
    const Eigen::MatrixXd all = dense + Eigen::MatrixXd(G.thickness) * dh2;
    EXPECT_LE((onNodes - all).norm(), 1e-13 * all.norm());
    // And their sum on the union of their nodes.
    NodeColumns shifted = NodeColumns::fromDense(sparseC);
    for (int& k : shifted.nodes) k = std::min(k + 3, n - 1);
    const NodeColumns both = NodeColumns::sum(NodeColumns::fromDense(sparseP), shifted);
    EXPECT_LE((both.dense(n) - (sparseP + shifted.dense(n))).norm(), 1e-15 * sparseP.norm());
    EXPECT_TRUE(std::is_sorted(both.nodes.begin(), both.nodes.end()));
}

}  // namespace

namespace {

// An arc of 21 × 13 nodes (non-uniform axially) with films of 5–45 µm, a pressure peak, contact
// pressure and film fraction, the liner sliding axially and circumferentially.
struct ArcFilm {
    FilmGrid g;
    FilmState f;
    Eigen::VectorXd p, pc, phi;
    ArcFilm(bool masked) : g(grid(masked)) {
        const int n = g.size();
        f.h.resize(n);
        p.resize(n);
        pc.resize(n);
        phi.resize(n);
        for (int k = 0; k < n; ++k) {
            const double th = g.theta(g.thetaIndex(k)), zz = g.z(g.axialIndex(k));
            f.h[k] = 5e-6 + 20e-6 * (1.0 - std::cos(th)) + 0.01 * zz * zz;
            p[k] = 1e5 + 2e6 * std::exp(-th * th * 4.0) * (1.0 + 10.0 * zz);
            pc[k] = 3e5 * std::max(0.0, std::cos(3 * th));
            phi[k] = 0.6 + 0.4 * std::cos(th + 0.3);
        }
        f.inner.axial = 0.5;
        f.outer.axial = -12.0;
        f.outer.circumferential = 0.7;
    }
    static FilmGrid grid(bool masked) {
        std::vector<double> z;
        for (int i = 0; i < 13; ++i) z.push_back(-0.02 + 0.04 * std::pow(i / 12.0, 1.3));  // non-uniform
        FilmGrid g = FilmGrid::arc(0.043, z, -0.7, 0.7, 21);
        g.setAmbientPressure(1e5);
        if (masked) {
            g.voidNode(g.index(6, 10));
            g.voidNode(g.index(0, 3));
        }
        return g;
    }
};

}  // namespace

TEST(FilmLoadGradient, MatchesDifferencesOfTheIntegralsOnAMaskedArc) {
    const ArcFilm a(true);
    FilmIntegralOptions opt;
    opt.referencePoint = Eigen::Vector3d(0.001, 0.0, 0.004);
    opt.boundaryFriction = 0.12;
    opt.filmFraction = &a.phi;
    expectMatchesDifferences(a.g, a.f, Lubricant(0.0086, 820.0).withBarus(1.5e-8), a.p, opt, a.pc, 7u);
}

TEST(FilmLoadGradient, MatchesDifferencesOfTheIntegralsOnAFullCircle) {
    flexehd::lube::test::Journal jb;
    const FilmGrid g = jb.finiteGrid(2 * jb.R, 31, 9);
    FilmState f = jb.state(g);
    const int n = g.size();
    Eigen::VectorXd p(n), pc = Eigen::VectorXd::Zero(n);
    for (int k = 0; k < n; ++k) {
        const double th = g.theta(g.thetaIndex(k)), zz = g.z(g.axialIndex(k)) / jb.R;
        p[k] = std::max(0.0, 1e6 * std::sin(th) * (1.0 - zz * zz));
    }
    FilmIntegralOptions opt;
    expectMatchesDifferences(g, f, Lubricant(0.01, 850.0), p, opt, pc, 11u);
}

TEST(FilmLoadGradient, RejectsAPressureOfTheWrongSize) {
    flexehd::lube::test::Journal jb;
    const FilmGrid g = jb.finiteGrid(2 * jb.R, 8, 4);
    EXPECT_THROW(filmLoadGradient(g, jb.state(g), Lubricant(0.01), Eigen::VectorXd::Zero(3)), std::invalid_argument);
}

// The Couette shear between rough surfaces (ShearStressFactor): over the arc's films of 5–45 µm
// at σ = 3 µm, H = h/σ spans the stress factor's three branches (H ≤ 3, 3 < H ≤ 9, H > 9).
TEST(FilmLoadGradient, MatchesDifferencesOfTheIntegralsWithTheRoughShearFactor) {
    const ArcFilm a(false);
    FilmIntegralOptions opt;
    opt.boundaryFriction = 0.12;
    opt.filmFraction = &a.phi;
    opt.roughness = 3e-6;
    expectMatchesDifferences(a.g, a.f, Lubricant(0.0086, 820.0), a.p, opt, a.pc, 13u);
}
