#pragma once
// SkirtOilExchange: how the skirt's mass-conserving film and the liner's oil layer trade oil over
// a step (docs/coupling.md §6). In the liner frame the skirt's cover [low, high] moves with the
// liner offset; per grid column:
//  * the advancing edge covers a strip of the layer; its volume V is what the liner brings in,
//    so the edge's inlet film fraction makes the Couette inflow (|U|/2) h_f L φ_in carry V/Δt
//    (φ_in ≤ 1: a thicker layer floods the inlet);
//  * what the film does not take in (V − inflow Δt: the excess of a flooded inlet, and any
//    back-flow out of that edge) stays on the liner as a bank just in front of the edge, carried
//    along and left where the skirt turns;
//  * the trailing edge leaves its outflow on the strip it uncovers (the steady Couette film
//    leaves φh/2 on the liner: the half that moves with the liner; the piston's half stays with
//    the skirt), or, with the edge at rest, just outside it;
//  * below a depth the replenishment restores the layer outside the skirt to the supply layer.
// Every rule moves volume; the sum of liner and film oil changes only by the replenishment and
// the leakage at the skirt's sides.
#include "cosim/case/EngineCase.hpp"
#include "cosim/oil/LinerOilLayer.hpp"
#include "lube/FilmGrid.hpp"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace flexehd::cosim {

/// What the exchange of one step moved (m³).
struct OilExchangeVolumes {
    double replenished = 0.0;  ///< added by the replenishment (< 0: removed)
    double shortfall = 0.0;    ///< drawn by the film beyond the layer there
};

class SkirtOilExchange {
public:
    /// zLow, zHigh: the liner-frame range of the skirt's edges over the cycle (m); zReplenish:
    /// liner-frame z below which the layer is restored (−∞: never).
    SkirtOilExchange(const lube::FilmGrid& grid, const OilSupplySpec& supply, double zLow, double zHigh,
                     double zReplenish);

    /// The supply layer at liner-frame z (m).
    double supplyThickness(double z) const;
    /// The layer at the start of the run, the skirt at liner offset `offset`.
    std::shared_ptr<const LinerOilLayer> initialLayer(double offset) const;
    /// The film fraction at the start: the layer the skirt stands on, φ = min(1, 2 t / h) at
    /// each Film node.
    Eigen::VectorXd initialFraction(const Eigen::VectorXd& h, double offset) const;

    /// The inlet film fraction of each edge node (index = grid node; other nodes untouched) for
    /// the step from offset `before` to `after` of length dt (s) with the liner sliding at U
    /// (m/s, grid frame) and the film thickness h.
    void inletFractions(const LinerOilLayer& layer, double before, double after, double dt, double U,
                        const Eigen::VectorXd& h, std::vector<double>& fraction) const;
    /// The layer after the step: flows (m³/s per column) into the film through the lower and the
    /// upper edge; the volumes the step moved besides.
    std::shared_ptr<const LinerOilLayer> advance(const LinerOilLayer& layer, double before, double after, double dt,
                                                 const Eigen::VectorXd& inflowLow, const Eigen::VectorXd& inflowHigh,
                                                 OilExchangeVolumes& moved) const;

    /// The cover of the skirt at liner offset `offset`.
    SkirtCover cover(double offset) const { return {offset + zEdge_[0], offset + zEdge_[1]}; }
    double replenishBelow() const { return zReplenish_; }

private:
    const lube::FilmGrid& grid_;
    OilSupplySpec supply_;
    double zLow_, zHigh_, zReplenish_;
    double zEdge_[2];            // piston-frame z of the lower and upper edge rows
    std::vector<double> width_;  // m per column (0: not on the skirt)
};

}  // namespace flexehd::cosim
