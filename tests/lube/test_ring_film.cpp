// The ring-face film (RingFilm) against closed forms: the steady parabolic face, fully flooded,
// with the Reynolds exit condition (Martin; Hamrock, Fundamentals of Fluid Film Lubrication:
// w' = 4.896 η u_m R / h0, rupture at x/√(2R h0) = 0.475 past the minimum, u_m = U/2 with the
// ring at rest) with the measured order of convergence; the pure squeeze of the same face
// (W' = 3√2 π η V R^1.5 / h0^1.5 for an approach speed V, full film); the face fed by a liner
// oil layer (starved, mass-conserving) against its meniscus solution and against JfoSolver on a
// grid of three θ columns across the face; a gas pushing an oil slug off the face against the
// slug's Poiseuille flow with the measured order; a gas blowing through a partial face against the
// characteristics of its oil streaks' conservation law with the measured order; and the face
// profiles.
#include <gtest/gtest.h>
#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "lube/FilmGrid.hpp"
#include "lube/JfoSolver.hpp"
#include "lube/RingFilm.hpp"

using namespace flexehd::lube;

namespace {

// A barrel face with vertex radius R standing for the infinite parabola: it spans
// X = x/√(2R h0) from −inlet to +outlet about its vertex. The inlet's truncation lowers the
// Martin load by 0.6 % at X = −20 (the pressure builds up far upstream; quadrature of the
// one-dimensional equation), by 0.03 % at −200; the squeeze load's tails beyond |X| = 20 are
// 5e-5 of it.
struct Face {
    double h0 = 1e-6, R = 0.02, eta = 0.01;
    double scale() const { return std::sqrt(2.0 * R * h0); }
    RingFaceProfile profile(double inlet, double outlet) const {
        const double b = (inlet + outlet) * scale(), half = 0.5 * b;
        // The vertex's offset from the face's centre puts it inlet·scale above the lower edge.
        return RingFaceProfile::barrel(b, half * half / (2.0 * R), inlet * scale() - half);
    }
};

// Nodes for a spacing ΔX across a face of the given span (in units of √(2R h0)).
int nodesFor(double span, double dX) { return static_cast<int>(std::lround(span / dX)) + 1; }

}  // namespace

// The one-dimensional parabola's pressure, in units of 12 η u_m √(2R h0)/h0², integrated from a
// film start at X0 (p = 0) to X1 by the trapezoidal rule in N steps: p(X1) and, in *load, the load
// 24 ∫ p dX in units of η u_m R / h0 (dp/dX ∝ (H − H_e)/H³, H = 1 + X²).
double parabolaPressure(double X0, double X1, double He, int N, double* load) {
    auto F = [&](double X) { const double H = 1.0 + X * X; return (H - He) / (H * H * H); };
    const double dX = (X1 - X0) / N;
    double p = 0.0, I = 0.0, f0 = F(X0);
    for (int i = 0; i < N; ++i) {
        const double f1 = F(X0 + (i + 1) * dX), pn = p + 0.5 * (f0 + f1) * dX;
        I += 0.5 * (p + pn) * dX;
        p = pn;
        f0 = f1;
    }
    if (load) *load = 24.0 * I;
    return p;
}

// The continuum load w' / (η u_m R / h0) and the rupture X_e of the parabola with its flooded inlet
// at X = −inlet, by a second method: the one-dimensional equation dp/dX ∝ (H − H_e)/H³,
// H = 1 + X², integrated by the trapezoidal rule from the inlet (p = 0) and shot in X_e until
// p(X_e) = 0 (then also dp/dX = 0: the Reynolds condition); w' = 24 ∫∫ (H − H_e)/H³.
std::pair<double, double> martinByQuadrature(double inlet) {
    auto shoot = [&](double Xe, int N, double* load) { return parabolaPressure(-inlet, Xe, 1.0 + Xe * Xe, N, load); };
    double lo = 0.3, hi = 0.6;
    for (int it = 0; it < 60; ++it) (shoot(0.5 * (lo + hi), 200000, nullptr) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
    double load = 0.0;
    shoot(0.5 * (lo + hi), 2000000, &load);
    return {load, 0.5 * (lo + hi)};
}

TEST(RingFilm, SteadyParabolicFaceMatchesMartinWithItsOrder) {
    const Face f;
    const double U = 10.0, unit = f.eta * (0.5 * U) * f.R / f.h0;  // η u_m R / h0
    const auto [reference, Xe] = martinByQuadrature(200.0);
    std::printf("quadrature: load %.6f, rupture %.5f (Martin 4.896, 0.475)\n", reference, Xe);
    EXPECT_NEAR(reference, 4.896, 2e-3);  // the inlet's truncation (0.03 %) and the constant's rounding
    EXPECT_NEAR(Xe, 0.475, 1e-3);
    const RingFaceProfile face = f.profile(200.0, 20.0);
    const double vertex = face.lower() + 200.0 * f.scale();
    std::vector<double> error;
    for (double dX : {0.1, 0.05, 0.025, 0.0125}) {
        const RingFilm film(face, Lubricant(f.eta), nodesFor(220.0, dX));
        RingFilmState s;
        s.minimumGap = f.h0;
        s.slidingSpeed = U;
        const RingFilmResult r = film.solve(s);
        int i = 0;
        while (r.x[i] < vertex) ++i;
        while (i + 1 < r.x.size() && r.p[i + 1] > 0.0) ++i;  // the last node with pressure past the minimum
        const double last = (r.x[i] - vertex) / f.scale();
        error.push_back(std::abs(r.load / unit / reference - 1.0));
        std::printf("dX %.4f: load %.6f (reference %.6f), error %.3g; last pressurised node X = %.4f\n", dX,
                    r.load / unit, reference, error.back(), last);
        // The free boundary lies in the cell after the last pressurised node, to the grid's first order.
        EXPECT_LE(std::abs(last + 0.5 * dX - Xe), dX);
    }
    // The free boundary's place within a cell makes the error's decrease uneven from grid to grid;
    // over the four grids it falls at second order (a free boundary alone would allow first).
    const double order = std::log2(error.front() / error.back()) / 3.0;
    std::printf("mean order of the load over the four grids %.2f\n", order);
    EXPECT_GE(order, 1.8);
    EXPECT_LT(error.back(), 1e-3);
}

TEST(RingFilm, PureSqueezeOfTheParabolicFaceMatchesTheClosedForm) {
    const Face f;
    const double V = 1e-3;  // approach speed (m/s)
    const double W = 3.0 * std::sqrt(2.0) * std::numbers::pi * f.eta * V * std::pow(f.R, 1.5) / std::pow(f.h0, 1.5);
    std::vector<double> load;
    for (double d : {0.1, 0.05, 0.025}) {
        const RingFilm film(f.profile(20.0, 20.0), Lubricant(f.eta), nodesFor(40.0, d));
        RingFilmState s;
        s.minimumGap = f.h0;
        s.squeezeRate = -V;
        const RingFilmResult r = film.solve(s);
        load.push_back(r.load);
        EXPECT_NEAR(r.friction, 0.0, 1e-9 * W) << "a symmetric squeeze film has no net shear";
        std::printf("dX %.3f: squeeze load %.6g N/m (closed form %.6g), error %.3g\n", d, r.load, W,
                    std::abs(r.load / W - 1.0));
    }
    const double order = std::log2(std::abs(load[0] - load[1]) / std::abs(load[1] - load[2]));
    std::printf("order of the load (successive differences) %.2f\n", order);
    EXPECT_GE(order, 1.8);
    // Second order: the finest grid's error is a third of the last difference, plus the tails.
    EXPECT_LT(std::abs(load.back() / W - 1.0), std::abs(load[1] - load[2]) / W + 1e-4);
}

// The parabolic face fed by a liner oil layer t (starved, mass-conserving): in the full film
// dp/dX ∝ (H − H_e)/H³ with H_e = 2t/h0 (the flux U t carried by the film at the Reynolds exit,
// where H = H_e), from the inlet meniscus X_m (p = 0) where the partial film ahead, φ h = 2t,
// becomes full. X_m from ∫_{X_m}^{X_e} (H − H_e)/H³ dX = 0 and the load 24 ∫∫ (units η u_m R/h0)
// by bisection and the trapezoidal rule (a second method); the film's meniscus and load must
// converge to them, the load at second order and the meniscus within a cell.
TEST(RingFilm, StarvedParabolicFaceMatchesTheMeniscusSolution) {
    const Face f;
    const double U = 10.0, t = 0.55e-6, He = 2.0 * t / f.h0, Xe = std::sqrt(He - 1.0);  // 2t below the flooded film's 1.226 h0
    // p(X_e) for a meniscus at X_m, and the load.
    auto closes = [&](double Xm, double* load) { return parabolaPressure(Xm, Xe, He, 400000, load); };
    double lo = -10.0, hi = -Xe;
    for (int it = 0; it < 60; ++it) (closes(0.5 * (lo + hi), nullptr) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
    const double Xm = 0.5 * (lo + hi);
    double reference = 0.0;
    closes(Xm, &reference);
    std::printf("meniscus solution: X_m %.5f, X_e %.5f, load %.6f (eta u_m R / h0)\n", Xm, Xe, reference);
    const double unit = f.eta * (0.5 * U) * f.R / f.h0;
    const RingFaceProfile face = f.profile(20.0, 20.0);
    const double vertex = face.lower() + 20.0 * f.scale();
    std::vector<double> error;
    for (double dX : {0.1, 0.05, 0.025, 0.0125}) {
        const RingFilm film(face, Lubricant(f.eta), nodesFor(40.0, dX));
        RingFilmState s;
        s.minimumGap = f.h0;
        s.slidingSpeed = U;
        s.supplyFilm = t;
        const RingFilmResult r = film.solve(s);
        int i = 0;
        while (r.fraction[i] < 1.0 || i == 0) ++i;  // the first full-film node from the inlet
        const double front = (0.5 * (r.x[i - 1] + r.x[i]) - vertex) / f.scale();
        error.push_back(std::abs(r.load / unit / reference - 1.0));
        std::printf("dX %.3f: load %.6f, error %.3g; meniscus at X = %.4f (%.4f)\n", dX, r.load / unit, error.back(),
                    front, Xm);
        EXPECT_LE(std::abs(front - Xm), dX);
    }
    const double order = std::log2(error.front() / error.back()) / 3.0;
    std::printf("mean order of the load %.2f\n", order);
    EXPECT_GE(order, 1.8);
    EXPECT_LT(error.back(), 2e-3);
}

// Steps of the mass-conserving film (backward Euler of its content) through a sliding reversal
// and a squeeze cycle on a 0.4 µm layer: each step's change of the film's oil is Δt × the inflow
// at its edges (the active set: to round-off).
TEST(RingFilm, StarvedStepsConserveTheFilmsOil) {
    const RingFaceProfile face = RingFaceProfile::barrel(1.5e-3, 5e-6, 0.1e-3);
    const RingFilm film(face, Lubricant(0.01), 301);
    const double T = 0.01, dt = T / 200;
    Eigen::VectorXd phi = Eigen::VectorXd::Ones(301);
    double oil = -1.0, worst = 0.0, scale = 0.0, minPhi = 1.0;
    for (int k = 1; k <= 200; ++k) {
        const double t = k * dt, w = 2.0 * std::numbers::pi / T;
        RingFilmState s;
        auto gap = [&](double tt) { return 1e-6 * (1.5 + 0.5 * std::cos(w * tt)); };
        s.minimumGap = gap(t);
        s.squeezeRate = (gap(t) - gap(t - dt)) / dt;  // the step's: the face's last gap is h_min − Δt ḣ_min
        s.slidingSpeed = 10.0 * std::sin(w * t);
        s.supplyFilm = 0.4e-6;
        const RingFilmResult r = film.step(s, dt, phi);
        if (oil >= 0.0) {
            worst = std::max(worst, std::abs((r.oil - oil) - dt * r.inflow));
            scale = std::max(scale, std::abs(dt * r.inflow));
        }
        oil = r.oil;
        phi = r.fraction;
        minPhi = std::min(minPhi, phi.minCoeff());
    }
    std::printf("worst step imbalance %.3g of the largest step flow %.3g m^2; smallest film fraction %.3f\n",
                worst / scale, scale, minPhi);
    EXPECT_LT(minPhi, 0.5) << "the film must be starved";
    EXPECT_LT(worst, 1e-10 * scale);
}

// Flooded (the layer thicker than the gap) and closing without sliding, the film stays full: its
// backward-Euler content term is the squeeze term, and the step is the Reynolds-condition film.
TEST(RingFilm, FloodedClosingStepIsTheReynoldsFilm) {
    const RingFaceProfile face = RingFaceProfile::barrel(1.5e-3, 5e-6);
    const RingFilm film(face, Lubricant(0.01), 201);
    RingFilmState s;
    s.minimumGap = 1e-6;
    s.squeezeRate = -1e-3;
    const RingFilmResult reynolds = film.solve(s);
    s.supplyFilm = 1e-3;
    const RingFilmResult jfo = film.step(s, 1e-5, Eigen::VectorXd::Ones(201));
    EXPECT_GT(reynolds.p.minCoeff(), -1e-9);
    EXPECT_LT((jfo.p - reynolds.p).cwiseAbs().maxCoeff(), 1e-9 * reynolds.p.maxCoeff());
    EXPECT_NEAR(jfo.load, reynolds.load, 1e-9 * reynolds.load);
}

// A warm start of the cavitated set (a near one, or a wrong one) leads to the same film as a
// cold start: the discrete complementarity problem has one solution.
TEST(RingFilm, TheCavitatedSetsWarmStartGivesTheSameFilm) {
    const RingFilm film(RingFaceProfile::barrel(1.15e-3, 8e-6), Lubricant(0.01), 101);
    RingFilmState s;
    s.minimumGap = 0.5e-6;
    s.slidingSpeed = 8.0;
    s.pressureAbove = 2e5;
    const RingFilmResult cold = film.solve(s);
    std::vector<char> near;
    RingFilmState other = s;
    other.minimumGap = 0.55e-6;
    film.solve(other, &near);  // the set of a nearby film
    std::vector<char> wrong(101, 1);  // every node held
    for (std::vector<char>* start : {&near, &wrong}) {
        const RingFilmResult warm = film.solve(s, start);
        EXPECT_LE((warm.p - cold.p).cwiseAbs().maxCoeff(), 1e-9 * cold.p.cwiseAbs().maxCoeff());
        EXPECT_NEAR(warm.load, cold.load, 1e-12 * cold.load);
        EXPECT_NEAR(warm.friction, cold.friction, 1e-12 * std::abs(cold.friction));
        int held = 0;
        for (int i = 0; i < 101; ++i) held += (*start)[static_cast<std::size_t>(i)];
        EXPECT_GT(held, 0);  // the film cavitates past its rupture
        for (int i = 1; i + 1 < 101; ++i)
            EXPECT_EQ((*start)[static_cast<std::size_t>(i)] != 0, cold.p[i] <= 0.0) << i;
    }
}

// The Couette shear between rough surfaces (Patir & Cheng's factor, docs/lube.md §5) on a flat
// face, where the film carries no pressure: the friction per unit circumference is η U b φ_f(H)/h
// at the nominal gap, whatever floor the film is solved at, and where the mean planes overlap
// the factor's limit at h → 0. (The cavitation pressure below the edges' keeps the parallel
// film whole: at p = p_cav the Reynolds condition counts a film cavitated.)
TEST(RingFilm, TheRoughCouetteShearFollowsTheNominalGapNotTheFloor) {
    const double b = 1e-3, sigma = 0.4e-6, eta = 0.01, U = 5.0, pcav = -0.5e5;
    const RingFilm film(RingFaceProfile::table({{-0.5 * b, 0.0}, {0.5 * b, 0.0}}), Lubricant(eta), 21, pcav, sigma);
    auto friction = [&](double nominal, double floor) {
        RingFilmState s;
        s.minimumGap = floor;
        s.nominalGap = nominal;
        s.slidingSpeed = U;
        return film.solve(s).friction;
    };
    for (double H : {0.5, 1.5, 4.0}) {
        double phi = 0.0, slope = 0.0;
        ShearStressFactor::ofFilmParameter(H, phi, slope);
        const double expected = eta * U * b * phi / (H * sigma);
        EXPECT_NEAR(friction(H * sigma, 0.05 * sigma), expected, 1e-8 * expected) << H;
        EXPECT_NEAR(friction(H * sigma, 0.2 * sigma), expected, 1e-8 * expected) << H;
    }
    double phi = 0.0, slope = 0.0;
    ShearStressFactor::ofFilmParameter(1e-7, phi, slope);
    const double touching = eta * U * b * phi / (1e-7 * sigma);
    EXPECT_NEAR(friction(-0.3 * sigma, 0.05 * sigma), touching, 1e-4 * touching);
    // Smooth surfaces: η U b / h.
    const RingFilm smooth(RingFaceProfile::table({{-0.5 * b, 0.0}, {0.5 * b, 0.0}}), Lubricant(eta), 21, pcav);
    RingFilmState s;
    s.minimumGap = 1e-6;
    s.slidingSpeed = U;
    EXPECT_NEAR(smooth.solve(s).friction, eta * U * b / 1e-6, 1e-12 * eta * U * b / 1e-6);
}

TEST(RingFilm, FaceProfilesAndBadInput) {
    const RingFaceProfile barrel = RingFaceProfile::barrel(1.5e-3, 6e-6, 0.15e-3);
    EXPECT_DOUBLE_EQ(barrel.drop(0.15e-3), 0.0);
    EXPECT_NEAR(barrel.drop(-0.75e-3), 6e-6 * std::pow(0.9e-3 / 0.75e-3, 2), 1e-18);
    EXPECT_NEAR(barrel.barrelRadius(), 0.75e-3 * 0.75e-3 / 12e-6, 1e-12);
    const RingFaceProfile table = RingFaceProfile::table({{-1e-3, 5e-6}, {0.0, 1e-6}, {1e-3, 3e-6}});
    EXPECT_NEAR(table.drop(0.0), 0.0, 1e-18);
    EXPECT_NEAR(table.drop(0.5e-3), 1e-6, 1e-18);
    EXPECT_NEAR(table.drop(-0.5e-3), 2e-6, 1e-18);
    using ::testing::HasSubstr;
    using ::testing::ThrowsMessage;
    EXPECT_THAT([] { RingFaceProfile::barrel(1e-3, 5e-6, 0.6e-3); },
                ThrowsMessage<std::invalid_argument>(HasSubstr("inside the face")));
    EXPECT_THAT([] { RingFaceProfile::table({{0.0, 1e-6}, {0.0, 2e-6}}); },
                ThrowsMessage<std::invalid_argument>(HasSubstr("increase strictly (row 2)")));
    const RingFilm film(barrel, Lubricant(0.01), 51);
    RingFilmState s;
    EXPECT_THAT([&] { film.solve(s); }, ThrowsMessage<std::invalid_argument>(HasSubstr("minimum gap must be positive")));
    s.minimumGap = 1e-6;
    s.supplyFilm = -1e-6;
    EXPECT_THAT([&] { film.solve(s); }, ThrowsMessage<std::invalid_argument>(HasSubstr("supply film must be >= 0")));
    s.supplyFilm = 1e-6;
    s.squeezeRate = -1e-3;
    EXPECT_THAT([&] { film.solve(s); }, ThrowsMessage<std::invalid_argument>(HasSubstr("squeeze rate must be 0")));
    EXPECT_THAT([&] { film.step(s, 1e-5, Eigen::VectorXd::Ones(7)); },
                ThrowsMessage<std::invalid_argument>(HasSubstr("previous film fraction on the 51 nodes")));
}

namespace {

// The mass-conserving film by JfoSolver's active set on a grid of three θ columns across the
// face (the solution does not depend on θ), per unit circumference: the reference for RingFilm's
// one-dimensional solve of the same scheme. Load by the trapezoidal rule as RingFilm's.
struct JfoReference {
    Eigen::VectorXd p, fraction;
    double oil = 0.0, inflowLow = 0.0, inflowHigh = 0.0, load = 0.0;
};

JfoReference jfoOnThreeColumns(const RingFaceProfile& face, double eta, int n, double pcav, const RingFilmState& s,
                               double dt, const Eigen::VectorXd* previous) {
    constexpr int kColumns = 3;
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, face.lower(), face.upper());
    Eigen::VectorXd h(n);
    for (int i = 0; i < n; ++i) h[i] = s.minimumGap + face.drop(x[i]);
    FilmGrid g = FilmGrid::fullCircumference(1.0, std::vector<double>(x.data(), x.data() + n), kColumns);
    g.setEdge(Edge::AxialLow, EdgeCondition::Pressure, std::max(s.pressureBelow, pcav));
    g.setEdge(Edge::AxialHigh, EdgeCondition::Pressure, std::max(s.pressureAbove, pcav));
    JfoOptions o;
    o.method = JfoMethod::ActiveSet;
    o.cavitationPressure = pcav;
    o.control.tolerance = 1e-12;
    JfoSolver jfo(g, Lubricant(eta), o);
    FilmState f;
    f.h.resize(g.size());
    for (int k = 0; k < g.size(); ++k) f.h[k] = h[g.axialIndex(k)];
    f.outer.axial = s.slidingSpeed;
    const int lead = s.slidingSpeed >= 0.0 ? 0 : n - 1, next = lead == 0 ? 1 : n - 2;
    const double hf = 0.5 * (h[lead] + h[next]);
    for (int j = 0; j < kColumns; ++j) jfo.setInletFraction(g.index(lead, j), std::min(1.0, 2.0 * s.supplyFilm / hf));
    JfoState before;
    if (previous) {
        before.h = f.h.array() - dt * s.squeezeRate;
        before.fraction.resize(g.size());
        for (int k = 0; k < g.size(); ++k) before.fraction[k] = (*previous)[g.axialIndex(k)];
    }
    const JfoResult res = jfo.solve(f, previous ? dt : 0.0, previous ? &before : nullptr);
    JfoReference r;
    r.p.resize(n);
    r.fraction.resize(n);
    for (int i = 0; i < n; ++i) {
        r.p[i] = res.pressure[g.index(i, 0)];
        r.fraction[i] = res.fraction[g.index(i, 0)];
    }
    const double circumference = 2.0 * std::numbers::pi * g.radius();
    r.oil = jfo.oilVolume(f, res.fraction) / circumference;
    for (int j = 0; j < kColumns; ++j) {
        r.inflowLow += res.boundaryFlow[g.index(0, j)] / circumference;
        r.inflowHigh += res.boundaryFlow[g.index(n - 1, j)] / circumference;
    }
    for (int i = 0; i + 1 < n; ++i) r.load += 0.5 * (r.p[i] + r.p[i + 1]) * (x[1] - x[0]);
    return r;
}

// The faces, sliding directions, supplies, edge pressures and cavitation pressures the
// mass-conserving film is compared over; visit(face, film, state, label).
constexpr int kNodes = 101;
template <class Visit>
void forStarvedCases(Visit visit) {
    const std::vector<std::pair<const char*, RingFaceProfile>> faces = {
        {"barrel", RingFaceProfile::barrel(1.2e-3, 8e-6)},
        {"taper", RingFaceProfile::table({{-0.6e-3, 0.0}, {-0.2e-3, 0.0}, {0.6e-3, 5e-6}})}};
    for (const auto& [name, face] : faces)
        for (double pcav : {0.0, -0.3e5}) {
            const RingFilm film(face, Lubricant(0.01), kNodes, pcav);
            for (double U : {8.0, -8.0})
                for (double t : {0.3e-6, 20e-6, 0.0})  // starved, flooding (2t above every gap), dry
                    for (double above : {0.0, 1e5}) {
                        RingFilmState s;
                        s.minimumGap = 1e-6;
                        s.slidingSpeed = U;
                        s.supplyFilm = t;
                        s.pressureAbove = above;
                        char label[160];
                        std::snprintf(label, sizeof label, "%s face, p_cav %g Pa, U %g m/s, supply %g m, p_above %g Pa",
                                      name, pcav, U, t, above);
                        visit(face, pcav, film, s, std::string(label));
                    }
        }
}

// A previous film fraction partly below 1: a partial film towards the lower edge.
Eigen::VectorXd partialFraction(int n) {
    Eigen::VectorXd phi(n);
    for (int i = 0; i < n; ++i) phi[i] = std::min(1.0, 0.2 + 1.6 * i / (n - 1.0));
    return phi;
}

constexpr double kStep = 1e-5, kSqueeze = -2e-3;  // a step (s) and its squeeze rate (m/s)

// The result against the reference, each quantity relative to its scale: the pressure to the
// largest pressure (at least 1 Pa), the flows to the Couette flux (|U|/2) h_max, the oil to the
// full film's.
void expectSameFilm(const RingFilmResult& r, const JfoReference& ref, double U, double tol, const std::string& label,
                    double& worst) {
    const double pScale = std::max(1.0, ref.p.cwiseAbs().maxCoeff());
    const double qScale = 0.5 * std::abs(U) * r.h.maxCoeff();
    const double oilScale = r.h.sum() * (r.x[1] - r.x[0]);
    const double loadScale = pScale * (r.x[r.x.size() - 1] - r.x[0]);
    const double e[] = {(r.p - ref.p).cwiseAbs().maxCoeff() / pScale, (r.fraction - ref.fraction).cwiseAbs().maxCoeff(),
                        std::abs(r.load - ref.load) / loadScale, std::abs(r.oil - ref.oil) / oilScale,
                        std::abs(r.inflowLow - ref.inflowLow) / qScale,
                        std::abs(r.inflowHigh - ref.inflowHigh) / qScale,
                        std::abs(r.inflow - (ref.inflowLow + ref.inflowHigh)) / qScale};
    const char* what[] = {"pressure", "fraction", "load", "oil", "inflow low", "inflow high", "inflow"};
    for (int k = 0; k < 7; ++k) {
        EXPECT_LE(e[k], tol) << what[k] << ", " << label;
        worst = std::max(worst, e[k]);
    }
}

}  // namespace

// RingFilm's one-dimensional mass-conserving solve is JfoSolver's scheme: where the gas on both
// sides is at the cavitation pressure it gives the film of JfoSolver's active set on three θ
// columns across the face, steady and in a step. (Otherwise JfoSolver holds every partial node at
// p_cav, the ring film its partial regions at their side's gas pressure: a case of its own below.)
TEST(RingFilm, MassConservingFilmEqualsJfoSolverOnTheFace) {
    double worstSteady = 0.0, worstStep = 0.0;
    int cases = 0;
    forStarvedCases([&](const RingFaceProfile& face, double pcav, const RingFilm& film, RingFilmState s,
                        const std::string& label) {
        if (pcav != 0.0 || s.pressureAbove != 0.0) return;
        const int n = kNodes;
        expectSameFilm(film.solve(s), jfoOnThreeColumns(face, 0.01, n, pcav, s, 0.0, nullptr), s.slidingSpeed, 1e-9,
                       "steady, " + label, worstSteady);
        s.squeezeRate = kSqueeze;
        const Eigen::VectorXd before = partialFraction(n);
        expectSameFilm(film.step(s, kStep, before), jfoOnThreeColumns(face, 0.01, n, pcav, s, kStep, &before),
                       s.slidingSpeed, 1e-9, "step, " + label, worstStep);
        ++cases;
    });
    std::printf("%d cases: largest relative difference steady %.3g, step %.3g\n", cases, worstSteady, worstStep);
}

// A step's change of the film's oil is the step times the inflow at the two edges, to round-off:
// oil − oil_n = Δt (q_low + q_high), oil_n = ∫ φₙ hₙ dx on the same nodes, hₙ = h − Δt ḣ.
TEST(RingFilm, MassConservingStepBalancesTheOilWithTheEdgesInflow) {
    double worst = 0.0;
    forStarvedCases([&](const RingFaceProfile&, double, const RingFilm& film, RingFilmState s,
                        const std::string& label) {
        s.squeezeRate = kSqueeze;
        const int n = kNodes;
        const Eigen::VectorXd before = partialFraction(n);
        const RingFilmResult r = film.step(s, kStep, before);
        double oilBefore = 0.0;
        for (int i = 1; i + 1 < n; ++i)
            oilBefore += 0.5 * (r.x[i + 1] - r.x[i - 1]) * before[i] * (r.h[i] - kStep * s.squeezeRate);
        const double scale = std::max(r.oil, kStep * 0.5 * std::abs(s.slidingSpeed) * r.h.maxCoeff());
        const double imbalance = std::abs((r.oil - oilBefore) - kStep * (r.inflowLow + r.inflowHigh)) / scale;
        EXPECT_LE(imbalance, 1e-13) << label;
        EXPECT_DOUBLE_EQ(r.inflow, r.inflowLow + r.inflowHigh) << label;
        worst = std::max(worst, imbalance);
    });
    std::printf("largest step imbalance %.3g of the film's oil\n", worst);
}

// The partition of a nearby step, or a wrong one (every node cavitated), as the start gives the
// same mass-conserving film as a cold start, and returns the same partition; a start of the
// wrong size is ignored.
TEST(RingFilm, MassConservingWarmStartGivesTheSameFilm) {
    const RingFilm film(RingFaceProfile::barrel(1.2e-3, 8e-6), Lubricant(0.01), 101);
    RingFilmState s;
    s.minimumGap = 1e-6;
    s.slidingSpeed = 8.0;
    s.supplyFilm = 1.5e-6;
    s.pressureAbove = 1e5;
    auto expectSame = [](const RingFilmResult& a, const RingFilmResult& b) {
        EXPECT_LE((a.p - b.p).cwiseAbs().maxCoeff(), 1e-12 * b.p.cwiseAbs().maxCoeff());
        EXPECT_LE((a.fraction - b.fraction).cwiseAbs().maxCoeff(), 1e-12);
        EXPECT_NEAR(a.load, b.load, 1e-12 * b.load);
        EXPECT_NEAR(a.oil, b.oil, 1e-12 * b.oil);
        EXPECT_NEAR(a.inflow, b.inflow, 1e-12 * std::abs(b.inflowLow));
        EXPECT_NEAR(a.friction, b.friction, 1e-12 * std::abs(b.friction));
    };
    // Steady.
    std::vector<char> coldSet;
    const RingFilmResult cold = film.solve(s, &coldSet);
    RingFilmState other = s;
    other.minimumGap = 1.1e-6;
    std::vector<char> near, wrong(101, 1), sized(7, 1);
    film.solve(other, &near);
    for (std::vector<char>* start : {&near, &wrong, &sized}) {
        expectSame(film.solve(s, start), cold);
        EXPECT_EQ(*start, coldSet);
    }
    int held = 0;
    for (char c : coldSet) held += c;
    EXPECT_GT(held, 10) << "the starved film is partial over much of the face";
    // A step.
    s.squeezeRate = kSqueeze;
    other.squeezeRate = kSqueeze;
    const Eigen::VectorXd before = cold.fraction;
    std::vector<char> coldStep;
    const RingFilmResult stepCold = film.step(s, kStep, before, &coldStep);
    expectSame(film.step(s, kStep, before), stepCold);
    std::vector<char> nearStep, wrongStep(101, 1);
    film.step(other, kStep, before, &nearStep);
    for (std::vector<char>* start : {&nearStep, &wrongStep}) {
        expectSame(film.step(s, kStep, before, start), stepCold);
        EXPECT_EQ(*start, coldStep);
    }
}

// The partial regions of a starved face hold the gas of the side they open to (Jeng 1992): with
// the gas on both sides at P, the film is the one with the gas at 0, every pressure raised by P
// (p_cav below both) — its fractions and flows the same.
TEST(RingFilm, MassConservingFilmIsTheSameOnAnyCommonGasPressure) {
    const RingFilm film(RingFaceProfile::barrel(1.2e-3, 8e-6), Lubricant(0.01), kNodes, -0.3e5);
    const RingFilm zero(RingFaceProfile::barrel(1.2e-3, 8e-6), Lubricant(0.01), kNodes, 0.0);
    for (double U : {8.0, -8.0})
        for (double t : {0.3e-6, 1.5e-6, 20e-6}) {
            RingFilmState s;
            s.minimumGap = 1e-6;
            s.slidingSpeed = U;
            s.supplyFilm = t;
            s.squeezeRate = kSqueeze;
            const Eigen::VectorXd before = partialFraction(kNodes);
            const RingFilmResult a = zero.step(s, kStep, before);
            s.pressureAbove = s.pressureBelow = 2e5;
            const RingFilmResult b = film.step(s, kStep, before);
            const double width = a.x[kNodes - 1] - a.x[0];
            EXPECT_LE((b.p.array() - 2e5 - a.p.array()).abs().maxCoeff(), 1e-9 * a.p.maxCoeff()) << U << " " << t;
            EXPECT_LE((b.fraction - a.fraction).cwiseAbs().maxCoeff(), 1e-12) << U << " " << t;
            EXPECT_NEAR(b.load, a.load + 2e5 * width, 1e-9 * b.load) << U << " " << t;
            EXPECT_NEAR(b.inflowLow, a.inflowLow, 1e-9 * std::abs(a.inflowLow) + 1e-18) << U << " " << t;
            EXPECT_NEAR(b.inflowHigh, a.inflowHigh, 1e-9 * std::abs(a.inflowHigh) + 1e-18) << U << " " << t;
        }
}

// The gas above a starved face is no oil: where the film ruptures towards the upper edge (the
// liner moving up past the ring, the upper edge trailing), the partial film there is at the
// gas's pressure, and the steady film lets out through that edge just the layer's flux U t it
// took in at the lower one, whatever the gas pressure.
TEST(RingFilm, GasAboveAStarvedFaceDrivesNoOilIn) {
    const RingFilm film(RingFaceProfile::barrel(1.2e-3, 8e-6), Lubricant(0.01), kNodes);
    for (double above : {0.0, 1e5, 2e6}) {
        RingFilmState s;
        s.minimumGap = 1e-6;
        s.slidingSpeed = 8.0;
        s.supplyFilm = 0.3e-6;
        s.pressureAbove = above;
        const RingFilmResult r = film.solve(s);
        EXPECT_NEAR(r.inflowLow, s.slidingSpeed * s.supplyFilm, 1e-12 * s.slidingSpeed * s.supplyFilm) << above;
        EXPECT_NEAR(r.inflowHigh, -r.inflowLow, 1e-12 * r.inflowLow) << above;
        EXPECT_NEAR(r.p[kNodes - 2], above, 1e-12 * std::max(1.0, above)) << "the partial film at the gas's pressure";
    }
}

// A barrel face standing 20 µm off a 1 µm layer: no node fills (h > 2t everywhere), so the film
// carries the layer's oil by its Couette flow alone (φ h = 2t, the pressure at cavitation) and the
// gap the oil leaves open to the gas is h − 2t across the face (docs/ring-pack.md, "Gas past a face
// on the oil layer"): its resistance ∫ dx/(h − 2t)³ by a fine midpoint rule, its narrowest height
// h_min − 2t. On a 12 µm layer the oil fills the gap about the minimum, and a flooded film
// everywhere: no path.
TEST(RingFilm, TheGapAFaceLeavesOpenToTheGasIsItsHeightLessItsOil) {
    const RingFaceProfile face = RingFaceProfile::barrel(1.2e-3, 8e-6, 0.1e-3);
    const RingFilm film(face, Lubricant(0.01), 201);
    const double h0 = 20e-6, t = 1e-6;
    RingFilmState s;
    s.minimumGap = h0;
    s.slidingSpeed = 8.0;
    s.supplyFilm = t;
    const OpenGap g = openGap(film.solve(s));
    const int N = 200000;
    const double dx = (face.upper() - face.lower()) / N;
    double integral = 0.0;
    for (int k = 0; k < N; ++k) integral += dx / std::pow(h0 + face.drop(face.lower() + (k + 0.5) * dx) - 2.0 * t, 3);
    std::printf("open gap: resistance %.6e (closed form %.6e) 1/m^2, narrowest %.6e m\n", g.resistance, integral,
                g.narrowest);
    // The scheme's upwind transport keeps φh within 0.3 % of 2t across the face (above it upstream,
    // below downstream; measured 4.3e-5 on the integral with the trapezoid's own error).
    EXPECT_NEAR(g.resistance / integral, 1.0, 2e-4);
    // The node nearest the vertex is up to a spacing off it (its drop), φh there within 0.1 % of 2t.
    const double spacing = (face.upper() - face.lower()) / 200;
    EXPECT_NEAR(g.narrowest, h0 - 2.0 * t, face.drop(0.1e-3 + spacing) + 1e-3 * 2.0 * t);
    s.supplyFilm = 12e-6;
    EXPECT_TRUE(std::isinf(openGap(film.solve(s)).resistance));
    s.supplyFilm = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(std::isinf(openGap(film.solve(s)).resistance));
}

// A step whose full nodes at the face's narrowest gap stand below the higher gas next to them (the
// top ring of the example engine's pack on a 0.3 µm layer at full load, moving down at 3.95 m/s
// with 4.35 bar of gas above it and the crankcase's below; the state taken from such a run):
// ruptured to that gas they would over-fill as partial nodes, and a partition that let them
// rupture alternated. Pushed by the gas instead, the step settles, and its oil balances with the
// edges' inflow as every step's does; its partial nodes keep their oil, and its full nodes hold
// pressures between the two gases'.
TEST(RingFilm, AFilmBelowTheHigherGasAtItsMeniscusIsPushedNotRuptured) {
    const RingFilm film(RingFaceProfile::barrel(1.15e-3, 8e-6, 0.0), Lubricant(0.0086, 820.0), 101, 0.0, 0.6e-6);
    RingFilmState s;
    s.minimumGap = s.nominalGap = 3.8006176219327308e-07;
    s.slidingSpeed = -3.9502225352495612;
    s.squeezeRate = 0.00037797907796130616;
    s.pressureBelow = 0.0;
    s.pressureAbove = 434820.95055419276;
    s.supplyFilm = 2.8798861536693486e-07;
    const double dt = 8.3333333333333344e-05;
    const Eigen::VectorXd before = (Eigen::VectorXd(101) <<
        1, 0.041382674395254684, 0.043035982425296, 0.04478945860784047, 0.046651208081635705,
        0.048630154219864913, 0.050736137302515243, 0.052980026955276302, 0.055373850518024362, 0.057930939878690337,
        0.060666099749276711, 0.063595800882572967, 0.066738402345401904, 0.070114407693910724, 0.073746760757669172,
        0.077661187753372177, 0.08188659363842625, 0.086455522002403945, 0.091404689400691436, 0.096775606873286499,
        0.10261530346212697, 0.10897716881560057, 0.11592193437577379, 0.12351881503096689, 0.13184683520354964,
        0.14099636464212553, 0.15107088887863512, 0.16218903605087251, 0.17448687341888994, 0.18812046999740165,
        0.20326869093896169, 0.22013613639935209, 0.23895605011952031, 0.25999288235168766, 0.28354397134612636,
        0.3099394705318419, 0.33953914729359619, 0.37272396025333271, 0.40987934183797459, 0.4513658800708501,
        0.49747175653454601, 0.54834030814973866, 0.60386644682616197, 0.66355924241522424, 0.72637749583806466,
        0.79056341642291983, 0.85352672256956019, 0.91185993050073211, 0.96157471735580258, 0.99860913291409448,
        1, 1, 1, 0.99663787715471797, 0.92814785045190995,
        0.8735670050664619, 0.81362211472852553, 0.7517534764777094, 0.69062577348005005, 0.63209096425733424,
        0.57728791873813623, 0.52679865332672438, 0.48080773191053083, 0.43923811219676662, 0.40185517974243201,
        0.36834063138570028, 0.33834182582607958, 0.31150287452996178, 0.28748294531986063, 0.26596602457777302,
        0.24666520963547586, 0.22932364975062483, 0.21371354444407054, 0.19963410715004715, 0.18690906144180788,
        0.17538401172358492, 0.16492388467351704, 0.15541054575960969, 0.14674063850136029, 0.13882366033375296,
        0.13158026963170563, 0.12494080821969812, 0.11884401899726592, 0.11323593690468692, 0.1080689319154688,
        0.1033008841927706, 0.098894473450052922, 0.094816566595425741, 0.09103768973482039, 0.087531572466743243,
        0.084274754077751049, 0.081246242730251508, 0.078427220027103783, 0.07580078445425012, 0.073351728160642699,
        0.071066342352751347, 0.068932247277141867, 0.066938243355680341, 0.065074180539323276, 0.063330843371043694,
        0.061699849608311312).finished();
    RingFilmResult r;
    ASSERT_NO_THROW(r = film.step(s, dt, before));
    const int n = 101;
    double oilBefore = 0.0;
    for (int i = 1; i + 1 < n; ++i) oilBefore += 0.5 * (r.x[i + 1] - r.x[i - 1]) * before[i] * (r.h[i] - dt * s.squeezeRate);
    const double flow = dt * (std::abs(r.inflowLow) + std::abs(r.inflowHigh));
    const double imbalance = std::abs((r.oil - oilBefore) - dt * r.inflow);
    int full = 0, belowUpperGas = 0;
    for (int i = 1; i + 1 < n; ++i) {
        EXPECT_GE(r.fraction[i], 0.0) << i;
        EXPECT_LE(r.fraction[i], 1.0) << i;
        if (r.fraction[i] < 1.0) continue;
        ++full;
        EXPECT_GE(r.p[i], s.pressureBelow) << i;
        EXPECT_LE(r.p[i], s.pressureAbove) << i;
        belowUpperGas += r.p[i] < s.pressureAbove;
    }
    std::printf("full nodes %d (%d below the upper gas's pressure); oil %.4g -> %.4g m^2, step imbalance %.3g of %.3g m^2 through the edges\n",
                full, belowUpperGas, oilBefore, r.oil, imbalance, flow);
    EXPECT_GT(belowUpperGas, 0) << "the state must be one the partition's plain update alternates on";
    EXPECT_LT(imbalance, 1e-12 * std::max(flow, r.oil));
}

// A flat face of width b, and its state h off the liner at rest with a gas of dp above it and none
// below, on no oil layer: the gas tests' set-up.
namespace {

RingFaceProfile flatFace(double b) { return RingFaceProfile::table({{-0.5 * b, 0.0}, {0.5 * b, 0.0}}); }

RingFilmState underGas(double h, double dp) {
    RingFilmState s;
    s.minimumGap = h;
    s.pressureAbove = dp;
    s.supplyFilm = 0.0;
    s.withFriction = false;
    return s;
}

}  // namespace

// The gas displacing the oil (docs/lube.md §9): a flat face, the liner at rest, its lower half
// full of oil and its upper half empty, 1 bar of gas above it and none below. The gas pushes the
// slug out through the lower edge as its Poiseuille flow says, Q = h³ Δp/(12 η L) per unit
// circumference with L the slug's length, so dL/dt = −Q/h and L² = L0² − h² Δp t/(6 η). The
// steps (backward Euler, Δt ∝ Δx) keep each step's oil to round-off, every fraction within [0, 1],
// and follow the closed form to first order in the grid: the meniscus lies within the node whose
// oil the gas drains, the slug's pressure reaching the gas's at that node's centre.
TEST(RingFilm, AGasAboveAnOilSlugPushesItOutAsItsPoiseuilleFlowSays) {
    const double b = 1e-3, h = 10e-6, eta = 0.0086, dp = 1e5;
    const double L0 = 0.5 * b, tEmpty = 6.0 * eta * L0 * L0 / (h * h * dp);
    double coarser = 0.0;
    for (const int n : {101, 201, 401}) {
        const RingFilm film(flatFace(b), Lubricant(eta), n);
        const RingFilmState s = underGas(h, dp);
        Eigen::VectorXd phi(n);
        for (int i = 0; i < n; ++i) phi[i] = i < (n - 1) / 2 ? 1.0 : i == (n - 1) / 2 ? 0.5 : 0.0;
        const double dx = b / (n - 1);
        double oil = 0.0;
        for (int i = 1; i + 1 < n; ++i) oil += dx * phi[i] * h;
        const double start = oil / h;
        const int steps = 40 * n;
        const double dt = 0.75 * tEmpty / steps;
        double worst = 0.0, imbalance = 0.0;
        for (int k = 1; k <= steps; ++k) {
            const RingFilmResult r = film.step(s, dt, phi);
            imbalance = std::max(imbalance, std::abs(r.oil - oil - dt * r.inflow) / (dt * std::abs(r.inflow)));
            EXPECT_GE(r.fraction.minCoeff(), 0.0);
            EXPECT_LE(r.fraction.maxCoeff(), 1.0);
            phi = r.fraction;
            oil = r.oil;
            const double L = std::sqrt(start * start - h * h * dp * k * dt / (6.0 * eta));
            worst = std::max(worst, std::abs(oil / h - L) / L0);
        }
        std::printf("%d nodes, %d steps: slug length within %.3g of L0 of the closed form, step imbalance %.2g of its "
                    "flow%s\n",
                    n, steps, worst, imbalance,
                    coarser > 0.0 ? (" (" + std::to_string(coarser / worst) + "x closer)").c_str() : "");
        EXPECT_LT(imbalance, 1e-9);
        if (coarser > 0.0) {
            EXPECT_GT(coarser / worst, 1.8) << n;  // first order: 2 per halving
        }
        coarser = worst;
    }
    EXPECT_LT(coarser, 2.5e-3);
}

// A face partial from edge to edge between two gases is open to them (docs/lube.md §9): the gas
// flows through the gap the oil leaves, its pressure falling along the channel's resistance
// ∫ dx/h_o³, h_o = (1 − φ) h, and pushes the oil streaks with the Poiseuille flow of that gradient.
// A flat face, the liner at rest, a uniform fraction φ0 and 1 bar of gas above, none below: the
// streaks' flux is λ(t) f(φ) with f = φ/(1 − φ)³ and λ = Δp/(12 η R(t)), R = ∫ dx/h_o³ over the
// face, so that h φ_t + λ ∂f/∂ξ = 0 (ξ down from the upper edge). Its solution by characteristics
// (Whitham, Linear and Nonlinear Waves, 1974, ch. 2) is a fan from the upper edge, which the gas
// brings no oil: in τ = ∫ λ/h dt, φ = 0 for ξ < τ f'(0) = τ, f'(φ) = ξ/τ in the fan, φ0 ahead of
// it; τ(t) integrated here by RK4, R and the oil over that profile by Simpson's rule in φ. The steps
// (backward Euler, Δt ∝ Δx) follow its oil to first order in the grid, each to round-off.
TEST(RingFilm, AGasThroughAPartialFaceDrainsItsOilStreaksAsTheirCharacteristicsSay) {
    const double b = 1e-3, h = 10e-6, eta = 0.0086, dp = 1e5, phi0 = 0.5;
    auto slope = [](double phi) { return (1.0 + 2.0 * phi) / std::pow(1.0 - phi, 4); };  // f'(φ)
    // ∫ g(φ) dξ over the face: the emptied length, the fan in φ (ξ = τ f'(φ), dξ = τ f''(φ) dφ,
    // f'' = 6 (1 + φ)/(1 − φ)⁵; Simpson's rule), the plateau φ0 ahead of it.
    auto overFace = [&](auto g, double tau) {
        if (tau * slope(0.0) >= b) return b * g(0.0);
        double head = phi0;  // the fan's φ at the lower edge once its head has left the face
        if (tau * slope(phi0) > b) {
            double lo = 0.0, hi = phi0;
            for (int k = 0; k < 60; ++k) (slope(0.5 * (lo + hi)) < b / tau ? lo : hi) = 0.5 * (lo + hi);
            head = 0.5 * (lo + hi);
        }
        const int N = 400;
        double fan = 0.0;
        for (int i = 0; i <= N; ++i) {
            const double phi = head * i / N;
            fan += (i == 0 || i == N ? 1.0 : i % 2 ? 4.0 : 2.0) * g(phi) * 6.0 * (1.0 + phi) / std::pow(1.0 - phi, 5);
        }
        return tau * g(0.0) + tau * fan * head / N / 3.0 + std::max(0.0, b - tau * slope(phi0)) * g(phi0);
    };
    auto rate = [&](double tau) {  // dτ/dt = Δp/(12 η h R)
        return dp / (12.0 * eta * h * overFace([&](double phi) { return 1.0 / std::pow((1.0 - phi) * h, 3); }, tau));
    };
    const int samples = 200;
    const double tEnd = 6.0 * eta * b * b / (h * h * dp), dT = tEnd / samples;
    std::vector<double> lost(samples + 1, 0.0);  // the oil the face lost by each sample (m²)
    double tau = 0.0;
    const double start = h * overFace([](double phi) { return phi; }, 0.0);
    for (int k = 1; k <= samples; ++k) {
        const double k1 = rate(tau), k2 = rate(tau + 0.5 * dT * k1), k3 = rate(tau + 0.5 * dT * k2),
                     k4 = rate(tau + dT * k3);
        tau += dT / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        lost[static_cast<std::size_t>(k)] = start - h * overFace([](double phi) { return phi; }, tau);
    }
    ASSERT_GT(tau * slope(phi0), b) << "the fan must have crossed the face";
    double coarser = 0.0;
    for (const int n : {101, 201, 401}) {
        const RingFilm film(flatFace(b), Lubricant(eta), n);
        const RingFilmState s = underGas(h, dp);
        Eigen::VectorXd phi = Eigen::VectorXd::Constant(n, phi0);
        const int per = (n - 1) / 50;  // steps per sample: Δt ∝ Δx
        const double dt = dT / per, first = phi0 * h * b * (n - 2) / (n - 1);
        double oil = first, worst = 0.0, imbalance = 0.0;
        for (int k = 1; k <= samples * per; ++k) {
            const RingFilmResult r = film.step(s, dt, phi);
            ASSERT_TRUE(r.openToGas) << k;
            imbalance = std::max(imbalance, std::abs(r.oil - oil - dt * r.inflow) / (dt * std::abs(r.inflow)));
            EXPECT_GE(r.fraction.minCoeff(), 0.0);
            phi = r.fraction;
            oil = r.oil;
            if (k % per == 0)
                worst = std::max(worst, std::abs((first - oil) - lost[static_cast<std::size_t>(k / per)]) / start);
        }
        std::printf("%d nodes: the oil lost within %.3g of the start's of the characteristics' (%.3g left), step "
                    "imbalance %.2g of its flow\n",
                    n, worst, 1.0 - lost.back() / start, imbalance);
        EXPECT_LT(imbalance, 1e-9);
        if (coarser > 0.0) {
            EXPECT_GT(coarser / worst, 1.7) << n;  // first order: 2 per halving
        }
        coarser = worst;
    }
    EXPECT_LT(coarser, 1.5e-3);
}

// A lifted taper face the gas blows through (the second ring of the example engine's pack lifted on
// its upper flank at 4000 rpm: 13.6 µm off the liner on the layer's 17 µm, 2.41 bar of gas above
// and 0.76 bar below, its lower edge rounded 2 µm over 50 µm, the 1° taper above; its last step's
// film partial, about that run's). A full film over the rounding could hold at most
// 6 η U ℓ/h² = 1.1 bar of gas against its Couette inflow (ℓ the rounding's length): less than
// the 1.65 bar across it. The partition that holds the higher gas at the film's meniscus cycles
// (the gas displaces the film, the inflow refills it), and the step is solved open to the gas: its
// oil balances with the edges' inflow to round-off, its gas pressure rises from the lower edge's to
// the upper one's along the face, and the oil leaves through the leading edge against the layer's
// inflow.
TEST(RingFilm, AFaceWhoseFilmCannotHoldTheGasIsBlownThrough) {
    const double b = 1.45e-3, eta = 0.0086;
    const RingFaceProfile face =
        RingFaceProfile::table({{-0.5 * b, 2e-6}, {-0.5 * b + 49.8e-6, 0.0}, {0.5 * b, 24.44e-6}});
    const int n = 201;
    const RingFilm film(face, Lubricant(eta, 820.0), n, 0.0, 0.6e-6);
    RingFilmState s;
    s.minimumGap = s.nominalGap = 13.57e-6;
    s.slidingSpeed = 7.908;
    s.squeezeRate = -0.00427;
    s.pressureBelow = 76116.0;
    s.pressureAbove = 240784.0;
    s.supplyFilm = 17.21e-6;
    const double dt = 1.632e-5;
    EXPECT_LT(6.0 * eta * s.slidingSpeed * 49.8e-6 / (s.minimumGap * s.minimumGap),
              s.pressureAbove - s.pressureBelow);
    Eigen::VectorXd before(n);
    for (int i = 0; i < n; ++i) before[i] = std::pow(0.923, i);
    RingFilmResult r;
    ASSERT_NO_THROW(r = film.step(s, dt, before));
    EXPECT_TRUE(r.openToGas);
    double oilBefore = 0.0;
    for (int i = 1; i + 1 < n; ++i) oilBefore += 0.5 * (r.x[i + 1] - r.x[i - 1]) * before[i] * (r.h[i] - dt * s.squeezeRate);
    const double imbalance = std::abs((r.oil - oilBefore) - dt * r.inflow);
    std::printf("blown through: oil %.4g -> %.4g m^2, lower edge's inflow %.3g m^2/s, step imbalance %.3g m^2\n",
                oilBefore, r.oil, r.inflowLow, imbalance);
    EXPECT_LT(imbalance, 1e-12 * std::max(dt * std::abs(r.inflow), r.oil));
    for (int i = 1; i + 1 < n; ++i) {
        EXPECT_GE(r.fraction[i], 0.0) << i;
        EXPECT_LE(r.fraction[i], 1.0) << i;
        EXPECT_GE(r.p[i], s.pressureBelow) << i;
        EXPECT_LE(r.p[i], s.pressureAbove) << i;
        if (r.fraction[i] < 1.0 && r.fraction[i - 1] < 1.0) {
            EXPECT_GE(r.p[i], r.p[i - 1]) << i;
        }
    }
    EXPECT_LT(r.inflowLow, 0.0) << "the gas blows the oil out through the leading edge";
}
