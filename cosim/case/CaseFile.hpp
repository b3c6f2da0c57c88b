#pragma once
// The case file: a YAML description of a co-simulation run (engine, piston, lubricant, contact,
// cylinder pressure, bodies, film grid, time stepping, coupling, output), read into an
// EngineCase. Every key, its unit, default and range: docs/case-file.md.
//
// Errors are std::runtime_error messages that start with the case file as given and the key
// path, e.g. "case.yaml: piston.clearance (line 14): expected a positive length in m, got
// -5e-05". Unknown keys are errors (with the closest valid key suggested), as are wrong
// types, out-of-range values, inconsistent values, and missing or unreadable files.
#include <string>
#include <vector>

#include "cosim/case/EngineCase.hpp"

namespace flexehd::cosim {

struct CaseFileOptions {
    /// Check that the reduced-body files of flexible bodies exist and are HDF5 files. Off:
    /// their paths are still resolved to absolute paths but not opened (tests, or checking a
    /// case before the reduced bodies have been made).
    bool checkBodyFiles = true;
    /// Rigid piston and liner whatever the case says (`flexehd run --rigid`), before the checks
    /// that depend on the bodies.
    bool rigidBodies = false;
};

/// Reads and validates a case file. Relative paths in it (cylinder pressure, reduced bodies,
/// output directory) resolve against the case file's directory; EngineCase holds them absolute.
EngineCase readCaseFile(const std::string& path, const CaseFileOptions& options = {});

/// Reads a cylinder-pressure CSV: two columns, crank angle in degrees (0–720) and absolute
/// pressure in Pa, separated by a comma (or a semicolon, or blanks); lines starting with `#`
/// and blank lines are skipped, and the first other line may be a header. The table is
/// validated as by CylinderPressure. Errors: std::runtime_error "FILE:LINE: reason".
std::vector<PressureSample> readPressureTable(const std::string& path);

}  // namespace flexehd::cosim
