// StarvedStepTolerance: a liner-layer case's step tolerances against the layer's defaults (header).
#include "cosim/run/StarvedStepTolerance.hpp"

#include <fmt/format.h>

#include <numbers>

namespace flexehd::cosim {

std::optional<std::string> looseStarvedStepTolerance(const EngineCase& c) {
    if (c.lubricant.supply.model != OilSupplyModel::LinerLayer) return std::nullopt;
    const TimeSpec& t = c.time;
    const bool lateral = t.lateralTolerance > TimeSpec::kStarvedLateralTolerance;
    const bool tilt = t.tiltTolerance > TimeSpec::kStarvedTiltTolerance;
    if (!lateral && !tilt) return std::nullopt;
    const double deg = 180.0 / std::numbers::pi;
    std::string keys;
    if (lateral)
        keys = fmt::format("time.lateral_tolerance {:g} m (liner layer default {:g} m)", t.lateralTolerance,
                           TimeSpec::kStarvedLateralTolerance);
    if (tilt)
        keys += fmt::format("{}time.tilt_tolerance_deg {:.4g} (default {:.4g})", lateral ? " and " : "",
                            t.tiltTolerance * deg, TimeSpec::kStarvedTiltTolerance * deg);
    return fmt::format("{} on the liner's oil layer (lubricant.supply.model: liner_layer): a starved skirt's cycles "
                       "repeat only at the layer's tighter step tolerances (docs/coupling.md section 1); remove "
                       "the key to take the default",
                       keys);
}

}  // namespace flexehd::cosim
