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
#include "cosim/casefile/PressureTable.hpp"  // readPressureTable, which the case reads

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

}  // namespace flexehd::cosim
