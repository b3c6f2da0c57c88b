// JfoLinearization (the mass-conserving film's generalized Jacobian for the coupled Newton
// method) against central differences of full JFO solves (the active set to round-off, an
// independent route: it knows nothing of the linearisation), in a transient step of the
// breathing finite journal that ruptures and re-forms: flooded, and sliding axially too with its
// inflow end starved (the cavity's film fraction then comes from the inlet's).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "lube/JfoLinearization.hpp"
#include "lube/JfoSolver.hpp"
#include "tests/lube/LubeTestSupport.hpp"

using namespace flexehd::lube;
using flexehd::lube::test::Journal;
using flexehd::lube::test::kPi;

namespace {

// axial: the bearing's axial sliding speed (m/s), so that the Couette flow enters at an end.
FilmState breathing(const Journal& jb, const FilmGrid& g, double t, double T, double axial) {
    Journal j = jb;
    j.eps = 0.5 + 0.3 * std::sin(2 * kPi * t / T);
    FilmState f = j.state(g);
    f.outer.axial = axial;
    return f;
}

// max |δp_lin − δp_fd| / max |δp_fd| at a step inside the transient (the film partly cavitated).
// fluxHeld: the starved ends bring a given oil flux (φ_in h_f held), the differences re-setting
// φ_in for each thickness; linearised with InletResponse::FluxHeldWherePartial when linFlux.
double relativeError(double inlet, double axial, int* cavitated, bool fluxHeld = false, bool linFlux = false) {
    Journal jb;
    const FilmGrid g = jb.finiteGrid(2 * jb.R, 48, 17);
    const double T = 0.02, dt = T / 40;
    JfoOptions jo;
    jo.method = JfoMethod::ActiveSet;
    jo.control.tolerance = 1e-13;
    JfoSolver jfo(g, Lubricant(jb.mu), jo);
    if (inlet < 1.0)  // the axial ends starved: the inflow end's Couette flow brings φ_in
        for (int j = 0; j < g.nTheta(); ++j)
            for (int i : {0, g.nAxial() - 1}) jfo.setInletFraction(g.index(i, j), inlet);
    FilmState st = breathing(jb, g, 0.0, T, axial);
    JfoResult r;
    r.pressure = Eigen::VectorXd::Zero(g.size());
    r.fraction = Eigen::VectorXd::Ones(g.size());
    JfoState old;
    const int steps = 27;  // the gap opening again after the squeeze: a re-forming film
    for (int step = 1; step <= steps; ++step) {
        old = {st.h, r.fraction};
        st = breathing(jb, g, step * dt, T, axial);
        r = jfo.solve(st, dt, &old, &r);
    }
    const int n = g.size();
    Eigen::VectorXd dh(n);
    for (int k = 0; k < n; ++k) {
        const double th = g.theta(g.thetaIndex(k)), z = g.z(g.axialIndex(k)) / jb.R;
        dh[k] = jb.c * (0.3 * std::cos(2 * th) + 0.2 * z + 0.1 * std::sin(th) * z * z);
    }
    JfoLinearization lin(jfo, linFlux ? InletResponse::FluxHeldWherePartial : InletResponse::FractionHeld);
    lin.linearize(st, dt, &old, r);
    *cavitated = lin.cavitatedNodes();
    const double s = 1e-6;
    auto pressureAt = [&](double e) {
        FilmState f = st;
        f.h += e * dh;
        if (fluxHeld)
            for (int j = 0; j < g.nTheta(); ++j)
                for (int i : {0, g.nAxial() - 1}) {
                    const int m = g.index(i, j), k = g.index(i == 0 ? 1 : i - 1, j);
                    jfo.setInletFraction(m, inlet * (st.h[m] + st.h[k]) / (f.h[m] + f.h[k]));
                }
        JfoResult solved = jfo.solve(f, dt, &old, &r);
        if (fluxHeld)  // back to the linearisation point's inlets
            for (int j = 0; j < g.nTheta(); ++j)
                for (int i : {0, g.nAxial() - 1}) jfo.setInletFraction(g.index(i, j), inlet);
        return solved.pressure;
    };
    const Eigen::VectorXd fd = (pressureAt(s) - pressureAt(-s)) / (2 * s);
    const Eigen::VectorXd dp = lin.pressureChange(dh).col(0);
    EXPECT_GT(fd.cwiseAbs().maxCoeff(), 0.0);
    const double err = (dp - fd).cwiseAbs().maxCoeff() / fd.cwiseAbs().maxCoeff();
    std::printf("inlet fraction %.2f: %d of %d nodes cavitated, relative error %.3g\n", inlet, *cavitated, n, err);
    return err;
}

}  // namespace

TEST(JfoLinearization, MatchesDifferencesOfReformingTransientSolves) {
    int cavitated = 0;
    const double err = relativeError(1.0, 0.0, &cavitated);
    EXPECT_GT(cavitated, 100) << "the check must include a cavity";
    EXPECT_LT(err, 1e-5);
}

TEST(JfoLinearization, MatchesDifferencesWithAxialSlidingFromAStarvedEnd) {
    int cavitated = 0;
    const double err = relativeError(0.3, 5.0, &cavitated);
    EXPECT_GT(cavitated, 100);
    EXPECT_LT(err, 1e-5);
}

// The inlet fed with a given oil flux (a liner oil layer): as the gap opens its fraction falls.
TEST(JfoLinearization, MatchesDifferencesWithAGivenInletFlux) {
    int cavitated = 0;
    const double err = relativeError(0.3, 5.0, &cavitated, true, true);
    EXPECT_GT(cavitated, 100);
    EXPECT_LT(err, 1e-5);
    // Holding the fraction instead misses how the inflow stays put: the check must tell them apart.
    const double wrongRule = relativeError(0.3, 5.0, &cavitated, true, false);
    EXPECT_GT(wrongRule, 100.0 * err);
}

// A skirt-like starved film (test::StarvedBarrel: a barrel-shaped gap sliding axially, the
// inflow end bringing φ_in = 0.4 of its gap, breathing)
// at a step with a full-film pad: the linearisation's system holds only the rows the pad's
// pressure depends on — the pad and the cavities upstream of it, not those downstream or beside
// it — and its δp matches central differences of full active-set solves (which know nothing of
// that restriction) as closely as on the journals above.
TEST(JfoLinearization, OnAStarvedPadItsSystemIsThePadAndWhatFeedsIt) {
    const flexehd::lube::test::StarvedBarrel barrel;
    const Journal jb = barrel.journal;
    const FilmGrid g = barrel.grid();
    const double dt = barrel.T / 80;
    auto state = [&](double t) { return barrel.state(g, t); };
    JfoOptions jo;
    jo.method = JfoMethod::ActiveSet;
    jo.control.tolerance = 1e-13;
    JfoSolver jfo(g, Lubricant(jb.mu), jo);
    barrel.feed(g, jfo);
    FilmState st = state(0.0);
    JfoResult r;
    r.pressure = Eigen::VectorXd::Zero(g.size());
    r.fraction = Eigen::VectorXd::Constant(g.size(), barrel.inlet);
    JfoState old;
    for (int step = 1; step <= 20; ++step) {  // the gap closing: a pad of about 300 full-film nodes
        old = {st.h, r.fraction};
        st = state(step * dt);
        r = jfo.solve(st, dt, &old, &r);
    }
    int full = 0;
    for (int k = 0; k < g.size(); ++k) full += g.kind(k) == NodeKind::Film && r.fraction[k] >= 1.0 && r.pressure[k] > 0.0;
    Eigen::VectorXd dh(g.size());
    for (int k = 0; k < g.size(); ++k) {
        const double th = g.theta(g.thetaIndex(k)), z = g.z(g.axialIndex(k)) / jb.R;
        dh[k] = jb.c * (0.3 * std::cos(2 * th) + 0.2 * z + 0.1 * std::sin(th) * z * z);
    }
    JfoLinearization lin(jfo);
    lin.linearize(st, dt, &old, r);
    const double s = 1e-6;
    auto pressureAt = [&](double e) {
        FilmState f = st;
        f.h += e * dh;
        return jfo.solve(f, dt, &old, &r).pressure;
    };
    const Eigen::VectorXd fd = (pressureAt(s) - pressureAt(-s)) / (2 * s);
    const Eigen::VectorXd dp = lin.pressureChange(dh).col(0);
    const double err = (dp - fd).cwiseAbs().maxCoeff() / fd.cwiseAbs().maxCoeff();
    std::printf("starved barrel: %d full-film nodes, system of %d of %d Film nodes, relative error %.3g\n", full,
                lin.systemRows(), g.filmNodeCount(), err);
    EXPECT_GT(full, 50) << "the check needs a pad";
    EXPECT_GT(lin.systemRows(), full);                   // the cavities feeding the pad are in it
    EXPECT_LT(lin.systemRows(), g.filmNodeCount() / 2);  // most of the cavity is not
    EXPECT_LT(err, 1e-5);
}
