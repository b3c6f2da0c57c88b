#pragma once
// RunObserver: what follows a run from outside the master (docs/coupling.md §1, "Observers"):
// every accepted step with every contact's film, and the end of each cycle. Results that are not
// the master's business — the wear maps, say — subscribe with PistonSimulation::addObserver
// instead of being built into the cycle loop.
#include "cosim/coupling/StepState.hpp"

namespace flexehd::cosim {

/// An accepted step as the observers see it.
struct AcceptedStep {
    const StepState& state;            ///< the accepted state (its contacts' states in films)
    const StepEvaluation& evaluation;  ///< its iterate: every contact's film and loads
    int cycle = 0;                     ///< 1-based
    double stepDeg = 0.0;              ///< °, the step that reached it
    double seconds = 0.0;              ///< s, the same step
};

class RunObserver {
public:
    virtual ~RunObserver() = default;
    /// After each accepted step, in order.
    virtual void stepAccepted(const AcceptedStep& /*step*/) {}
    /// After the last step of each cycle (also a cycle cut short by the run's span).
    virtual void cycleEnded(int /*cycle*/) {}
};

}  // namespace flexehd::cosim
