#pragma once
// Modal damping ratios of a reduced body: one ratio for all elastic modes, or ratios per
// frequency band (as measured damping is usually given). Rigid-body modes get none.
#include <string>
#include <vector>

#include "modal/ReducedBody.hpp"

namespace flexehd::modal {

struct DampingBand {
    double upToHz = 0.0;  ///< the band covers elastic modes with f <= upToHz (above the previous band)
    double ratio = 0.0;   ///< ζ, -
};

/// Parses "FMAX:ZETA" (Hz, -); throws std::invalid_argument naming the text.
DampingBand parseDampingBand(const std::string& text);

/// Sets body.dampingRatios: for each elastic mode the ratio of the first band (in order of
/// upToHz) whose upToHz is >= its frequency, `defaultRatio` above all bands, 0 for
/// rigid-body modes.
void assignModalDamping(ReducedBody& body, double defaultRatio, std::vector<DampingBand> bands);

}  // namespace flexehd::modal
