#pragma once
// A simulation run whose step records and snapshots a test keeps.
#include "cosim/coupling/PistonSimulation.hpp"

#include <vector>

namespace flexehd::test {

struct RecordedRun {
    std::vector<cosim::StepRecord> steps;
    std::vector<cosim::Snapshot> snapshots;
};

/// Runs sim over spanDeg degrees from its start, keeping every step record and snapshot.
inline RecordedRun recordRun(cosim::PistonSimulation& sim, double spanDeg) {
    RecordedRun r;
    cosim::SimulationCallbacks cb;
    cb.onStep = [&](const cosim::StepRecord& s) { r.steps.push_back(s); };
    cb.onSnapshot = [&](const cosim::Snapshot& s) { r.snapshots.push_back(s); };
    sim.run(cb, spanDeg);
    return r;
}

}  // namespace flexehd::test
