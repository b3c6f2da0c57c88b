#pragma once
// EdgeTrade: a cover's two edges trading with the liner's oil layer over a step (docs/coupling.md
// §6, "The liner's oil layer and its covers"), per θ column: the advancing edge's strip, less what
// the film took in through that edge, stays as a bank just in front of it; the retreating edge's
// outflow lies on the strip it uncovers (with no strip, is added to the layer just outside it); a
// net inflow through a retreating edge (the sliding reversed within the step) leaves that strip
// none and is taken from the layer outside it. Every rule moves volume: the strip a cover uncovers
// holds what the trade puts there, never what lay in its cells before it was covered.
#include "cosim/oil/LinerOil.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace flexehd::cosim {

/// The trade of the step from liner offset `before` to `after` (m) of a cover whose lower and
/// upper edges are at piston-frame z edges[0], edges[1]; inflowLow, inflowHigh: the film's flows in
/// through them per column (m³/s); columns of width 0 do not trade. Adds what the film drew beyond
/// the layer to ex.shortfall.
void tradeAtEdges(LinerOilExchange& ex, double before, double after, const std::array<double, 2>& edges,
                  const std::vector<double>& width, const Eigen::VectorXd& inflowLow, const Eigen::VectorXd& inflowHigh);

}  // namespace flexehd::cosim
