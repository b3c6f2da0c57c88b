#pragma once
// RunObserver: what follows a run from outside the master (docs/coupling.md §1, "Observers"):
// every accepted step with every contact's film, its history row, every snapshot, and the end of
// each cycle. The results — history.csv, the VTK series, the wear maps — subscribe with
// PistonSimulation::addObserver instead of being built into the cycle loop.
#include "cosim/coupling/Snapshot.hpp"
#include "cosim/coupling/StepRecord.hpp"
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

/// The end of a cycle as the observers see it.
struct CycleEnd {
    int cycle = 0;      ///< 1-based
    int snapshots = 0;  ///< the snapshots it took
    bool last = false;  ///< the run's last cycle (periodic, the cycle limit or the run's span)
    /// The cycle's history rows as the periodicity and the cycle figures see them: from the
    /// second cycle on, the first is the previous cycle's last state.
    const std::vector<StepRecord>* records = nullptr;
};

class RunObserver {
public:
    virtual ~RunObserver() = default;
    /// After each accepted step, in order.
    virtual void stepAccepted(const AcceptedStep& /*step*/) {}
    /// The history row of each accepted step, after stepAccepted.
    virtual void recorded(const StepRecord& /*row*/) {}
    /// Each snapshot as it is taken (every output.vtk_every_deg of every cycle).
    virtual void snapshotTaken(const Snapshot& /*snapshot*/) {}
    /// After the last step of each cycle (also a cycle cut short by the run's span), once its
    /// periodicity is known.
    virtual void cycleEnded(const CycleEnd& /*end*/) {}
};

}  // namespace flexehd::cosim
