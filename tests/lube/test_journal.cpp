// Plain journal bearings against the classical solutions (Hamrock, Fundamentals of Fluid Film Lubrication): infinitely long bearing
// (full and half Sommerfeld, Reynolds condition), short bearing (Ocvirk), Petroff friction, and
// the fast solver against PSOR.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "lube/FilmIntegrals.hpp"
#include "lube/ReynoldsSolver.hpp"
#include "tests/lube/LubeTestSupport.hpp"

using namespace flexehd::lube;
using flexehd::lube::test::Journal;
using flexehd::lube::test::kPi;

namespace {

struct LongResult {
    double Wr, Wt;  // film force on the journal along +x (line of centres) and −y, per unit
                    // length, in units of 6 μ ω R³ / c²
    int iterations;
    // Reference only: ∫ H P' dθ and ∫ H³ P'² dθ over the full film (the Poiseuille parts of
    // the friction torque and of the dissipation).
    double poiseuilleTorque = 0.0, poiseuilleDissipation = 0.0;
};

LongResult solveLong(const Journal& jb, int nTheta, Cavitation cav, SolverKind solver) {
    ReynoldsOptions opt;
    opt.cavitation = cav;
    opt.solver = solver;
    opt.control.tolerance = 1e-10;
    ReynoldsSolver rs(jb.longGrid(nTheta), Lubricant(jb.mu), opt);
    const FilmState st = jb.state(rs.grid());
    const ReynoldsResult r = rs.solve(st);
    const FilmLoads f = integrateFilm(rs.grid(), st, rs.lubricant(), r.pressure);
    const double unit = 6 * jb.mu * jb.omega * std::pow(jb.R, 3) / (jb.c * jb.c) *
                        rs.grid().length();
    return {f.pressureForce.x() / unit, -f.pressureForce.y() / unit, r.iterations};
}

// Infinitely long bearing with the Reynolds condition, by an independent method: the integrated
// Reynolds equation P' = (H − H*)/H³ (P in units 6μω(R/c)², H = 1 + ε cos θ) from P(0) = 0 to
// the cavitation angle θc where P = P' = 0 (H* = H(θc)), found by bisection; loads by parts:
// Fx = ∫ P' sin θ dθ, Fy = −∫ P' cos θ dθ, Simpson with 20000 intervals.
LongResult reynoldsLongReference(double eps) {
    auto H = [&](double t) { return 1 + eps * std::cos(t); };
    auto simpson = [](auto f, double a, double b) {
        const int n = 20000;
        const double h = (b - a) / n;
        double s = f(a) + f(b);
        for (int i = 1; i < n; ++i) s += (i % 2 ? 4 : 2) * f(a + i * h);
        return s * h / 3;
    };
    auto G = [&](double tc) {
        const double hs = H(tc);
        return simpson([&](double t) { return (H(t) - hs) / std::pow(H(t), 3); }, 0.0, tc);
    };
    double lo = kPi + 1e-9, hi = 2 * kPi - 1e-9;  // G(lo) > 0, G(hi) < 0
    for (int it = 0; it < 80; ++it) {
        const double mid = 0.5 * (lo + hi);
        (G(mid) > 0 ? lo : hi) = mid;
    }
    const double tc = 0.5 * (lo + hi), hs = H(tc);
    auto dP = [&](double t) { return (H(t) - hs) / std::pow(H(t), 3); };
    return {simpson([&](double t) { return dP(t) * std::sin(t); }, 0.0, tc),
            simpson([&](double t) { return dP(t) * std::cos(t); }, 0.0, tc), 0,
            simpson([&](double t) { return H(t) * dP(t); }, 0.0, tc),
            simpson([&](double t) { return std::pow(H(t), 3) * dP(t) * dP(t); }, 0.0, tc)};
}

}  // namespace

// Full Sommerfeld: W = 2πε/[(2+ε²)√(1−ε²)] at 90° attitude (1.99677 at ε = 0.6).
// Second-order FV: the error falls ~4× from 120 to 240 nodes; 240 nodes is within 0.1%.
TEST(JournalLong, FullSommerfeldLoadAndSecondOrderConvergence) {
    for (double eps : {0.3, 0.6, 0.8}) {
        Journal jb;
        jb.eps = eps;
        const double W = 2 * kPi * eps / ((2 + eps * eps) * std::sqrt(1 - eps * eps));
        if (eps == 0.6) {
            EXPECT_NEAR(W, 1.99677, 1e-5);
        }
        const LongResult coarse = solveLong(jb, 120, Cavitation::None, SolverKind::ActiveSet);
        const LongResult fine = solveLong(jb, 240, Cavitation::None, SolverKind::ActiveSet);
        const double eC = std::abs(std::hypot(coarse.Wr, coarse.Wt) - W) / W;
        const double eF = std::abs(std::hypot(fine.Wr, fine.Wt) - W) / W;
        EXPECT_LT(eF, 1e-3) << "eps " << eps;
        EXPECT_GT(eC / eF, 3.5) << "eps " << eps << " not second order: " << eC << " " << eF;
        EXPECT_LT(eC / eF, 4.5) << "eps " << eps;
        EXPECT_NEAR(fine.Wr, 0.0, 1e-9 * W) << "attitude must be 90 deg (antisymmetric p)";
    }
}

// Half Sommerfeld: W_r = 2ε²/[(2+ε²)(1−ε²)], W_t = πε/[(2+ε²)√(1−ε²)] (0.47669, 0.99839 at 0.6).
TEST(JournalLong, HalfSommerfeldComponents) {
    for (double eps : {0.3, 0.6, 0.8}) {
        Journal jb;
        jb.eps = eps;
        const double Wr = 2 * eps * eps / ((2 + eps * eps) * (1 - eps * eps));
        const double Wt = kPi * eps / ((2 + eps * eps) * std::sqrt(1 - eps * eps));
        if (eps == 0.6) {
            EXPECT_NEAR(Wr, 0.47669, 1e-5);
            EXPECT_NEAR(Wt, 0.99839, 1e-5);
        }
        for (SolverKind s : {SolverKind::ActiveSet, SolverKind::Psor, SolverKind::Multigrid}) {
            const LongResult r = solveLong(jb, 240, Cavitation::HalfSommerfeld, s);
            EXPECT_NEAR(r.Wr, Wr, 5e-3 * std::hypot(Wr, Wt)) << "eps " << eps;
            EXPECT_NEAR(r.Wt, Wt, 5e-3 * std::hypot(Wr, Wt)) << "eps " << eps;
        }
    }
}

// Reynolds (Swift–Stieber) condition against the independent shooting solution above; both
// solvers; the error shrinks with refinement.
TEST(JournalLong, ReynoldsConditionMatchesShooting) {
    for (double eps : {0.3, 0.6, 0.8}) {
        Journal jb;
        jb.eps = eps;
        const LongResult ref = reynoldsLongReference(eps);
        const double W = std::hypot(ref.Wr, ref.Wt);
        double prev = 1.0;
        for (int n : {120, 480}) {
            const LongResult fast = solveLong(jb, n, Cavitation::Reynolds, SolverKind::ActiveSet);
            const double err = std::hypot(fast.Wr - ref.Wr, fast.Wt - ref.Wt) / W;
            const LongResult mg = solveLong(jb, n, Cavitation::Reynolds, SolverKind::Multigrid);
            EXPECT_NEAR(mg.Wr, fast.Wr, 1e-8 * W) << "multigrid = active set";
            EXPECT_NEAR(mg.Wt, fast.Wt, 1e-8 * W) << "multigrid = active set";
            EXPECT_LT(err, n == 480 ? 5e-3 : 2e-2) << "eps " << eps << " n " << n;
            EXPECT_LT(err, prev) << "eps " << eps;
            prev = err;
        }
    }
}

// Friction across a cavitation boundary: the infinitely long bearing with the Reynolds
// condition (cavitated film: p = p_cav, full Couette shear) against the shooting solution above.
// With p = 6μω(R/c)² P and h = c H the torque on the journal and the dissipation are
//   T = −(μωR³L/c) [∫ dθ/H + 3 ∫ H P' dθ],   D = (μω²R³L/c) [∫ dθ/H + 3 ∫ H³ P'² dθ],
// ∫₀^2π dθ/H = 2π/√(1−ε²) (the full-Sommerfeld case of FrictionTorqueAndFlow, these with the
// integrals over the whole circumference). The pressure gradient is continuous at rupture
// (P' = 0 there) but jumps at reformation (θ = 0, where P' goes from 0 to (H(0) − H*)/H(0)³):
// the dissipation's |∇p|² must take the mean of the squares there, not the square of the mean,
// for both to converge at second order.
TEST(JournalLong, FrictionAcrossTheCavitationBoundaryConvergesAtSecondOrder) {
    for (double eps : {0.3, 0.6, 0.8}) {
        Journal jb;
        jb.eps = eps;
        const LongResult ref = reynoldsLongReference(eps);
        const double couette = 2 * kPi / std::sqrt(1 - eps * eps);
        double prevT = 0.0, prevD = 0.0;
        for (int n : {120, 240, 480}) {
            ReynoldsOptions opt;
            opt.cavitation = Cavitation::Reynolds;
            opt.control.tolerance = 1e-12;
            ReynoldsSolver rs(jb.longGrid(n), Lubricant(jb.mu), opt);
            const FilmState st = jb.state(rs.grid());
            const ReynoldsResult r = rs.solve(st);
            const FilmLoads f = integrateFilm(rs.grid(), st, rs.lubricant(), r.pressure);
            const double unit = jb.mu * jb.omega * std::pow(jb.R, 3) * rs.grid().length() / jb.c;
            const double T = -unit * (couette + 3 * ref.poiseuilleTorque);
            const double D = unit * jb.omega * (couette + 3 * ref.poiseuilleDissipation);
            const double eT = std::abs(f.moment.z() / T - 1), eD = std::abs(f.viscousDissipation / D - 1);
            std::printf("  eps %.1f n %d: torque error %.3e, dissipation error %.3e\n", eps, n, eT, eD);
            EXPECT_LT(eT, 5e-4) << "eps " << eps << " n " << n;
            EXPECT_LT(eD, 5e-4) << "eps " << eps << " n " << n;
            if (prevT > 0) {
                EXPECT_GT(prevT / eT, 3.0) << "torque not second order, eps " << eps << " n " << n;
                EXPECT_GT(prevD / eD, 3.0) << "dissipation not second order, eps " << eps << " n " << n;
            }
            prevT = eT;
            prevD = eD;
        }
    }
}

// Short-bearing (Ocvirk) limit, half Sommerfeld: W = μωR L³ ε √(π²(1−ε²)+16ε²)/[4c²(1−ε²)²],
// tan φ = π√(1−ε²)/(4ε). The short-bearing theory neglects circumferential pressure flow, an
// O((L/D)²) error: the deficit must fall ~4× when L/D halves and be < 1% at L/D = 1/16.
TEST(JournalShort, OcvirkLimit) {
    const double eps = 0.6;
    double prevDeficit = 1.0;
    for (double LD : {0.125, 0.0625}) {
        Journal jb;
        jb.eps = eps;
        const double L = LD * 2 * jb.R;
        ReynoldsOptions opt;
        opt.cavitation = Cavitation::HalfSommerfeld;
        ReynoldsSolver rs(jb.finiteGrid(L, 240, 41), Lubricant(jb.mu), opt);
        const FilmState st = jb.state(rs.grid());
        const ReynoldsResult r = rs.solve(st);
        const FilmLoads f = integrateFilm(rs.grid(), st, rs.lubricant(), r.pressure);
        const double W = jb.mu * jb.omega * jb.R * std::pow(L, 3) * eps *
                         std::sqrt(kPi * kPi * (1 - eps * eps) + 16 * eps * eps) /
                         (4 * jb.c * jb.c * std::pow(1 - eps * eps, 2));
        const double phi = std::atan(kPi * std::sqrt(1 - eps * eps) / (4 * eps));
        const double deficit = 1 - f.pressureForce.norm() / W;
        EXPECT_GT(deficit, 0.0);
        EXPECT_LT(deficit, prevDeficit / 3) << "L/D " << LD;
        prevDeficit = deficit;
        const double att = std::atan2(-f.pressureForce.y(), f.pressureForce.x());
        EXPECT_NEAR(att, phi, LD == 0.0625 ? 0.005 : 0.02) << "L/D " << LD;
    }
    EXPECT_LT(prevDeficit, 0.01);
}

// Friction torque on the journal, infinitely long, full Sommerfeld (Couette + Poiseuille):
// T = −(4πμωR³L/c)(1+2ε²)/[(2+ε²)√(1−ε²)]; ε = 0 is Petroff's law T = −2πμωR³L/c.
// Circumferential flow Q = ωRcL(1−ε²)/(2+ε²) (h* = 2c(1−ε²)/(2+ε²)), the same at every section.
TEST(JournalLong, FrictionTorqueAndFlow) {
    for (double eps : {0.0, 0.6}) {
        Journal jb;
        jb.eps = eps;
        ReynoldsOptions opt;
        opt.cavitation = Cavitation::None;
        ReynoldsSolver rs(jb.longGrid(240), Lubricant(jb.mu), opt);
        const FilmState st = jb.state(rs.grid());
        const ReynoldsResult r = rs.solve(st);
        const FilmLoads f = integrateFilm(rs.grid(), st, rs.lubricant(), r.pressure);
        const double L = rs.grid().length();
        const double T = -4 * kPi * jb.mu * jb.omega * std::pow(jb.R, 3) * L / jb.c *
                         (1 + 2 * eps * eps) / ((2 + eps * eps) * std::sqrt(1 - eps * eps));
        EXPECT_NEAR(f.moment.z() / T, 1.0, 2e-4) << "eps " << eps;
        if (eps == 0.0) {
            EXPECT_NEAR(f.moment.z(), -2 * kPi * jb.mu * jb.omega * std::pow(jb.R, 3) * L / jb.c,
                        1e-12);
        }
        const double Q = jb.omega * jb.R * jb.c * L * (1 - eps * eps) / (2 + eps * eps);
        const double q10 = circumferentialFlow(rs.grid(), st, rs.lubricant(), r.pressure, 10);
        const double q100 = circumferentialFlow(rs.grid(), st, rs.lubricant(), r.pressure, 100);
        EXPECT_NEAR(q10 / Q, 1.0, 5e-4);
        EXPECT_NEAR(q100 / q10, 1.0, 1e-10) << "finite volumes conserve mass exactly";
        // Dissipation equals the torque's power for a fixed sleeve (no pressure work at steady state).
        EXPECT_NEAR(f.viscousDissipation / (-f.moment.z() * jb.omega), 1.0, 2e-3);
    }
}

// Second independent method: PSOR (the seed's baseline) and the active-set solver give the same
// cavitated pressure field on a finite bearing, L/D = 1, ε = 0.7, to the solver tolerance.
TEST(JournalFinite, ActiveSetEqualsPsor) {
    Journal jb;
    jb.eps = 0.7;
    Eigen::VectorXd p[2];
    int it[2];
    for (int s = 0; s < 2; ++s) {
        ReynoldsOptions opt;
        opt.solver = s == 0 ? SolverKind::Psor : SolverKind::ActiveSet;
        opt.control.tolerance = 1e-11;
        ReynoldsSolver rs(jb.finiteGrid(2 * jb.R, 72, 25), Lubricant(jb.mu), opt);
        const ReynoldsResult r = rs.solve(jb.state(rs.grid()));
        p[s] = r.pressure;
        it[s] = r.iterations;
        EXPECT_LE(r.residual, 1e-11);
    }
    const double pmax = p[1].maxCoeff();
    EXPECT_GT(pmax, 1e5);
    EXPECT_LT((p[0] - p[1]).cwiseAbs().maxCoeff() / pmax, 1e-8);
    EXPECT_GT(it[0], 10 * it[1]);
    EXPECT_EQ(p[1].minCoeff(), 0.0) << "cavitated nodes sit exactly at p_cav";
}

// Grid sequencing (coarse solves prolonged as the start) changes the path, not the answer:
// the active-set solution is exact to round-off either way, with fewer fine factorizations.
// A warm start from the converged answer needs a single factorization.
TEST(JournalFinite, GridSequencingAndWarmStart) {
    Journal jb;
    jb.eps = 0.7;
    ReynoldsResult r[2];
    for (int s = 0; s < 2; ++s) {
        ReynoldsOptions opt;
        opt.gridSequencing = s == 1;
        ReynoldsSolver rs(jb.finiteGrid(2 * jb.R, 128, 33), Lubricant(jb.mu), opt);
        r[s] = rs.solve(jb.state(rs.grid()));
        if (s == 1) {
            const ReynoldsResult again = rs.solve(jb.state(rs.grid()), &r[s].pressure);
            EXPECT_EQ(again.iterations, 1);
            EXPECT_EQ(again.coarseIterations, 0);
        }
    }
    EXPECT_EQ(r[0].coarseIterations, 0);
    EXPECT_GT(r[1].coarseIterations, 0);
    EXPECT_LT(r[1].iterations, r[0].iterations);
    EXPECT_LT((r[0].pressure - r[1].pressure).cwiseAbs().maxCoeff() / r[0].pressure.maxCoeff(), 1e-12);
}

// Flow out of an end (axialEdgeFlow): a journal of eccentricity 0.6, not turning, its film
// closing at ∂h/∂t = −V(1 + 2z/L) + 0.5 V cos θ, the low end closed (zero flux), the high end
// open, full film. Mass conservation makes the flow out of the open end the volume the film
// loses, ∫ −∂h/∂t dA = V × 2πRL, whatever the pressure field. The face fluxes half a cell inside
// the end miss the last half cell's share (first order: 2πR · 2V · Δz/2, Δz/L relative, the
// film closing at 2V there); the extrapolated ones converge
// at second order. Their error is known: the ring's flux Q(z) is quadratic (Q'' = 4πRV/L), so
// extrapolating it linearly from Δz/2 and 3Δz/2 inside the end errs by (3/8) Q'' Δz², and the
// closed end's half cell, weighting the source at its node, by Q'' Δz²/8: together (Δz/L)²
// relative, which the test expects to 1 %.
TEST(JournalSqueeze, FlowOutOfAnEndConvergesAtSecondOrder) {
    Journal jb;
    const double L = 0.05, V = 1e-3;
    for (int nz : {9, 17, 33, 65}) {
        ReynoldsOptions opt;
        opt.cavitation = Cavitation::None;
        opt.control.tolerance = 1e-12;
        FilmGrid g = jb.finiteGrid(L, 64, nz);
        g.setEdge(Edge::AxialLow, EdgeCondition::Symmetry);
        ReynoldsSolver rs(std::move(g), Lubricant(jb.mu), opt);
        const FilmGrid& grid = rs.grid();
        FilmState st = jb.state(grid);
        st.inner.circumferential = 0.0;
        st.dhdt.resize(grid.size());
        for (int k = 0; k < grid.size(); ++k)
            st.dhdt[k] = -V * (1.0 + 2.0 * grid.z(grid.axialIndex(k)) / L) +
                         0.5 * V * std::cos(grid.theta(grid.thetaIndex(k)));
        const Eigen::VectorXd p = rs.solve(st).pressure;
        const double out = axialEdgeFlow(grid, st, rs.lubricant(), p, Edge::AxialHigh);
        const double inside = axialFlow(grid, st, rs.lubricant(), p, nz - 2);
        const double exact = V * 2 * kPi * jb.R * L;
        const double err = std::abs(out / exact - 1.0);
        std::printf("  nz %2d: flow out of the end, error %.2e (half a cell inside it: %.2e)\n", nz, err,
                    std::abs(inside / exact - 1.0));
        const double dz = L / (nz - 1);
        EXPECT_NEAR(err, dz * dz / (L * L), 0.01 * dz * dz / (L * L)) << "nz = " << nz;
        EXPECT_NEAR(std::abs(inside / exact - 1.0), dz / L, 0.01 * dz / L) << "nz = " << nz;
    }
}
