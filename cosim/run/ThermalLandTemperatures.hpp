#pragma once
// The lands' gas temperatures from the thermal file (docs/case-file.md, `ring_gas`): a case with
// `ring_gas: {model: lands}`, a `thermal.file` and no `land_temperatures` takes for each land
// between the rings the mean of the file's piston ring-belt temperature profile
// (/piston/ring_belt, docs/coupling.md §5) over the land's z range, from ring i's groove lower
// flank down to ring i + 1's groove top (piston frame). A file without the profile leaves
// RingGasSpec::kLandTemperature with a warning; given temperatures always win.
#include <optional>
#include <string>
#include <vector>

#include "cosim/case/EngineCase.hpp"

namespace flexehd::cosim {

struct ThermalLandTemperatures {
    /// K, one per land between the rings, top first; empty: the file has no ring-belt profile
    /// (RingGasSpec::kLandTemperature stays).
    std::vector<double> temperatures;
    std::string message;  ///< for the run's log: the temperatures and their source, or why 450 K stays (a warning)
};

/// nullopt unless the case has ring_gas model lands with at least two rings, a thermal file and no
/// land_temperatures. Reads c.thermal.file; throws std::runtime_error naming the case, the file and
/// the land when a land reaches beyond the profile's z range (errors of the file: as
/// readThermalDisplacementFile).
std::optional<ThermalLandTemperatures> thermalLandTemperatures(const EngineCase& c);

}  // namespace flexehd::cosim
