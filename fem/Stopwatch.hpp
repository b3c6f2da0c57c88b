#pragma once
// Stopwatch: wall-clock seconds since it was started or restarted — the one timer behind every
// timing a command or a run reports.
#include <chrono>

namespace flexehd::fem {

class Stopwatch {
public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}
    double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
    void restart() { start_ = std::chrono::steady_clock::now(); }
    /// Seconds since the start, and restarts (consecutive stages timed with one watch).
    double lap() {
        const double s = seconds();
        restart();
        return s;
    }

private:
    std::chrono::steady_clock::time_point start_;
};

}  // namespace flexehd::fem
