#pragma once
// StarvedStepTolerance: the warning for a case on the liner's oil layer whose step error
// tolerances are looser than that layer's defaults (docs/coupling.md §1, "Step-size control"): a
// starved skirt's crossings of its clearance need the tighter ones for its cycles to repeat, and
// a value copied from a flooded case (hd.yaml sets the general defaults explicitly) silently
// takes them away.
#include <optional>
#include <string>

#include "cosim/case/EngineCase.hpp"

namespace flexehd::cosim {

/// The warning's text, naming the keys, their values and the defaults; none when the supply is
/// flooded or the tolerances are at most the liner layer's.
std::optional<std::string> looseStarvedStepTolerance(const EngineCase& c);

}  // namespace flexehd::cosim
