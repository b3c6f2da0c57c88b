#pragma once
// The cylinder-pressure table a case names (docs/case-file.md, "cylinder_pressure").
#include <string>
#include <vector>

#include "cosim/case/EngineCase.hpp"

namespace flexehd::cosim {

/// Reads a cylinder-pressure CSV: two columns, crank angle in degrees (0–720) and absolute
/// pressure in Pa, separated by a comma (or a semicolon, or blanks); lines starting with `#`
/// and blank lines are skipped, and the first other line may be a header. The table is
/// validated as by CylinderPressure. Errors: std::runtime_error "FILE:LINE: reason".
std::vector<PressureSample> readPressureTable(const std::string& path);

}  // namespace flexehd::cosim
