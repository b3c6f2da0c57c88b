#pragma once
// runCase: what `flexehd run` does with a case — the co-simulation of the piston's secondary
// motion over the engine cycle (PistonSimulation, docs/coupling.md) writing its results
// directory (docs/results-format.md): history.csv line by line, the VTK series of the last
// complete cycle, the bodies' mode shapes and summary.json.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cosim/case/EngineCase.hpp"
#include "cosim/contact/FilmContact.hpp"

namespace flexehd::cosim {

/// Where the run's progress lines and warnings go (either may be empty: not shown).
struct RunLog {
    std::function<void(const std::string&)> info;
    std::function<void(const std::string&)> warn;
    /// Asked before each step: a signal number stops the run (summary.json `status: interrupted`,
    /// then RunInterrupted is thrown); 0 or null goes on.
    std::function<int()> interrupted;
};

struct CaseRunResult {
    nlohmann::json summary;  ///< as written to summary.json
    int cycles = 0;          ///< cycles run
    bool periodic = false;
    double seconds = 0.0;    ///< wall-clock, the whole run
};

class PistonSimulation;

/// A further film contact of the run beside the skirt's, built once the simulation is (it may ask
/// it for the liner offset); its own columns go to history.csv and summary.json.
using ContactBuilder = std::function<std::unique_ptr<FilmContact>(const EngineCase&, const PistonSimulation&)>;

/// Runs `c` into c.output.directory (created; unfinished .tmp files of an earlier run removed).
/// A ring pack's lands without given temperatures take them from the case's thermal file
/// (thermalLandTemperatures: an info line, or a warning when the file has no ring-belt profile).
/// A failed run writes summary.json with status "failed" and its message, then throws
/// std::runtime_error with the message and where the partial results are.
CaseRunResult runCase(const EngineCase& c, const RunLog& log = {}, const std::vector<ContactBuilder>& contacts = {});

}  // namespace flexehd::cosim
