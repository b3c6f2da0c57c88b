#pragma once
// Mode shapes of a mesh as ParaView files: DIR/mode_NNN.vtu (one per mode, displacement
// scaled for viewing, frequency in field data) and DIR/modes.pvd (time = mode number).
// Used by `flexehd modes` and `flexehd export-modes`. Format: docs/file-formats.md.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fem/Mesh.hpp"

namespace flexehd::cosim {

/// `shapes`: 3·nodes x m. `eigenvalues` (rad/s)^2 may be empty. Returns the file names
/// written (relative to `directory`), the .pvd last.
std::vector<std::string> writeModeShapes(const std::string& directory, const fem::Mesh& mesh,
                                         const Eigen::MatrixXd& shapes, const Eigen::VectorXd& frequenciesHz,
                                         const Eigen::VectorXd& eigenvalues);

}  // namespace flexehd::cosim
