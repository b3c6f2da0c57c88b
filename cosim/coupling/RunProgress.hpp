#pragma once
// RunProgress: the progress lines of a run (flexehd run, docs/coupling.md §1 "Cycles and
// periodicity"): elapsed time, the time of the current cycle so far and its estimate, and —
// once two periodicity errors show a trend — an estimate of the cycles and time the run still
// needs. Formatting only: the step loop hands it the state and reads back lines.
#include <functional>
#include <optional>
#include <string>

#include "cosim/coupling/RunObserver.hpp"
#include "fem/Stopwatch.hpp"


namespace flexehd::cosim {

/// "3.5 h", "12 days": a duration for messages.
std::string formatDuration(double seconds);

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

/// The progress lines of a slow run: the step loop prints a line every 30° of crank, which tiny or
/// slow steps may take hours to cover. ProgressPacer, told of every accepted step and every line
/// printed, makes a line when `interval` s of wall time passed since the last one: the crank angle,
/// the steps of the cycle so far, the step and the time to the cycle's end at the pace since the
/// cycle started. As an observer of the run (PistonSimulation::addObserver) it prints these lines
/// through `print` on its own clock, started with it.
class ProgressPacer final : public RunObserver {
public:
    ProgressPacer(int maxCycles, double startDeg, std::function<void(const std::string&)> print = {},
                  double intervalSeconds = 10.0);

    /// Any progress line was printed `elapsed` s after the run started.
    void linePrinted(double elapsed);
    /// Any progress line was printed now (the pacer's clock).
    void linePrinted() { linePrinted(clock_.seconds()); }
    void recorded(const StepRecord& row) override;
    /// An accepted step of cycle `cycle` (1-based) reached `crankDeg` (0…720, as history.csv) by
    /// `stepDeg`, `elapsed` s after the run started: a line when one is due (then counted as
    /// printed), else empty.
    std::optional<std::string> stepAccepted(int cycle, double crankDeg, double stepDeg, double elapsed);

private:
    const fem::Stopwatch clock_;
    std::function<void(const std::string&)> print_;
    int maxCycles_;
    double startDeg_, interval_;
    double lastLine_ = 0.0;
    int cycle_ = 0;
    long stepsInCycle_ = 0;
    double cycleStart_ = 0.0, lastStep_ = 0.0;
};

}  // namespace flexehd::cosim
