// The supply layer's thickness over the liner's depth (docs/case-file.md, `lubricant.supply`).
#include "cosim/oil/OilSupply.hpp"

#include <algorithm>

namespace flexehd::cosim {

double supplyLayerThickness(const OilSupplySpec& supply, double z) {
    const std::vector<OilLayerPoint>& t = supply.layer;
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

}  // namespace flexehd::cosim
