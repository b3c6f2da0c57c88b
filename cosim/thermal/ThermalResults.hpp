#pragma once
// writeThermalResults: the results directory of `flexehd thermal` (docs/thermal.md) —
// DIR/piston.vtu and DIR/liner.vtu (temperature and thermal displacement, body frame, for
// ParaView), DIR/thermal.h5 (the radial displacement tables `flexehd run` reads) and
// DIR/summary.json (temperatures, convection, calibration, supports, radial growth, timings),
// each written atomically. Returns the summary document.
#include <string>

#include <nlohmann/json.hpp>

#include "cosim/thermal/ThermalAnalysis.hpp"
#include "cosim/thermal/ThermalCase.hpp"
#include "fem/Stopwatch.hpp"

namespace flexehd::cosim {

/// `total`: the command's stopwatch (summary.json's timings_s.total).
nlohmann::json writeThermalResults(const std::string& dir, const std::string& casePath, const ThermalCase& c,
                                   const ThermalResult& r, const fem::Stopwatch& total);

}  // namespace flexehd::cosim
