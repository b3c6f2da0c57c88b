#pragma once
// Reads the YAML thermal case of `flexehd thermal` (every key: docs/thermal.md §5).
// Errors are std::runtime_error messages "FILE: key.path (line N): reason": unknown keys
// (with the closest valid key), wrong types, out-of-range values, missing files.
// Relative paths resolve against the case file's directory.
#include <string>

#include "cosim/thermal/ThermalCase.hpp"

namespace flexehd::cosim {

ThermalCase readThermalCaseFile(const std::string& path);

}  // namespace flexehd::cosim
