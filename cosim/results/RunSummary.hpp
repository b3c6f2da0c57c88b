#pragma once
// RunSummary: summary.json of a run (docs/results-format.md) — the run's status, the cycle
// figures of its last cycle (CycleMetrics), the centred clearance, periodicity, solver
// statistics and timings. One table of (key, value) entries writes the document and is the list
// of keys `flexehd sweep` may collect (docs/sweep.md, `outputs`).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cosim/case/EngineCase.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "cosim/coupling/StepRecord.hpp"
#include "cosim/results/CycleSeries.hpp"
#include "cosim/wear/SkirtWear.hpp"

namespace flexehd::cosim {

struct RunSummaryInput {
    const EngineCase& c;
    const PistonSimulation& sim;
    const std::vector<StepRecord>& cycle;  ///< the last cycle's records (fewer than 2: no cycle figures)
    std::string status;                    ///< "ok" or "failed"
    std::string message;                   ///< why it failed (empty: not written)
    double outputSeconds = 0.0;            ///< s, output outside the step loop (mode shapes)
    double outputInRun = 0.0;              ///< s, output inside the step loop (history, snapshots)
    double totalSeconds = 0.0;             ///< s, the whole run
    const SkirtWear* wear = nullptr;       ///< the wear maps (null: the case asks for none)
    /// Every completed cycle's figures (null: none kept): cycle_to_cycle of a run that did not
    /// become periodic.
    const CycleSeries* cycles = nullptr;
    /// acoustics.json of the liner's vibration record (LinerVibrationReport; null: none)
    const nlohmann::json* acoustics = nullptr;
};

nlohmann::json runSummary(const RunSummaryInput& in);

/// Every key runSummary can write, nested ones dotted ("iterations.steps"), in table order.
const std::vector<std::string>& runSummaryKeys();

}  // namespace flexehd::cosim
