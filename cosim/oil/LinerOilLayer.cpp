// LinerOilLayer: the liner's oil layer outside the contacts, cell by cell (docs/coupling.md §6).
#include "cosim/oil/LinerOilLayer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace flexehd::cosim {

namespace {

double overlap(double a0, double a1, double b0, double b1) { return std::max(0.0, std::min(a1, b1) - std::max(a0, b0)); }

}  // namespace

LinerOilLayer::LinerOilLayer(double zLow, double zHigh, double cell, std::vector<double> width)
    : zLow_(zLow), cell_(cell), nCells_(0), width_(std::move(width)) {
    if (!(cell > 0.0) || !(zHigh > zLow))
        throw std::invalid_argument("LinerOilLayer: needs zHigh > zLow and a positive cell length");
    nCells_ = static_cast<int>(std::ceil((zHigh - zLow) / cell));
    t_.assign(static_cast<std::size_t>(nCells_) * width_.size(), 0.0);
}

void LinerOilLayer::fill(const std::function<double(double)>& thickness) {
    for (int c = 0; c < nCells_; ++c) {
        const double tc = thickness(zLow_ + (c + 0.5) * cell_);
        for (int j = 0; j < columns(); ++j) t(c, j) = tc;
    }
}

double LinerOilLayer::uncovered(int c, int j, const LinerCovers& cover) const {
    const double z0 = zLow_ + c * cell_;
    return cell_ - cover.covered(j, z0, z0 + cell_);
}

int LinerOilLayer::cellOf(double z) const {
    return std::clamp(static_cast<int>(std::floor((z - zLow_) / cell_)), 0, nCells_ - 1);
}

double LinerOilLayer::volume(int j, double a, double b, const LinerCovers& cover) const {
    const double w = width(j);
    if (!(w > 0.0) || !(b > a)) return 0.0;
    double v = 0.0;
    for (int c = cellOf(a); c <= cellOf(b); ++c) {
        const double z0 = zLow_ + c * cell_, z1 = z0 + cell_;
        const double lo = std::max(a, z0), hi = std::min(b, z1);
        if (!(hi > lo)) continue;
        v += t(c, j) * (hi - lo - cover.covered(j, lo, hi)) * w;
    }
    return v;
}

double LinerOilLayer::volume(const LinerCovers& cover) const {
    double v = 0.0;
    for (int c = 0; c < nCells_; ++c)
        for (int j = 0; j < columns(); ++j)
            if (width(j) > 0.0) v += t(c, j) * uncovered(c, j, cover) * width(j);
    return v;
}

double LinerOilLayer::thicknessAt(int j, double z) const {
    if (z < zLow_ || z > zLow_ + nCells_ * cell_) return 0.0;
    return t(cellOf(z), j);
}

void LinerOilLayer::deposit(int j, double a, double b, double v, const LinerCovers& before) {
    const double w = width(j);
    if (!(w > 0.0) || !(b > a)) return;
    for (int c = cellOf(a); c <= cellOf(b); ++c) {
        const double z0 = zLow_ + c * cell_;
        const double o = overlap(a, b, z0, z0 + cell_);
        if (!(o > 0.0)) continue;
        const double u = uncovered(c, j, before);
        t(c, j) = (t(c, j) * u + v * (o / (b - a)) / w) / (u + o);
    }
}

double LinerOilLayer::addOutside(int j, double z, int outward, double v, const LinerCovers& cover) {
    const double w = width(j);
    if (!(w > 0.0) || v == 0.0) return 0.0;
    const double tiny = 1e-9 * cell_;
    for (int c = cellOf(z + outward * tiny); c >= 0 && c < nCells_; c += outward) {
        const double u = uncovered(c, j, cover);
        if (u < tiny) continue;
        if (v > 0.0) {
            t(c, j) += v / (w * u);
            return 0.0;
        }
        const double take = std::min(t(c, j) * u * w, -v);
        t(c, j) -= take / (w * u);
        v += take;
        if (v >= 0.0) return 0.0;
    }
    if (v > 0.0) throw std::logic_error("LinerOilLayer::addOutside: no liner cell outside the contact's edge");
    return -v;
}

double LinerOilLayer::restore(double zBelow, const std::function<double(double)>& thickness, const LinerCovers& cover) {
    double added = 0.0;
    for (int c = 0; c < nCells_; ++c) {
        const double zc = zLow_ + (c + 0.5) * cell_;
        if (!(zc < zBelow)) break;
        const double tc = thickness(zc);
        for (int j = 0; j < columns(); ++j) {
            const double u = uncovered(c, j, cover);
            if (!(width(j) > 0.0) || !(u > 0.0)) continue;
            added += (tc - t(c, j)) * u * width(j);
            t(c, j) = tc;
        }
    }
    return added;
}

Eigen::VectorXd LinerOilLayer::meanThickness(const LinerCovers& cover) const {
    Eigen::VectorXd m(static_cast<Eigen::Index>(t_.size()));
    for (int c = 0; c < nCells_; ++c)
        for (int j = 0; j < columns(); ++j)
            m[static_cast<Eigen::Index>(c) * columns() + j] = t(c, j) * uncovered(c, j, cover) / cell_;
    return m;
}

}  // namespace flexehd::cosim
