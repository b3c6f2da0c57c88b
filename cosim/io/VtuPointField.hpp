#pragma once
// VtuPointField: the points and one point-data array of a VTK XML unstructured grid (.vtu) —
// an external FE result such as a liner's assembly displacement (BoreDistortion, `format:
// nodal`). Cells are not read: the consumers fit fields to the points.
#include <Eigen/Core>

#include <string>
#include <vector>

namespace flexehd::cosim {

struct VtuPointField {
    Eigen::Matrix3Xd points;  ///< coordinates as stored (undeformed)
    Eigen::MatrixXd values;   ///< components × points
};

/// Reads `path` with VTK's XML reader and returns its points with the point-data array `name`
/// (any number of components, converted to double). Throws std::runtime_error "PATH: reason" if
/// the file is missing or not a readable .vtu, has no points, or has no such array (the message
/// lists the arrays it has).
VtuPointField readVtuPointField(const std::string& path, const std::string& name);

}  // namespace flexehd::cosim
