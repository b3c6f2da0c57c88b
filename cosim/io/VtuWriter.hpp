#pragma once
// Writes a mesh with nodal fields as a VTK XML unstructured grid (.vtu) for ParaView:
// binary appended data, float64 points, TET10 as VTK_QUADRATIC_TETRA (Gmsh's last two
// edge nodes swapped into VTK order); or a surface of flat triangles.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fem/Mesh.hpp"

namespace flexehd::cosim {

struct PointField {
    std::string name;
    Eigen::MatrixXd values;  ///< components x nodes (1 row: scalar, 3 rows: vector)
};

struct FieldValue {
    std::string name;
    double value;
};

/// Compression of the appended data blocks: zlib (smallest, slow: ≈ 30 MB/s), LZ4 (≈ 10× faster,
/// somewhat larger files; ParaView ≥ 5.5 reads it) or none.
enum class VtuCompression { ZLib, LZ4, None };

/// Writes atomically; throws std::runtime_error naming the file on failure or if a
/// field has the wrong size or a non-finite value.
void writeVtu(const std::string& path, const fem::Mesh& mesh, const std::vector<PointField>& fields,
              const std::vector<FieldValue>& fieldData = {}, VtuCompression compression = VtuCompression::ZLib);

/// Writes a surface of flat triangles (3 point indices each into `points`) with point fields (LZ4);
/// the same guarantees.
void writeTriangleSurfaceVtu(const std::string& path, const Eigen::Matrix3Xd& points, const std::vector<int>& triangles,
                             const std::vector<PointField>& fields, const std::vector<FieldValue>& fieldData = {});

}  // namespace flexehd::cosim
