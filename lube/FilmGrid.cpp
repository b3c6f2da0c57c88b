#include "lube/FilmGrid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace flexehd::lube {

namespace {

void checkAxial(const std::vector<double>& z) {
    if (z.size() < 2)
        throw std::invalid_argument("FilmGrid: axial coordinates need at least 2 nodes, got " +
                                    std::to_string(z.size()));
    for (std::size_t i = 0; i < z.size(); ++i) {
        if (!std::isfinite(z[i]))
            throw std::invalid_argument("FilmGrid: axial coordinate " + std::to_string(i) +
                                        " is not finite");
        if (i > 0 && !(z[i] > z[i - 1]))
            throw std::invalid_argument("FilmGrid: axial coordinates must be strictly increasing "
                                        "(z[" + std::to_string(i) + "] <= z[" +
                                        std::to_string(i - 1) + "])");
    }
}

void checkRadius(double radius) {
    if (!(radius > 0.0) || !std::isfinite(radius))
        throw std::invalid_argument("FilmGrid: radius must be positive and finite, got " +
                                    std::to_string(radius));
}

}  // namespace

FilmGrid::FilmGrid(double radius, std::vector<double> axial, int nTheta, bool periodic,
                   double theta0, double dTheta)
    : radius_(radius), z_(std::move(axial)), nTheta_(nTheta), periodic_(periodic),
      theta0_(theta0), dTheta_(dTheta) {
    const auto n = static_cast<std::size_t>(size());
    userKind_.assign(n, NodeKind::Film);
    userPressure_.assign(n, 0.0);
    if (periodic_) {
        edges_[static_cast<int>(Edge::ArcStart)].condition = EdgeCondition::Symmetry;
        edges_[static_cast<int>(Edge::ArcEnd)].condition = EdgeCondition::Symmetry;
    }
    refreshKinds();
    resetColumnGeometry();
    for (int j = 0; j < nTheta_; ++j) {
        cosTheta_.push_back(std::cos(theta(j)));
        sinTheta_.push_back(std::sin(theta(j)));
    }
}

void FilmGrid::resetColumnGeometry() {
    const auto nt = static_cast<std::size_t>(nTheta_);
    cvWidth_.assign(nt, dTheta_);
    if (!periodic_) cvWidth_.front() = cvWidth_.back() = 0.5 * dTheta_;
    coveredWidth_ = cvWidth_;
    coveredBelow_.assign(nt, 0.5 * dTheta_);
    if (!periodic_) coveredBelow_.front() = 0.0;
    faceAngle_.assign(nt, dTheta_);
}

FilmGrid FilmGrid::fullCircumference(double radius, std::vector<double> axial, int nTheta,
                                     double theta0) {
    checkRadius(radius);
    checkAxial(axial);
    if (nTheta < 3)
        throw std::invalid_argument("FilmGrid: a full circumference needs nTheta >= 3, got " +
                                    std::to_string(nTheta));
    return FilmGrid(radius, std::move(axial), nTheta, true, theta0, 2.0 * kPi / nTheta);
}

FilmGrid FilmGrid::arc(double radius, std::vector<double> axial, double theta0, double theta1,
                       int nTheta) {
    checkRadius(radius);
    checkAxial(axial);
    if (nTheta < 3)
        throw std::invalid_argument("FilmGrid: an arc needs nTheta >= 3, got " +
                                    std::to_string(nTheta));
    if (!(theta1 > theta0) || theta1 - theta0 > 2.0 * kPi)
        throw std::invalid_argument("FilmGrid: arc needs theta0 < theta1 <= theta0 + 2*pi");
    return FilmGrid(radius, std::move(axial), nTheta, false, theta0,
                    (theta1 - theta0) / (nTheta - 1));
}

std::vector<double> FilmGrid::uniform(double a, double b, int n) {
    if (n < 2)
        throw std::invalid_argument("FilmGrid::uniform: need n >= 2 nodes, got " +
                                    std::to_string(n));
    std::vector<double> v(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = a + (b - a) * i / (n - 1);
    return v;
}

double FilmGrid::axialWidth(int i) const {
    const int n = nAxial();
    const double lo = i > 0 ? 0.5 * (z(i) - z(i - 1)) : 0.0;
    const double hi = i < n - 1 ? 0.5 * (z(i + 1) - z(i)) : 0.0;
    return lo + hi;
}

void FilmGrid::restrictToArcs(std::vector<std::pair<double, double>> arcs) {
    if (arcs.empty()) throw std::invalid_argument("FilmGrid::restrictToArcs: no arc given");
    const double turn = 2.0 * kPi;
    for (const auto& [lo, hi] : arcs)
        if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo) || (periodic_ && hi - lo >= turn))
            throw std::invalid_argument("FilmGrid::restrictToArcs: arc [" + std::to_string(lo) + ", " +
                                        std::to_string(hi) + "] rad must have lo < hi" +
                                        (periodic_ ? " and span less than a turn" : ""));
    resetColumnGeometry();
    arcs_ = std::move(arcs);
    // Position of column j in arc a (θ wrapped into [lo, lo + 2π) on a full circumference), or
    // NaN when it lies outside.
    const double eps = 1e-12 * dTheta_;
    auto positionIn = [&](int j, const std::pair<double, double>& a) {
        double t = theta(j);
        const double from = a.first - eps;
        if (periodic_) t = from + std::fmod(std::fmod(t - from, turn) + turn, turn);
        return t >= from && t <= a.second + eps ? t : std::numeric_limits<double>::quiet_NaN();
    };
    const auto nt = static_cast<std::size_t>(nTheta_);
    std::vector<int> arcOf(nt, -1);
    std::vector<double> pos(nt, 0.0);
    for (int j = 0; j < nTheta_; ++j)
        for (std::size_t a = 0; a < arcs_.size(); ++a) {
            const double t = positionIn(j, arcs_[a]);
            if (std::isnan(t)) continue;
            arcOf[std::size_t(j)] = int(a);
            pos[std::size_t(j)] = t;
            break;
        }
    for (int j = 0; j < nTheta_; ++j) {
        const auto sj = static_cast<std::size_t>(j);
        if (arcOf[sj] < 0) {
            for (int i = 0; i < nAxial(); ++i) voidNode(index(i, j));
            continue;
        }
        const auto& [lo, hi] = arcs_[std::size_t(arcOf[sj])];
        const bool hasRight = periodic_ || j + 1 < nTheta_, hasLeft = periodic_ || j > 0;
        const std::size_t jr = std::size_t((j + 1) % nTheta_), jl = std::size_t((j + nTheta_ - 1) % nTheta_);
        double cv = 0.0, covered = 0.0;
        bool onEdge = false;
        // Adds the side's control volume and covered width; returns the covered width.
        auto side = [&](bool exists, std::size_t nb, double distance, std::size_t face) {
            if (!exists) return 0.0;  // open-arc end: the half control volume of the grid
            distance = std::max(0.0, distance);
            if (arcOf[nb] >= 0) {
                cv += 0.5 * dTheta_;
                covered += 0.5 * dTheta_;
                return 0.5 * dTheta_;
            }
            cv += 0.5 * distance;
            covered += distance;
            faceAngle_[face] = std::max(distance, 1e-6 * dTheta_);
            onEdge = onEdge || distance < 1e-6 * dTheta_;
            return distance;
        };
        side(hasRight, jr, hi - pos[sj], sj);
        coveredBelow_[sj] = side(hasLeft, jl, pos[sj] - lo, jl);
        cvWidth_[sj] = cv;
        coveredWidth_[sj] = covered;
        if (onEdge)
            for (int i = 0; i < nAxial(); ++i)
                if (userKind_[std::size_t(index(i, j))] == NodeKind::Film) fixNode(index(i, j), ambient_);
    }
}

void FilmGrid::setEdge(Edge edge, EdgeCondition condition, double pressure) {
    if (periodic_ && (edge == Edge::ArcStart || edge == Edge::ArcEnd))
        throw std::invalid_argument("FilmGrid::setEdge: a full circumference has no arc edges");
    if (!std::isfinite(pressure))
        throw std::invalid_argument("FilmGrid::setEdge: edge pressure must be finite");
    edges_[static_cast<int>(edge)] = {condition, pressure};
    refreshKinds();
}

void FilmGrid::setAmbientPressure(double p) {
    if (!std::isfinite(p))
        throw std::invalid_argument("FilmGrid::setAmbientPressure: pressure must be finite");
    ambient_ = p;
    refreshKinds();
}

void FilmGrid::fixNode(int k, double pressure) {
    if (k < 0 || k >= size())
        throw std::out_of_range("FilmGrid::fixNode: node " + std::to_string(k) +
                                " outside [0, " + std::to_string(size()) + ")");
    if (!std::isfinite(pressure))
        throw std::invalid_argument("FilmGrid::fixNode: pressure must be finite");
    const auto sk = static_cast<std::size_t>(k);
    userKind_[sk] = NodeKind::Fixed;
    userPressure_[sk] = pressure;
    kind_[sk] = NodeKind::Fixed;  // a user override wins over edges: no full refresh (O(N))
    fixedPressure_[sk] = pressure;
}

void FilmGrid::voidNode(int k) {
    if (k < 0 || k >= size())
        throw std::out_of_range("FilmGrid::voidNode: node " + std::to_string(k) +
                                " outside [0, " + std::to_string(size()) + ")");
    const auto sk = static_cast<std::size_t>(k);
    userKind_[sk] = NodeKind::Void;
    kind_[sk] = NodeKind::Void;
    fixedPressure_[sk] = ambient_;
}

double FilmGrid::prescribedPressure(int k) const {
    return fixedPressure_[static_cast<std::size_t>(k)];
}

int FilmGrid::filmNodeCount() const {
    int n = 0;
    for (NodeKind kd : kind_) n += kd == NodeKind::Film;
    return n;
}

std::optional<FilmGrid> FilmGrid::coarsened(std::vector<int>& axialMap) const {
    axialMap.clear();
    const int nz = nAxial();
    for (int i = 0; i < nz; i += 2) axialMap.push_back(i);
    if (axialMap.back() != nz - 1) axialMap.push_back(nz - 1);
    const bool halvable = periodic_ ? nTheta_ % 2 == 0 : nTheta_ % 2 == 1;
    const int nt = periodic_ ? nTheta_ / 2 : (nTheta_ + 1) / 2;
    if (!halvable || nt < 8 || axialMap.size() < 3 || axialMap.size() == z_.size())
        return std::nullopt;
    std::vector<double> zc;
    for (int i : axialMap) zc.push_back(z(i));
    FilmGrid c(radius_, std::move(zc), nt, periodic_, theta0_, 2.0 * dTheta_);
    for (int e = 0; e < 4; ++e) c.edges_[e] = edges_[e];
    c.ambient_ = ambient_;
    for (int I = 0; I < c.nAxial(); ++I)
        for (int J = 0; J < nt; ++J) {
            const auto kc = static_cast<std::size_t>(c.index(I, J));
            const auto kf = static_cast<std::size_t>(index(axialMap[static_cast<std::size_t>(I)], 2 * J));
            c.userKind_[kc] = userKind_[kf];
            c.userPressure_[kc] = userPressure_[kf];
        }
    c.refreshKinds();
    if (!arcs_.empty()) c.restrictToArcs(arcs_);
    return c;
}

void FilmGrid::refreshKinds() {
    const auto n = static_cast<std::size_t>(size());
    kind_.assign(n, NodeKind::Film);
    fixedPressure_.assign(n, ambient_);
    auto fixEdge = [&](Edge e, int i0, int i1, int j0, int j1) {
        const EdgeSpec& s = edges_[static_cast<int>(e)];
        if (s.condition != EdgeCondition::Pressure) return;
        for (int i = i0; i <= i1; ++i)
            for (int j = j0; j <= j1; ++j) {
                const auto k = static_cast<std::size_t>(index(i, j));
                kind_[k] = NodeKind::Fixed;
                fixedPressure_[k] = s.pressure;
            }
    };
    const int ni = nAxial() - 1, nj = nTheta_ - 1;
    if (!periodic_) {
        fixEdge(Edge::ArcStart, 0, ni, 0, 0);
        fixEdge(Edge::ArcEnd, 0, ni, nj, nj);
    }
    fixEdge(Edge::AxialLow, 0, 0, 0, nj);
    fixEdge(Edge::AxialHigh, ni, ni, 0, nj);
    for (std::size_t k = 0; k < n; ++k) {
        if (userKind_[k] == NodeKind::Fixed) {
            kind_[k] = NodeKind::Fixed;
            fixedPressure_[k] = userPressure_[k];
        } else if (userKind_[k] == NodeKind::Void) {
            kind_[k] = NodeKind::Void;
            fixedPressure_[k] = ambient_;
        }
    }
}

}  // namespace flexehd::lube
