// SkirtOilExchange: the oil the skirt's film and the liner's layer trade over a step, per grid
// column and edge (docs/coupling.md §6).
#include "cosim/oil/SkirtOilExchange.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace flexehd::cosim {

namespace {

constexpr int kMarginCells = 8;  // liner cells beyond the skirt's reach on either side

}  // namespace

SkirtOilExchange::SkirtOilExchange(const lube::FilmGrid& grid, const OilSupplySpec& supply, double zLow,
                                   double zHigh, double zReplenish)
    : grid_(grid), supply_(supply), zLow_(zLow), zHigh_(zHigh), zReplenish_(zReplenish) {
    zEdge_[0] = grid.z(0);
    zEdge_[1] = grid.z(grid.nAxial() - 1);
    width_.assign(static_cast<std::size_t>(grid.nTheta()), 0.0);
    for (int j = 0; j < grid.nTheta(); ++j)
        if (grid.kind(grid.index(0, j)) != lube::NodeKind::Void)
            width_[static_cast<std::size_t>(j)] = grid.radius() * grid.angularWidth(j);
}

double SkirtOilExchange::supplyThickness(double z) const {
    const std::vector<OilLayerPoint>& t = supply_.layer;
    if (t.empty()) return 0.0;
    const double depth = -z;
    if (depth <= t.front().depth) return t.front().thickness;
    if (depth >= t.back().depth) return t.back().thickness;
    const auto hi = std::upper_bound(t.begin(), t.end(), depth,
                                     [](double d, const OilLayerPoint& p) { return d < p.depth; });
    const auto lo = hi - 1;
    const double w = (depth - lo->depth) / (hi->depth - lo->depth);
    return lo->thickness + w * (hi->thickness - lo->thickness);
}

std::shared_ptr<const LinerOilLayer> SkirtOilExchange::initialLayer(double) const {
    const double cell = (zEdge_[1] - zEdge_[0]) / (grid_.nAxial() - 1);
    auto layer = std::make_shared<LinerOilLayer>(zLow_ - kMarginCells * cell, zHigh_ + kMarginCells * cell, cell, width_);
    layer->fill([this](double z) { return supplyThickness(z); });
    return layer;
}

Eigen::VectorXd SkirtOilExchange::initialFraction(const Eigen::VectorXd& h, double offset) const {
    Eigen::VectorXd phi = Eigen::VectorXd::Ones(grid_.size());
    for (int k = 0; k < grid_.size(); ++k)
        if (grid_.kind(k) == lube::NodeKind::Film)
            phi[k] = std::min(1.0, 2.0 * supplyThickness(offset + grid_.z(grid_.axialIndex(k))) / h[k]);
    return phi;
}

void SkirtOilExchange::inletFractions(const LinerOilLayer& layer, double before, double after, double dt, double U,
                                      const Eigen::VectorXd& h, std::vector<double>& fraction) const {
    const int n = grid_.nAxial();
    const SkirtCover cb = cover(before);
    for (int e = 0; e < 2; ++e) {
        const int out = e == 0 ? -1 : 1, ie = e == 0 ? 0 : n - 1, iin = e == 0 ? 1 : n - 2;
        const double a = before + zEdge_[e], b = after + zEdge_[e];
        const bool advancing = (b - a) * out > 0.0;
        for (int j = 0; j < grid_.nTheta(); ++j) {
            const double w = width_[static_cast<std::size_t>(j)];
            if (!(w > 0.0)) continue;
            const int k = grid_.index(ie, j);
            const double hf = 0.5 * (h[k] + h[grid_.index(iin, j)]);
            const double capacity = 0.5 * std::abs(U) * hf * w;  // Couette inflow of a full film (m³/s)
            double phi = 0.0;
            if (advancing && capacity > 0.0)
                phi = layer.volume(j, std::min(a, b), std::max(a, b), cb) / dt / capacity;
            else
                phi = 2.0 * layer.thicknessAt(j, a + out * 1e-9 * layer.cellLength()) / hf;
            fraction[static_cast<std::size_t>(k)] = std::clamp(phi, 0.0, 1.0);
        }
    }
}

std::shared_ptr<const LinerOilLayer> SkirtOilExchange::advance(const LinerOilLayer& layer, double before, double after,
                                                               double dt, const Eigen::VectorXd& inflowLow,
                                                               const Eigen::VectorXd& inflowHigh,
                                                               OilExchangeVolumes& moved) const {
    auto next = std::make_shared<LinerOilLayer>(layer);
    const SkirtCover cb = cover(before), ca = cover(after);
    moved = {};
    for (int e = 0; e < 2; ++e) {
        const int out = e == 0 ? -1 : 1;
        const double a = before + zEdge_[e], b = after + zEdge_[e];
        const double lo = std::min(a, b), hi = std::max(a, b);
        const bool advancing = (b - a) * out > 0.0;
        const Eigen::VectorXd& q = e == 0 ? inflowLow : inflowHigh;
        for (int j = 0; j < grid_.nTheta(); ++j) {
            if (!(width_[static_cast<std::size_t>(j)] > 0.0)) continue;
            if (advancing) {  // what it covered, less what the film took in: the bank in front
                const double bank = layer.volume(j, lo, hi, cb) - q[j] * dt;
                moved.shortfall += next->addOutside(j, b, out, bank, ca);
            } else {          // the outflow, on the strip it uncovered
                const double left = -q[j] * dt;
                if (hi > lo && left >= 0.0)
                    next->deposit(j, lo, hi, left, cb);
                else
                    moved.shortfall += next->addOutside(j, b, out, left, ca);
            }
        }
    }
    if (std::isfinite(zReplenish_))
        moved.replenished = next->restore(zReplenish_, [this](double z) { return supplyThickness(z); }, ca);
    return next;
}

}  // namespace flexehd::cosim
