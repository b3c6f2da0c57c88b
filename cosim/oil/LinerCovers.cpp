// LinerCovers: the union of the contacts' bands on the liner, column by column (docs/coupling.md §6).
#include "cosim/oil/LinerCovers.hpp"

#include <algorithm>

namespace flexehd::cosim {

LinerCovers::LinerCovers(std::vector<LinerCover> bands) : bands_(std::move(bands)) {
    std::sort(bands_.begin(), bands_.end(), [](const LinerCover& a, const LinerCover& b) { return a.low < b.low; });
}

double LinerCovers::covered(int j, double a, double b) const {
    // The union of the column's bands (ascending in low) within [a, b].
    double length = 0.0, reached = a;
    for (const LinerCover& c : bands_) {
        if (!c.covers(j)) continue;
        const double lo = std::max(c.low, reached), hi = std::min(c.high, b);
        if (hi > lo) length += hi - lo;
        reached = std::max(reached, std::min(c.high, b));
    }
    return length;
}

}  // namespace flexehd::cosim
