#include "cosim/contact/LinerOffsetRange.hpp"

#include <algorithm>

namespace flexehd::cosim {

LinerOffsetRange linerOffsetRange(const std::function<double(double)>& linerOffset) {
    LinerOffsetRange r{linerOffset(0.0), linerOffset(0.0)};
    for (int k = 1; k <= 1440; ++k) {
        const double s = linerOffset(0.25 * k);
        r.low = std::min(r.low, s);
        r.high = std::max(r.high, s);
    }
    return r;
}

}  // namespace flexehd::cosim
