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

}  // namespace flexehd::lube::test
