#pragma once
// LinerOil: the liner's oil layer as the co-simulation master owns it (docs/coupling.md §6, "The
// liner's oil layer and its covers"). One LinerOilLayer over the reach of every contact that
// runs on it; at each step the contacts' bands are its covers. An accepted step trades oil in two
// stages: each contact exchanges with the layer at its edges (what its leading edge covers, less
// what its film takes in, stays as a bank in front of it; what its trailing edge leaves lies on
// the strip it uncovers), then the replenishment restores the layer below its depth. The oil on
// the liner, the replenished volume and the films' shortfall are the master's, over all covers.
#include "cosim/case/EngineCase.hpp"
#include "cosim/oil/LinerCovers.hpp"
#include "cosim/oil/LinerOilLayer.hpp"

#include <functional>
#include <memory>
#include <vector>

namespace flexehd::cosim {

/// What a contact on the liner's oil layer needs of it: the liner-frame z range its edges sweep
/// over a revolution (m), the cell length along z (m) and the width of each θ column (m; 0 for a
/// column it does not reach).
struct LinerFootprint {
    double zLow = 0.0, zHigh = 0.0, cell = 0.0;
    std::vector<double> width;
};

/// The liner's oil at an accepted step.
struct LinerOilState {
    std::shared_ptr<const LinerOilLayer> layer;  ///< null: no contact runs on a liner layer
    LinerCovers covers;        ///< the contacts' bands at the step
    double replenished = 0.0;  ///< m³ added by the replenishment since the start (< 0: removed)
    double shortfall = 0.0;    ///< m³ the films drew beyond the layer since the start (stays 0)
};

/// A step's trade of the contacts with the layer: each reads the layer as it was at the step's
/// start and writes into the next one.
struct LinerOilExchange {
    const LinerOilLayer& was;
    LinerOilLayer& next;
    const LinerCovers& before;  ///< every contact's band at the step's start
    const LinerCovers& after;   ///< and at its end
    double dt = 0.0;            ///< s
    double shortfall = 0.0;     ///< m³ drawn beyond the layer (each contact adds its own)
};

class LinerOil {
public:
    /// The layer over the union of the footprints with 8 cells of margin on either side, the
    /// finest of their cells and the footprints' columns (every footprint has as many; a column's
    /// width the widest any footprint gives it);
    /// zReplenish: the liner-frame z below which the replenishment restores the supply layer
    /// (−∞: never).
    LinerOil(const OilSupplySpec& supply, const std::vector<LinerFootprint>& footprints, double zReplenish);

    /// The supply layer at the start, the contacts at `covers`.
    LinerOilState initial(const LinerCovers& covers) const;
    /// The oil after an accepted step of dt (s) that moved the covers to `after`: exchange lets
    /// the contacts trade with the layer, then the replenishment.
    LinerOilState advance(const LinerOilState& now, const LinerCovers& after, double dt,
                          const std::function<void(LinerOilExchange&)>& exchange) const;
    /// The oil on the liner outside the covers (m³; 0 without a layer).
    static double volume(const LinerOilState& s) { return s.layer ? s.layer->volume(s.covers) : 0.0; }

private:
    OilSupplySpec supply_;
    double zLow_, zHigh_, cell_, zReplenish_;
    std::vector<double> width_;
};

}  // namespace flexehd::cosim
