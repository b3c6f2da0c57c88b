// StepSizeControl: planning, error estimate, shrinking and growing of the crank-angle step
// (docs/coupling.md §1).
#include "cosim/coupling/StepSizeControl.hpp"

#include <algorithm>
#include <cmath>

namespace flexehd::cosim {

StepSizeControl::StepSizeControl(const TimeSpec& time, double snapshotEveryDeg, double secondsPerDegree)
    : time_(time), every_(snapshotEveryDeg), secondsPerDegree_(secondsPerDegree), size_(std::min(time.maxStepDeg, 0.1)) {}

double StepSizeControl::planned(double crankDeg, double cycleStart, double cycleEnd, bool& atSnapshot) const {
    double step = std::min(size_, cycleEnd - crankDeg);
    atSnapshot = false;
    if (every_ > 0.0) {
        // The next snapshot angle; those closer than time.min_step_deg to the present state
        // are skipped (landing on them would need a step below the smallest allowed).
        double next = cycleStart + every_ * (std::floor((crankDeg - cycleStart) / every_ + 1e-9) + 1.0);
        if (next - crankDeg < time_.minStepDeg)
            next += every_ * std::ceil((time_.minStepDeg - (next - crankDeg)) / every_);
        if (next - crankDeg <= step + 1e-12) {
            step = next - crankDeg;
            atSnapshot = true;
        }
    }
    if (std::abs(crankDeg + step - cycleEnd) < 1e-9) atSnapshot = every_ > 0.0;
    return step;
}

double StepSizeControl::errorRatio(const StepState& s, const StepState& n, double stepDeg) const {
    const double dt = stepDeg * secondsPerDegree_;
    const Eigen::Vector2d pred = s.x + dt * s.v + 0.5 * dt * dt * s.a;
    const Eigen::Vector2d err = 0.5 * (n.x - pred).cwiseAbs();
    return std::max(err[0] / time_.lateralTolerance, err[1] / time_.tiltTolerance);
}

bool StepSizeControl::rejected(double stepDeg, bool converged, double ratio) {
    size_ = converged ? stepDeg * std::max(0.2, 0.9 * std::pow(ratio, -1.0 / 3.0)) : 0.25 * stepDeg;
    return !(size_ < time_.minStepDeg);
}

void StepSizeControl::accepted(double stepDeg, double ratio) {
    // Grow with the error ratio, from the unclipped step size.
    const double grow = ratio > 0.0 ? std::min(2.0, 0.9 * std::pow(ratio, -1.0 / 3.0)) : 2.0;
    size_ = std::min(time_.maxStepDeg, std::max(stepDeg, std::min(size_, time_.maxStepDeg)) * grow);
}

}  // namespace flexehd::cosim
