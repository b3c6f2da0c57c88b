#pragma once
// LinerOffsetRange: where the piston frame sits on the liner over a revolution — the extremes of
// the liner offset (the liner-frame z of the piston frame's origin), sampled every 0.25° of crank
// angle. A contact's edge at piston-frame z sweeps [low + z, high + z].
#include <functional>

namespace flexehd::cosim {

struct LinerOffsetRange {
    double low = 0.0, high = 0.0;  ///< m
};

/// linerOffset(crank angle in degrees): the liner offset (m).
LinerOffsetRange linerOffsetRange(const std::function<double(double)>& linerOffset);

}  // namespace flexehd::cosim
