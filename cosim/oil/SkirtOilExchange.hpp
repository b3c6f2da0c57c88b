#pragma once
// SkirtOilExchange: how the skirt's mass-conserving film and the liner's oil layer trade oil over
// a step (docs/coupling.md §6): the skirt as a cover of the master's layer (LinerOil). In the
// liner frame the skirt's cover [low, high] moves with the liner offset; per grid column:
//  * the advancing edge covers a strip of the layer; its volume V is what the liner brings in,
//    so the edge's inlet film fraction makes the Couette inflow (|U|/2) h_f L φ_in carry V/Δt
//    (φ_in ≤ 1: a thicker layer floods the inlet);
//  * what the film does not take in (V − inflow Δt: the excess of a flooded inlet, and any
//    back-flow out of that edge) stays on the liner as a bank just in front of the edge, carried
//    along and left where the skirt turns;
//  * the trailing edge leaves its outflow on the strip it uncovers (the steady Couette film
//    leaves φh/2 on the liner: the half that moves with the liner; the piston's half stays with
//    the skirt), or, with the edge at rest, just outside it.
// Every rule moves volume; the sum of liner and film oil changes only by the replenishment (the
// master's, LinerOil) and the leakage at the skirt's sides. The layer's other covers are the
// other contacts': the skirt's strips, banks and deposits lie outside all of them.
#include "cosim/case/EngineCase.hpp"
#include "cosim/oil/LinerOil.hpp"
#include "lube/FilmGrid.hpp"

#include <Eigen/Core>

#include <vector>

namespace flexehd::cosim {

class SkirtOilExchange {
public:
    /// zLow, zHigh: the liner-frame range of the skirt's edges over the cycle (m).
    SkirtOilExchange(const lube::FilmGrid& grid, const OilSupplySpec& supply, double zLow, double zHigh);

    /// What the skirt needs of the liner's layer: its reach, the grid's axial spacing as the
    /// cell, the grid columns' widths.
    LinerFootprint footprint() const;
    /// The film fraction at the start: the supply layer the skirt stands on, φ = min(1, 2 t / h)
    /// at each Film node.
    Eigen::VectorXd initialFraction(const Eigen::VectorXd& h, double offset) const;

    /// The inlet film fraction of each edge node (index = grid node; other nodes untouched) for
    /// the step from offset `before` to `after` of length dt (s) with the liner sliding at U
    /// (m/s, grid frame) and the film thickness h; `covers`: every contact's band at the step's
    /// start.
    void inletFractions(const LinerOilLayer& layer, const LinerCovers& covers, double before, double after, double dt,
                        double U, const Eigen::VectorXd& h, std::vector<double>& fraction) const;
    /// The skirt's trade of the step from offset `before` to `after`: flows (m³/s per column)
    /// into the film through the lower and the upper edge. Adds what the film drew beyond the
    /// layer to ex.shortfall.
    void exchange(LinerOilExchange& ex, double before, double after, const Eigen::VectorXd& inflowLow,
                  const Eigen::VectorXd& inflowHigh) const;

private:
    const lube::FilmGrid& grid_;
    OilSupplySpec supply_;
    double zLow_, zHigh_;
    double zEdge_[2];            // piston-frame z of the lower and upper edge rows
    std::vector<double> width_;  // m per column (0: not on the skirt)
};

}  // namespace flexehd::cosim
