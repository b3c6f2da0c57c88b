// Bearing surfaces that cover only arcs of the grid's circumference (FilmGrid::restrictToArcs,
// docs/lube.md §1): the arc ends sit at their true angle, not at the nearest grid node.
//  * geometry: the covered widths of an arc's columns add up to the arc's length;
//  * order: an inclined slider laid along θ on an arc whose ends fall between nodes converges
//    at second order to its closed-form flow, friction torque, dissipation and load;
//  * smoothness: the film force of a pair of skirt-like panels grows smoothly with their
//    half-width, with no staircase as the ends cross grid nodes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "lube/FilmIntegrals.hpp"
#include "lube/ReynoldsSolver.hpp"
#include "tests/lube/LubeTestSupport.hpp"

using namespace flexehd::lube;
using flexehd::lube::test::kPi;

namespace {

// An infinitely long pad (one axial cell, zero-flux axial edges) on the arc [a, b] of a full
// circumference of radius R with n columns.
FilmGrid padGrid(double R, int n, double a, double b) {
    FilmGrid g = FilmGrid::fullCircumference(R, {0.0, 0.005, 0.01}, n);
    g.setEdge(Edge::AxialLow, EdgeCondition::Symmetry);
    g.setEdge(Edge::AxialHigh, EdgeCondition::Symmetry);
    g.restrictToArcs({{a, b}});
    return g;
}

// Inclined slider along s = R(θ − a): h = h0[1 + K(1 − s/B)], B = R(b − a), the inner surface
// sliding at U in +θ. Closed form of p (Reynolds' equation integrated with p(0) = p(B) = 0):
// p = (6ηUB/(K h0²)) [(−1/(1+K) + H*/(2(1+K)²)) − (−1/H + H*/(2H²))], H = h/h0,
// H* = 2(1+K)/(2+K).
struct ThetaSlider {
    double R = 0.05, a = -0.3017, b = 0.2741, h0 = 10e-6, K = 1.0, mu = 0.05, U = 5.0;
    double B() const { return R * (b - a); }
    double Hstar() const { return 2.0 * (1.0 + K) / (2.0 + K); }
    double H(double theta) const { return 1.0 + K * (1.0 - R * (theta - a) / B()); }
    double pressure(double theta) const {
        const double Hs = Hstar(), h = H(theta);
        return 6.0 * mu * U * B() / (K * h0 * h0) *
               ((-1.0 / (1.0 + K) + Hs / (2.0 * (1.0 + K) * (1.0 + K))) - (-1.0 / h + Hs / (2.0 * h * h)));
    }
    // −∫ p cos θ R dθ per unit length (the x force on the inner body), by Simpson's rule.
    double forceX() const {
        const int m = 20000;
        double sum = 0.0;
        for (int k = 0; k <= m; ++k) {
            const double t = a + (b - a) * k / m;
            sum += (k == 0 || k == m ? 1.0 : k % 2 ? 4.0 : 2.0) * pressure(t) * std::cos(t);
        }
        return -sum * (b - a) / (3.0 * m) * R;
    }
};

struct SliderErrors {
    double flow, torque, dissipation, force;
};

SliderErrors sliderErrors(const ThetaSlider& s, int n) {
    ReynoldsOptions opt;
    opt.control.tolerance = 1e-12;
    ReynoldsSolver rs(padGrid(s.R, n, s.a, s.b), Lubricant(s.mu), opt);
    const FilmGrid& g = rs.grid();
    FilmState st;
    st.h.resize(g.size());
    for (int k = 0; k < g.size(); ++k) st.h[k] = s.h0 * s.H(std::remainder(g.theta(g.thetaIndex(k)), 2 * kPi));
    st.inner.circumferential = s.U;
    const Eigen::VectorXd p = rs.solve(st).pressure;
    const FilmLoads f = integrateFilm(g, st, rs.lubricant(), p);
    const double L = g.length();
    // Flow U h*/2 through every section; friction on the sliding surface
    // −(ηUB/h0)[4 ln(1+K)/K − 6/(2+K)] (InclinedSlider tests), its power U × that.
    const double q = 0.5 * s.U * s.h0 * s.Hstar() * L;
    const double F = -(s.mu * s.U * s.B() / s.h0) * (4.0 * std::log(1.0 + s.K) / s.K - 6.0 / (2.0 + s.K)) * L;
    const int mid = int(std::lround(n * (1.0 - 0.01 / (2 * kPi)))) % n;  // a face inside the pad, θ ≈ −0.01
    SliderErrors e;
    e.flow = std::abs(circumferentialFlow(g, st, rs.lubricant(), p, mid) / q - 1.0);
    e.torque = std::abs(f.moment.z() / (s.R * F) - 1.0);
    e.dissipation = std::abs(f.viscousDissipation / (-F * s.U) - 1.0);
    e.force = std::abs(f.pressureForce.x() / (s.forceX() * L) - 1.0);
    return e;
}

}  // namespace

TEST(FilmArcs, CoveredWidthsAddUpToTheArcLength) {
    for (int n : {96, 97, 250}) {
        const double a = -0.4123, b = 0.3311;
        FilmGrid g = padGrid(0.05, n, a, b);
        double covered = 0.0;
        int columns = 0;
        for (int j = 0; j < n; ++j)
            if (g.kind(g.index(1, j)) != NodeKind::Void) {
                covered += g.coveredAngularWidth(j);
                ++columns;
            }
        EXPECT_NEAR(covered, b - a, 1e-13) << "n = " << n;
        EXPECT_EQ(columns, int(std::floor(b * n / (2 * kPi))) - int(std::ceil(a * n / (2 * kPi))) + 1) << "n = " << n;
    }
}

// Second order with the ends halfway between nodes on every grid (a half cell of the coarsest
// grid stays a half cell when Δθ is divided by 3): the flow, torque and load errors fall by 9
// per refinement, at least 7 here, where ends put half a cell off would leave first order (3).
// The dissipation's error is smaller and changes sign between the first two grids (−4.9e-5,
// +1.2e-6, +4.2e-7, +5.8e-8), so its ratios say nothing; the next test bounds it.
TEST(FilmArcs, InclinedSliderWithEndsBetweenNodesConvergesAtSecondOrder) {
    ThetaSlider s;
    const int n0 = 128;
    const double d0 = 2 * kPi / n0;
    s.a = -12.5 * d0;
    s.b = 11.5 * d0;
    std::vector<SliderErrors> e;
    for (int n : {n0, 3 * n0, 9 * n0, 27 * n0}) {
        e.push_back(sliderErrors(s, n));
        std::printf("  n %4d: flow %.2e, torque %.2e, dissipation %.2e, x force %.2e\n", n, e.back().flow,
                    e.back().torque, e.back().dissipation, e.back().force);
    }
    for (double SliderErrors::*m : {&SliderErrors::flow, &SliderErrors::torque, &SliderErrors::force})
        for (std::size_t k = 1; k < e.size(); ++k) EXPECT_GT(e[k - 1].*m / (e[k].*m), 7.0) << "refinement " << k;
}

// Ends anywhere between nodes (their places relative to the nodes change from grid to grid, so
// the error's constant does too): over three halvings of Δθ the least-squares slope of
// log(error) against log(Δθ) is at least 1.8, and every error ends below 1e-4.
TEST(FilmArcs, InclinedSliderOnAnyArcConvergesAtSecondOrder) {
    const ThetaSlider s;
    std::vector<SliderErrors> e;
    const std::vector<int> grids{256, 512, 1024, 2048};
    for (int n : grids) {
        e.push_back(sliderErrors(s, n));
        std::printf("  n %4d: flow %.2e, torque %.2e, dissipation %.2e, x force %.2e\n", n, e.back().flow,
                    e.back().torque, e.back().dissipation, e.back().force);
    }
    for (double SliderErrors::*m : {&SliderErrors::flow, &SliderErrors::torque, &SliderErrors::dissipation,
                                     &SliderErrors::force}) {
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (std::size_t k = 0; k < e.size(); ++k) {
            const double x = std::log(2 * kPi / grids[k]), y = std::log(e[k].*m);
            sx += x; sy += y; sxx += x * x; sxy += x * y;
        }
        const double m4 = double(e.size());
        const double slope = (m4 * sxy - sx * sy) / (m4 * sxx - sx * sx);
        EXPECT_GT(slope, 1.8);
        EXPECT_LT(e.back().*m, 1e-4);
    }
}

// Two skirt-like panels (thrust θ = 0, antithrust θ = π, half-width α) on a 24 × 72 grid, the
// piston shifted 30 µm towards the thrust side and the liner sliding past at 5 m/s, with
// cavitation: over 35°…45° in steps of 0.25° (Δθ = 5°, so the ends cross two grid nodes) the
// film's lateral force must change smoothly — every step of α changes it by the same sign and,
// step to step, by amounts that differ by less than half their mean (a staircase would change
// it by nothing for most steps and jump at the nodes).
TEST(FilmArcs, PanelForceChangesSmoothlyWithThePanelWidth) {
    const double R = 0.043, c = 50e-6, e = 30e-6;
    std::vector<double> force;
    for (int k = 0; k <= 40; ++k) {
        const double alpha = (35.0 + 0.25 * k) * kPi / 180.0;
        FilmGrid g = FilmGrid::fullCircumference(R, FilmGrid::uniform(-0.025, 0.0108, 24), 72);
        g.restrictToArcs({{-alpha, alpha}, {kPi - alpha, kPi + alpha}});
        ReynoldsOptions opt;
        opt.control.tolerance = 1e-10;
        ReynoldsSolver rs(std::move(g), Lubricant(0.0086), opt);
        const FilmGrid& grid = rs.grid();
        FilmState st;
        st.h.resize(grid.size());
        for (int n = 0; n < grid.size(); ++n) {
            const double z = grid.z(grid.axialIndex(n)), th = grid.theta(grid.thetaIndex(n));
            st.h[n] = c + 0.06 * (z + 0.010) * (z + 0.010) - e * std::cos(th);
        }
        st.outer.axial = -5.0;
        force.push_back(integrateFilm(grid, st, rs.lubricant(), rs.solve(st).pressure).pressureForce.x());
    }
    std::vector<double> step;
    for (std::size_t k = 1; k < force.size(); ++k) step.push_back(force[k] - force[k - 1]);
    double mean = 0.0;
    for (double d : step) mean += d / double(step.size());
    std::printf("  lateral force %.2f N at 35 deg … %.2f N at 45 deg; steps %.4f … mean %.4f N\n", force.front(),
                force.back(), step.front(), mean);
    ASSERT_LT(mean, 0.0) << "a wider thrust panel carries more load (force towards −x)";
    for (std::size_t k = 0; k < step.size(); ++k) {
        EXPECT_LT(step[k], 0.0) << "step " << k;
        if (k > 0) {
            EXPECT_LT(std::abs(step[k] - step[k - 1]), 0.5 * std::abs(mean)) << "step " << k;
        }
    }
}
