#pragma once
// Builders shared by the lube tests: plain journal bearings and 1-D pads on the film grid.
#include <cmath>

#include "lube/FilmGrid.hpp"
#include "lube/FilmState.hpp"

namespace flexehd::lube::test {

constexpr double kPi = 3.14159265358979323846;

/// Plain journal bearing, journal spinning at ω inside a fixed sleeve, h = c(1 + ε cos θ).
struct Journal {
    double R = 0.05, c = 50e-6, mu = 0.01, omega = 100.0, eps = 0.6;

    /// Full 360° grid of length L, open ends at ambient 0.
    FilmGrid finiteGrid(double L, int nTheta, int nZ) const {
        return FilmGrid::fullCircumference(R, FilmGrid::uniform(-0.5 * L, 0.5 * L, nZ), nTheta);
    }
    /// Infinitely long bearing: one axial cell with symmetry (zero-flux) edges, pressure datum
    /// p = 0 at θ = 0 (the maximum film, where the Sommerfeld solution vanishes).
    FilmGrid longGrid(int nTheta) const {
        FilmGrid g = FilmGrid::fullCircumference(R, {0.0, 0.01}, nTheta);
        g.setEdge(Edge::AxialLow, EdgeCondition::Symmetry);
        g.setEdge(Edge::AxialHigh, EdgeCondition::Symmetry);
        g.fixNode(g.index(0, 0), 0.0);
        g.fixNode(g.index(1, 0), 0.0);
        return g;
    }
    FilmState state(const FilmGrid& g) const {
        FilmState s;
        s.h.resize(g.size());
        for (int k = 0; k < g.size(); ++k)
            s.h[k] = c * (1.0 + eps * std::cos(g.theta(g.thetaIndex(k))));
        s.inner.circumferential = omega * R;
        return s;
    }
};

/// A skirt-like starved film: the journal's gap c(1 + ε cos θ), ε = 0.5 + 0.3 sin(2πt/T) breathing
/// (squeeze, then opening), plus a barrel crown (2z/L)²; the outer surface slides axially at U
/// (no circumferential speed) and both axial ends are inlets of fraction φ_in (feed), so the full
/// film is a small pad where the barrel meets the oil.
struct StarvedBarrel {
    Journal journal;
    double L = 0.04, U = 8.0, crown = 40e-6, T = 0.02, inlet = 0.4;

    FilmGrid grid() const { return journal.finiteGrid(L, 72, 33); }
    FilmState state(const FilmGrid& g, double t) const {
        Journal j = journal;
        j.eps = 0.5 + 0.3 * std::sin(2 * kPi * t / T);
        FilmState f = j.state(g);
        f.inner.circumferential = 0.0;
        f.outer.axial = U;
        for (int k = 0; k < g.size(); ++k) {
            const double z = 2.0 * g.z(g.axialIndex(k)) / L;
            f.h[k] += crown * z * z;
        }
        return f;
    }
    /// The inlet fraction on both axial ends of a solver's grid.
    template <class Solver>
    void feed(const FilmGrid& g, Solver& s) const {
        for (int j = 0; j < g.nTheta(); ++j)
            for (int i : {0, g.nAxial() - 1}) s.setInletFraction(g.index(i, j), inlet);
    }
};

}  // namespace flexehd::lube::test
