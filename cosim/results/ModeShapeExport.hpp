#pragma once
// Mode shapes of a mesh as ParaView files: DIR/mode_NNN.vtu (one per mode, displacement
// scaled for viewing, frequency in field data) and DIR/modes.pvd (time = mode number).
// Used by `flexehd modes`, `flexehd export-modes` and `flexehd run` (output.mode_shapes).
// Format: docs/file-formats.md; in a results directory: docs/results-format.md.
//
// Written once: DIR/modes.fingerprint holds a 64-bit hash of everything the files are made
// of (mesh, shapes, frequencies, eigenvalues, format version). When DIR already holds the files
// of the same data, nothing is rewritten (a re-run of a case into the same results directory
// does not export its bodies' modes again). The data blocks are LZ4-compressed: the export of
// a few hundred modes takes about a second instead of ~15 s with zlib.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fem/Mesh.hpp"

namespace flexehd::cosim {

/// `shapes`: 3·nodes x m. `eigenvalues` (rad/s)^2 may be empty. Returns the file names
/// (relative to `directory`), the .pvd last — written now or kept from an earlier export of
/// the same data (`reused`, when given, tells which).
std::vector<std::string> writeModeShapes(const std::string& directory, const fem::Mesh& mesh,
                                         const Eigen::MatrixXd& shapes, const Eigen::VectorXd& frequenciesHz,
                                         const Eigen::VectorXd& eigenvalues, bool* reused = nullptr);

/// The hash writeModeShapes compares (hex string, 16 digits).
std::string modeShapeFingerprint(const fem::Mesh& mesh, const Eigen::MatrixXd& shapes,
                                 const Eigen::VectorXd& frequenciesHz, const Eigen::VectorXd& eigenvalues);

}  // namespace flexehd::cosim
