// LinerCovers: the union of the contacts' bands on the liner (docs/coupling.md §6).
#include "cosim/oil/LinerCovers.hpp"

#include <algorithm>

namespace flexehd::cosim {

LinerCovers::LinerCovers(std::vector<LinerCover> bands) {
    std::sort(bands.begin(), bands.end(), [](const LinerCover& a, const LinerCover& b) { return a.low < b.low; });
    for (const LinerCover& b : bands) {
        if (!bands_.empty() && b.low <= bands_.back().high)
            bands_.back().high = std::max(bands_.back().high, b.high);
        else
            bands_.push_back(b);
    }
}

double LinerCovers::covered(double a, double b) const {
    double length = 0.0;
    for (const LinerCover& c : bands_) length += std::max(0.0, std::min(b, c.high) - std::max(a, c.low));
    return length;
}

}  // namespace flexehd::cosim
