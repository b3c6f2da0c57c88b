#pragma once
// StepSizeControl: the crank-angle step of the co-simulation (docs/coupling.md §1, "Step-size
// control").
// A step is planned from the running step size, shortened to land on the next snapshot angle
// (output.vtk_every_deg) or the cycle's end; its local error is half the difference between the
// corrector (the step's solution) and the predictor x + Δt v + ½Δt² a, against
// time.lateral_tolerance and time.tilt_tolerance. A rejected step shrinks the size by
// 0.9 r^(−1/3) (at least to 0.2×; a failed iteration to 0.25×), an accepted one grows it by the
// same factor (at most 2×, within time.max_step_deg).
#include "cosim/case/EngineCase.hpp"
#include "cosim/coupling/StepState.hpp"

namespace flexehd::cosim {

class StepSizeControl {
public:
    /// secondsPerDegree: of the crank.
    StepSizeControl(const TimeSpec& time, double snapshotEveryDeg, double secondsPerDegree);

    /// The next step from crankDeg (°, continuous) within the cycle [cycleStart, cycleEnd]: the
    /// running size, shortened to land on the next snapshot angle or the cycle's end; atSnapshot
    /// when it lands on a snapshot angle.
    double planned(double crankDeg, double cycleStart, double cycleEnd, bool& atSnapshot) const;
    /// The local error estimate of the step s → n of stepDeg in units of its tolerance.
    double errorRatio(const StepState& s, const StepState& n, double stepDeg) const;
    /// After the step of stepDeg was rejected (its iteration failed, or its error ratio > 1):
    /// the shorter size; false when it fell below time.min_step_deg.
    bool rejected(double stepDeg, bool converged, double ratio);
    /// After the step of stepDeg was accepted with its error ratio: the next size.
    void accepted(double stepDeg, double ratio);

private:
    const TimeSpec& time_;
    double every_, secondsPerDegree_;
    double size_;  // °, the running step size (unclipped by snapshots and the cycle's end)
};

}  // namespace flexehd::cosim
