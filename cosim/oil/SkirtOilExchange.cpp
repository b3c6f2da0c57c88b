// SkirtOilExchange: the oil the skirt's film and the liner's layer trade over a step, per grid
// column and edge (docs/coupling.md §6).
#include "cosim/oil/SkirtOilExchange.hpp"

#include "cosim/oil/EdgeTrade.hpp"
#include "cosim/oil/OilSupply.hpp"

#include <algorithm>
#include <cmath>

namespace flexehd::cosim {

SkirtOilExchange::SkirtOilExchange(const lube::FilmGrid& grid, const OilSupplySpec& supply, double zLow, double zHigh)
    : grid_(grid), supply_(supply), zLow_(zLow), zHigh_(zHigh) {
    zEdge_[0] = grid.z(0);
    zEdge_[1] = grid.z(grid.nAxial() - 1);
    width_.assign(static_cast<std::size_t>(grid.nTheta()), 0.0);
    for (int j = 0; j < grid.nTheta(); ++j)
        if (grid.kind(grid.index(0, j)) != lube::NodeKind::Void)
            width_[static_cast<std::size_t>(j)] = grid.radius() * grid.angularWidth(j);
}

LinerFootprint SkirtOilExchange::footprint() const {
    return {zLow_, zHigh_, (zEdge_[1] - zEdge_[0]) / (grid_.nAxial() - 1), width_};
}

Eigen::VectorXd SkirtOilExchange::initialFraction(const Eigen::VectorXd& h, double offset) const {
    Eigen::VectorXd phi = Eigen::VectorXd::Ones(grid_.size());
    for (int k = 0; k < grid_.size(); ++k)
        if (grid_.kind(k) == lube::NodeKind::Film)
            phi[k] = std::min(1.0, 2.0 * supplyLayerThickness(supply_, offset + grid_.z(grid_.axialIndex(k))) / h[k]);
    return phi;
}

void SkirtOilExchange::inletFractions(const LinerOilLayer& layer, const LinerCovers& covers, double before,
                                      double after, double dt, double U, const Eigen::VectorXd& h,
                                      std::vector<double>& fraction) const {
    const int n = grid_.nAxial();
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
                phi = layer.volume(j, std::min(a, b), std::max(a, b), covers) / dt / capacity;
            else
                phi = 2.0 * layer.thicknessAt(j, a + out * 1e-9 * layer.cellLength()) / hf;
            fraction[static_cast<std::size_t>(k)] = std::clamp(phi, 0.0, 1.0);
        }
    }
}

void SkirtOilExchange::exchange(LinerOilExchange& ex, double before, double after, const Eigen::VectorXd& inflowLow,
                                const Eigen::VectorXd& inflowHigh) const {
    tradeAtEdges(ex, before, after, {zEdge_[0], zEdge_[1]}, width_, inflowLow, inflowHigh);
}

}  // namespace flexehd::cosim
