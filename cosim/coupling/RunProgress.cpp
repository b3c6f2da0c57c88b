#include "cosim/coupling/RunProgress.hpp"

#include <algorithm>
#include <cmath>

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
                       "iterations {:2d}  step {:.3f} deg  | {:.1f} s{}",
                       cycle_, maxCycles_, crankDeg, lateral * 1e6, tilt * 1e3, iterations, stepDeg, elapsed, eta);
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

}  // namespace flexehd::cosim
