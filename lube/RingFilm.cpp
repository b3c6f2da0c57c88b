#include "lube/RingFilm.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::lube {

namespace {

constexpr int kColumns = 3;  // θ columns of the axisymmetric film (the least a periodic grid takes)

ReynoldsOptions ringSolverOptions(double pcav) {
    ReynoldsOptions o;
    o.cavitation = Cavitation::Reynolds;
    o.solver = SolverKind::ActiveSet;
    o.cavitationPressure = pcav;
    o.control.tolerance = 1e-12;
    return o;
}

FilmGrid faceGrid(const RingFaceProfile& profile, double radius, int nodes) {
    if (nodes < 5) throw std::invalid_argument("RingFilm: at least 5 nodes across the face, got " + std::to_string(nodes));
    if (!(radius > 0.0)) throw std::invalid_argument("RingFilm: the bore radius must be positive");
    return FilmGrid::fullCircumference(radius, FilmGrid::uniform(profile.lower(), profile.upper(), nodes), kColumns);
}

}  // namespace

RingFilm::RingFilm(RingFaceProfile profile, double boreRadius, Lubricant lubricant, int nodes, double cavitationPressure)
    : profile_(std::move(profile)), lubricant_(lubricant), pcav_(cavitationPressure),
      grid_(faceGrid(profile_, boreRadius, nodes)) {
    drop_.resize(grid_.size());
    for (int k = 0; k < grid_.size(); ++k) drop_[k] = profile_.drop(grid_.z(grid_.axialIndex(k)));
}

RingFilmResult RingFilm::solve(const RingFilmState& s) const {
    if (!(s.minimumGap > 0.0) || !std::isfinite(s.minimumGap))
        throw std::invalid_argument("RingFilm: the minimum gap must be positive, got " + std::to_string(s.minimumGap));
    if (!std::isfinite(s.slidingSpeed) || !std::isfinite(s.squeezeRate) || !std::isfinite(s.pressureBelow) ||
        !std::isfinite(s.pressureAbove))
        throw std::invalid_argument("RingFilm: sliding speed, squeeze rate and edge pressures must be finite");
    // The edges at the gas pressures of this state (a small grid: its solver is set up per solve).
    FilmGrid g = grid_;
    g.setEdge(Edge::AxialLow, EdgeCondition::Pressure, std::max(s.pressureBelow, pcav_));
    g.setEdge(Edge::AxialHigh, EdgeCondition::Pressure, std::max(s.pressureAbove, pcav_));
    ReynoldsSolver solver(g, lubricant_, ringSolverOptions(pcav_));
    FilmState f;
    f.h = drop_.array() + s.minimumGap;
    f.dhdt = Eigen::VectorXd::Constant(g.size(), s.squeezeRate);
    f.outer.axial = s.slidingSpeed;
    const Eigen::VectorXd p = solver.solve(f).pressure;

    // Per unit circumference: the first column (the film does not depend on θ).
    const int n = g.nAxial();
    RingFilmResult r;
    r.x.resize(n);
    r.h.resize(n);
    r.p.resize(n);
    for (int i = 0; i < n; ++i) {
        const int k = g.index(i, 0);
        r.x[i] = g.z(i);
        r.h[i] = f.h[k];
        r.p[i] = p[k];
    }
    const double eta = lubricant_.referenceViscosity();
    for (int i = 0; i + 1 < n; ++i) {  // trapezoids between nodes
        const double dx = r.x[i + 1] - r.x[i], hm = 0.5 * (r.h[i] + r.h[i + 1]), dpdx = (r.p[i + 1] - r.p[i]) / dx;
        r.load += 0.5 * (r.p[i] + r.p[i + 1]) * dx;
        // Shear on the ring (u = 0) from the liner's Couette flow and the Poiseuille flow; no
        // Couette shear where the film is cavitated on both nodes (Reynolds condition).
        const bool cavitated = r.p[i] <= pcav_ && r.p[i + 1] <= pcav_;
        r.friction += ((cavitated ? 0.0 : eta * s.slidingSpeed / hm) - 0.5 * hm * dpdx) * dx;
    }
    return r;
}

}  // namespace flexehd::lube
