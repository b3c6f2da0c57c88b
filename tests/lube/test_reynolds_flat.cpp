// Flat-pad problems on the film grid: inclined slider (Couette term, second-order convergence,
// non-uniform spacing), squeeze-film time (∂h/∂t term), bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "lube/FilmIntegrals.hpp"
#include "lube/ReynoldsSolver.hpp"
#include "tests/lube/LubeTestSupport.hpp"

using namespace flexehd::lube;

namespace {

// A flat pad: a thin arc (half angle 1e-3 rad) of a cylinder of radius 1 km, so e_r ≈ e_x to
// 2e-7; the circumferential edges are symmetry planes (infinitely wide pad, 1-D in z).
FilmGrid flatPad(std::vector<double> z) {
    const double d = 1e-3;
    FilmGrid g = FilmGrid::arc(1000.0, std::move(z), -d, d, 3);
    g.setEdge(Edge::ArcStart, EdgeCondition::Symmetry);
    g.setEdge(Edge::ArcEnd, EdgeCondition::Symmetry);
    return g;
}
double padWidth(const FilmGrid& g) { return g.radius() * g.angularExtent(); }

// Inclined slider h = h0[1 + K(1 − z/B)], lower surface sliding at U along +z:
// returns W h0²/(μ U B² L).
double sliderLoad(const std::vector<double>& z, SolverKind solver) {
    const double B = 0.02, h0 = 10e-6, K = 1.0, mu = 0.05, U = 5.0;
    ReynoldsOptions opt;
    opt.solver = solver;
    opt.control.tolerance = 1e-11;
    ReynoldsSolver rs(flatPad(z), Lubricant(mu), opt);
    FilmState st;
    st.h.resize(rs.grid().size());
    for (int k = 0; k < rs.grid().size(); ++k)
        st.h[k] = h0 * (1 + K * (1 - rs.grid().z(rs.grid().axialIndex(k)) / B));
    st.inner.axial = U;
    const ReynoldsResult r = rs.solve(st);
    const FilmLoads f = integrateFilm(rs.grid(), st, rs.lubricant(), r.pressure);
    EXPECT_GT(f.maxPressure, 0.0);
    EXPECT_EQ(f.cavitatedArea, 0.0) << "a converging slider has no cavitation";
    return -f.pressureForce.x() * h0 * h0 / (mu * U * B * B * padWidth(rs.grid()));
}

}  // namespace

// Inclined slider (Hamrock, Fundamentals of Fluid Film Lubrication): 6/K²[ln(1+K) − 2K/(2+K)] = 0.15888 at K = 1. The finite-volume error is O(Δz²):
// it must fall by 4 ± 0.5 per halving, and be below 1e-4 relative at 161 nodes.
TEST(InclinedSlider, LoadConvergesAtSecondOrder) {
    const double exact = 6.0 * (std::log(2.0) - 2.0 / 3.0);
    EXPECT_NEAR(exact, 0.15888, 5e-6);
    double prev = 0.0;
    for (int n : {21, 41, 81, 161}) {
        const double err = std::abs(sliderLoad(FilmGrid::uniform(0.0, 0.02, n), SolverKind::ActiveSet) - exact);
        if (prev > 0.0) {
            EXPECT_NEAR(prev / err, 4.0, 0.5) << "n = " << n;
        }
        prev = err;
    }
    EXPECT_LT(prev / exact, 1e-4);
}

// Friction of the inclined slider on both surfaces (h = h0[1 + K(1 − z/B)], the lower surface
// sliding at U, Reynolds' equation integrated in closed form with p(0) = p(B) = 0, h* =
// 2h0(1 + K)/(2 + K)): per width W, on the sliding surface F = −(ηUB/h0)[4 ln(1+K)/K − 6/(2+K)],
// on the stationary one F = (ηUB/h0)[6/(2+K) − 2 ln(1+K)/K] (Hamrock, Fundamentals of Fluid Film
// Lubrication, fixed-incline slider). The stationary surface does no work, so the viscous
// dissipation equals the sliding surface's power −F U.
TEST(InclinedSlider, FrictionOnBothSurfacesAndDissipation) {
    const double B = 0.02, h0 = 10e-6, K = 1.0, mu = 0.05, U = 5.0;
    const double scale = mu * U * B / h0;
    const double inner = -(4.0 * std::log(1.0 + K) / K - 6.0 / (2.0 + K));
    const double outer = 6.0 / (2.0 + K) - 2.0 * std::log(1.0 + K) / K;
    double prevInner = 0.0, prevOuter = 0.0;
    for (int n : {41, 81, 161}) {
        ReynoldsOptions opt;
        opt.control.tolerance = 1e-11;
        ReynoldsSolver rs(flatPad(FilmGrid::uniform(0.0, B, n)), Lubricant(mu), opt);
        FilmState st;
        st.h.resize(rs.grid().size());
        for (int k = 0; k < rs.grid().size(); ++k) st.h[k] = h0 * (1 + K * (1 - rs.grid().z(rs.grid().axialIndex(k)) / B));
        st.inner.axial = U;
        const FilmLoads f = integrateFilm(rs.grid(), st, rs.lubricant(), rs.solve(st).pressure);
        const double W = padWidth(rs.grid());
        const double ei = std::abs(f.shearForce.z() / (scale * W) - inner);
        const double eo = std::abs(f.outerShearForce.z() / (scale * W) - outer);
        if (prevInner > 0.0) {
            EXPECT_GT(prevInner / ei, 3.5) << "sliding surface, n = " << n;
            EXPECT_GT(prevOuter / eo, 3.5) << "stationary surface, n = " << n;
        }
        prevInner = ei;
        prevOuter = eo;
        EXPECT_NEAR(f.dissipatedPower() / (-inner * scale * W * U), 1.0, n == 161 ? 1e-4 : 2e-3) << "n = " << n;
        EXPECT_GT(f.viscousDissipation, 0.0);
    }
    EXPECT_LT(prevInner / std::abs(inner), 1e-4);
    EXPECT_LT(prevOuter / std::abs(outer), 1e-4);
}

// Non-uniform (smoothly graded) axial spacing: still converges to the exact load at 2nd order.
TEST(InclinedSlider, NonUniformAxialSpacing) {
    const double exact = 6.0 * (std::log(2.0) - 2.0 / 3.0);
    auto graded = [](int n) {
        std::vector<double> z = FilmGrid::uniform(0.0, 1.0, n);
        for (double& v : z) v = 0.02 * (v + 0.4 * v * (1 - v));  // spacing ratio 0.6/1.4 end to end
        return z;
    };
    const double e1 = std::abs(sliderLoad(graded(41), SolverKind::ActiveSet) - exact);
    const double e2 = std::abs(sliderLoad(graded(81), SolverKind::Psor) - exact);
    EXPECT_LT(e2 / exact, 5e-4);
    EXPECT_GT(e1 / e2, 3.0);
}

// Squeeze film of a flat pad of width B under a constant load W′ per unit length:
// t = μB³/(2W′)(1/h₁² − 1/h₀²) = 0.4277 s for μ = 0.01 Pa·s, B = 30 mm, W′ = 12.5 kN/m,
// 50 µm → 5 µm (closed form t = μB³/(2W′)(1/h₁² − 1/h₀²)). Transient: RK4 in time on dh/dt, each stage a film solve with the
// ∂h/∂t term (the load is linear in dh/dt: scale a unit-rate solve). Quadrature error of the
// load is O(Δz²) ≈ 1e-4 at 101 nodes, RK4 error far below.
TEST(SqueezeFilm, FlatPadApproachTime) {
    const double mu = 0.01, B = 0.03, Wp = 12500.0, h0 = 50e-6, h1 = 5e-6;
    const double exact = mu * B * B * B / (2 * Wp) * (1 / (h1 * h1) - 1 / (h0 * h0));
    EXPECT_NEAR(exact, 0.4277, 5e-5);
    ReynoldsSolver rs(flatPad(FilmGrid::uniform(0.0, B, 101)), Lubricant(mu));
    const double width = padWidth(rs.grid());
    auto rate = [&](double h) {  // dh/dt such that the film carries W′
        FilmState st;
        st.h = Eigen::VectorXd::Constant(rs.grid().size(), h);
        st.dhdt = Eigen::VectorXd::Constant(rs.grid().size(), -1e-6);
        const ReynoldsResult r = rs.solve(st);
        const double W = -integrateFilm(rs.grid(), st, rs.lubricant(), r.pressure).pressureForce.x();
        return -1e-6 * Wp * width / W;
    };
    double t = 0.0, h = h0;
    const double dt = 1e-3;
    while (true) {
        const double k1 = rate(h), k2 = rate(h + 0.5 * dt * k1), k3 = rate(h + 0.5 * dt * k2),
                     k4 = rate(h + dt * k3);
        const double hn = h + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        if (hn <= h1) {  // final partial step, interpolated in 1/h² (linear in t exactly)
            t += dt * (1 / (h1 * h1) - 1 / (h * h)) / (1 / (hn * hn) - 1 / (h * h));
            break;
        }
        h = hn;
        t += dt;
    }
    EXPECT_NEAR(t, exact, 2e-4 * exact);
    EXPECT_NEAR(t, 0.4277, 1e-4);
}

TEST(BadInput, ClearErrors) {
    EXPECT_THROW(Lubricant(0.0), std::invalid_argument);
    EXPECT_THROW(Lubricant(-1e-3), std::invalid_argument);
    EXPECT_THROW(Lubricant(0.01, 0.0), std::invalid_argument);
    EXPECT_THROW(FilmGrid::fullCircumference(0.05, {0.0, 0.01}, 2), std::invalid_argument);
    EXPECT_THROW(FilmGrid::fullCircumference(0.05, {0.0}, 16), std::invalid_argument);
    EXPECT_THROW(FilmGrid::fullCircumference(0.05, {0.0, 0.0, 0.01}, 16), std::invalid_argument);
    EXPECT_THROW(FilmGrid::fullCircumference(-0.05, {0.0, 0.01}, 16), std::invalid_argument);
    EXPECT_THROW(FilmGrid::arc(0.05, {0.0, 0.01}, 1.0, 0.5, 16), std::invalid_argument);
    // A grid whose every node is prescribed has nothing to solve.
    EXPECT_THROW(ReynoldsSolver(FilmGrid::fullCircumference(0.05, {0.0, 0.01}, 16), Lubricant(0.01)),
                 std::invalid_argument);

    ReynoldsSolver rs(FilmGrid::fullCircumference(0.05, FilmGrid::uniform(0, 0.02, 5), 16),
                      Lubricant(0.01));
    FilmState st;
    st.h = Eigen::VectorXd::Constant(rs.grid().size(), 10e-6);
    st.inner.circumferential = 1.0;
    st.h[7] = -1e-6;
    try {
        rs.solve(st);
        FAIL() << "negative film accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("film thickness"), std::string::npos) << e.what();
    }
    st.h[7] = std::nan("");
    EXPECT_THROW(rs.solve(st), std::invalid_argument);
    st.h = Eigen::VectorXd::Constant(3, 10e-6);
    EXPECT_THROW(rs.solve(st), std::invalid_argument);

    // PSOR that cannot converge in the allowed sweeps reports it instead of returning garbage.
    ReynoldsOptions opt;
    opt.solver = SolverKind::Psor;
    opt.control.maxIterations = 3;
    opt.control.tolerance = 1e-14;
    ReynoldsSolver slow(FilmGrid::fullCircumference(0.05, FilmGrid::uniform(0, 0.02, 11), 64),
                        Lubricant(0.01), opt);
    st.h = Eigen::VectorXd::Constant(slow.grid().size(), 10e-6);
    for (int k = 0; k < st.h.size(); ++k) st.h[k] *= 1 + 0.5 * std::cos(slow.grid().theta(slow.grid().thetaIndex(k)));
    try {
        slow.solve(st);
        FAIL() << "unconverged PSOR accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("not converged after 3"), std::string::npos) << e.what();
    }
}

// Masked (Void) nodes hold ambient pressure and leave the film area; supply nodes hold theirs.
TEST(FilmGridMask, VoidAndSupplyNodes) {
    FilmGrid g = FilmGrid::fullCircumference(0.05, FilmGrid::uniform(0, 0.02, 11), 32);
    const double fullArea = 2 * 3.14159265358979323846 * 0.05 * 0.02;
    double sum = 0.0;
    for (int k = 0; k < g.size(); ++k) sum += g.area(k);
    EXPECT_NEAR(sum, fullArea, 1e-15);
    g.setAmbientPressure(1e5);
    g.voidNode(g.index(5, 8));
    g.fixNode(g.index(5, 24), 3e5);
    EXPECT_EQ(g.kind(g.index(5, 8)), NodeKind::Void);
    EXPECT_EQ(g.kind(g.index(0, 3)), NodeKind::Fixed);
    ReynoldsOptions opt;
    opt.cavitationPressure = 0.9e5;
    ReynoldsSolver rs(g, Lubricant(0.01), opt);
    FilmState st;
    st.h = Eigen::VectorXd::Constant(g.size(), 20e-6);
    const ReynoldsResult r = rs.solve(st);
    EXPECT_DOUBLE_EQ(r.pressure[g.index(5, 8)], 1e5);
    EXPECT_DOUBLE_EQ(r.pressure[g.index(5, 24)], 3e5);
    EXPECT_DOUBLE_EQ(r.pressure[g.index(0, 3)], 0.0) << "open edge at the default edge pressure 0";
    const FilmLoads f = integrateFilm(rs.grid(), st, rs.lubricant(), r.pressure,
                                      {.cavitationPressure = 0.9e5});
    EXPECT_NEAR(f.filmArea, fullArea - g.area(g.index(5, 8)), 1e-15);
}
