#pragma once
// RunProgress: the progress lines of a run (flexehd run, docs/coupling.md §1 "Cycles and
// periodicity"): elapsed time, the time of the current cycle so far and its estimate, and —
// once two periodicity errors show a trend — an estimate of the cycles and time the run still
// needs. Formatting only: the step loop hands it the state and reads back lines.
#include <optional>
#include <string>

namespace flexehd::cosim {

class RunProgress {
public:
    RunProgress(int maxCycles, double periodicityTolerance);

    /// Call when cycle `cycle` (1-based) starts, `elapsed` s after the run started.
    void startCycle(int cycle, double elapsed);
    /// A line for a step: `fraction` of the current cycle done (0…1), the state in SI units.
    std::string stepLine(double crankDeg, double fraction, double elapsed, double lateral, double tilt,
                         int iterations, double stepDeg) const;
    /// The line that closes a cycle; `periodicityError` empty after the first cycle.
    std::string cycleDoneLine(double elapsed, std::optional<double> periodicityError);

    /// Cycles the run is expected to need beyond the current one, from the last two periodicity
    /// errors' ratio (geometric convergence), capped by the cycles left; empty without a trend.
    std::optional<int> cyclesLeftEstimate() const;

private:
    int maxCycles_;
    double tolerance_;
    int cycle_ = 0;
    double cycleStart_ = 0.0, lastCycleSeconds_ = 0.0;
    double previousError_ = -1.0, lastError_ = -1.0;
};

}  // namespace flexehd::cosim
