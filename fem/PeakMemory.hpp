#pragma once
// peakMemoryMiB: the process's peak resident memory so far (MiB), as every command reports it.
#include <sys/resource.h>

namespace flexehd::fem {

inline double peakMemoryMiB() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss / 1024.0;  // Linux reports KiB
}

}  // namespace flexehd::fem
