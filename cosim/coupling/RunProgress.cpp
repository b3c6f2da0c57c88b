#include "cosim/coupling/RunProgress.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

namespace flexehd::cosim {

RunProgress::RunProgress(int maxCycles, double periodicityTolerance)
    : maxCycles_(maxCycles), tolerance_(periodicityTolerance) {}

void RunProgress::startCycle(int cycle, double elapsed) {
    cycle_ = cycle;
    cycleStart_ = elapsed;
}

std::string RunProgress::stepLine(double crankDeg, double fraction, double elapsed, double lateral, double tilt,
                                  int iterations, double stepDeg) const {
    const double inCycle = elapsed - cycleStart_;
    std::string eta;
    if (fraction > 0.02) {
        const double estimate = inCycle / fraction;
        eta = fmt::format(", this cycle {:.1f} of ~{:.1f} s ({:.1f} s left)", inCycle, estimate,
                          std::max(0.0, estimate - inCycle));
    }
    return fmt::format("cycle {} (at most {})  crank {:6.1f} deg  e {:+7.2f} um  tilt {:+6.3f} mrad  "
                       "iterations {:2d}  step {} deg  | {:.1f} s{}",
                       cycle_, maxCycles_, crankDeg, lateral * 1e6, tilt * 1e3, iterations,
                       stepDeg >= 0.01 ? fmt::format("{:.3f}", stepDeg) : fmt::format("{:.2g}", stepDeg), elapsed, eta);
}

std::optional<int> RunProgress::cyclesLeftEstimate() const {
    const int left = maxCycles_ - cycle_;
    if (lastError_ < 0.0 || left <= 0) return std::nullopt;
    if (lastError_ <= tolerance_) return 0;
    if (previousError_ <= 0.0) return std::nullopt;
    const double ratio = lastError_ / previousError_;
    if (!(ratio < 1.0)) return left;  // not converging: the run goes on to max_cycles
    const double needed = std::ceil(std::log(tolerance_ / lastError_) / std::log(ratio) - 1e-9);  // 2.0000000001 is 2
    return int(std::min<double>(left, std::max(1.0, needed)));
}

std::string RunProgress::cycleDoneLine(double elapsed, std::optional<double> periodicityError) {
    lastCycleSeconds_ = elapsed - cycleStart_;
    std::string line = fmt::format("cycle {} done in {:.1f} s ({:.1f} s elapsed)", cycle_, lastCycleSeconds_, elapsed);
    if (!periodicityError) return line + (cycle_ < maxCycles_ ? "; periodicity is judged from cycle 2 on" : "");
    previousError_ = lastError_;
    lastError_ = *periodicityError;
    line += fmt::format(": periodicity error {:.3g} m (tolerance {:.3g} m)", lastError_, tolerance_);
    if (lastError_ <= tolerance_) return line + ", periodic";
    const std::optional<int> more = cyclesLeftEstimate();
    if (cycle_ >= maxCycles_) return line + ", NOT periodic after time.max_cycles";
    if (!more) return line;
    return line + fmt::format("; about {} more cycle{} (~{:.0f} s){}", *more, *more == 1 ? "" : "s",
                              *more * lastCycleSeconds_, cycle_ + *more >= maxCycles_ ? ", up to time.max_cycles" : "");
}

std::string formatDuration(double s) {
    if (s < 120.0) return fmt::format("{:.0f} s", s);
    if (s < 7200.0) return fmt::format("{:.0f} min", s / 60.0);
    if (s < 2.0 * 86400.0) return fmt::format("{:.1f} h", s / 3600.0);
    if (s < 2.0 * 365.0 * 86400.0) return fmt::format("{:.0f} days", s / 86400.0);
    return fmt::format("{:.3g} years", s / (365.0 * 86400.0));
}

ProgressPacer::ProgressPacer(int maxCycles, double startDeg, std::function<void(const std::string&)> print,
                             double intervalSeconds)
    : print_(std::move(print)), maxCycles_(maxCycles), startDeg_(startDeg), interval_(intervalSeconds) {}

void ProgressPacer::recorded(const StepRecord& row) {
    if (!print_) return;
    if (const auto line = stepAccepted(row.cycle, row.crankDeg, row.stepDeg, clock_.seconds())) print_(*line);
}

void ProgressPacer::linePrinted(double elapsed) { lastLine_ = std::max(lastLine_, elapsed); }

std::optional<std::string> ProgressPacer::stepAccepted(int cycle, double crankDeg, double stepDeg, double elapsed) {
    if (cycle != cycle_) {  // the cycle started with the previous step's end
        cycle_ = cycle;
        stepsInCycle_ = 0;
        cycleStart_ = lastStep_;
    }
    ++stepsInCycle_;
    lastStep_ = elapsed;
    if (elapsed - lastLine_ < interval_) return std::nullopt;
    lastLine_ = elapsed;
    double done = std::fmod(crankDeg - startDeg_ + 720.0, 720.0);  // degrees of the cycle behind
    if (done < 1e-9 && stepsInCycle_ > 1) done = 720.0;
    const double inCycle = elapsed - cycleStart_;
    std::string eta;
    if (done > 0.0 && inCycle > 0.0) {
        const double left = (720.0 - done) * inCycle / done;
        eta = fmt::format(", ~{} to the cycle's end at this pace", formatDuration(left));
    }
    return fmt::format("cycle {} (at most {})  crank {:.6g} deg  {} steps this cycle ({:.3g} % of it)  step {:.3g} deg  "
                       "| {:.1f} s{}",
                       cycle_, maxCycles_, crankDeg, stepsInCycle_, 100.0 * done / 720.0, stepDeg, elapsed, eta);
}

}  // namespace flexehd::cosim
