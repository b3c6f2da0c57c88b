#pragma once
// CylinderMapWriter: fields on a cylinder of the film grid's radius — its θ columns by a list of
// axial positions — as a VTK structured grid nx × nz × 1 (x = θ, the first column repeated on a
// full circumference so that ParaView draws it closed), written atomically with LZ4-compressed
// appended data. The wear maps and the liner's oil layer (docs/results-format.md).
#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

#include "cosim/io/VtuWriter.hpp"
#include "lube/FilmGrid.hpp"

class vtkStructuredGrid;

namespace flexehd::cosim {

/// Adds one-value field arrays (TimeValue, crank_deg, …) to the grid.
void addFieldValues(vtkStructuredGrid& grid, const std::vector<FieldValue>& values);
/// Writes the grid to `path` atomically: VTK XML, appended raw LZ4-compressed blocks, UInt64
/// headers. Throws std::runtime_error naming the file on an I/O error.
void writeStructuredGrid(const std::string& path, vtkStructuredGrid& grid);

struct CylinderMapArray {
    std::string name;                         ///< array name (unit suffix)
    std::function<double(int i, int j)> value;  ///< at axial position i, θ column j
};

/// Writes `path`: points (R cos θ_j, R sin θ_j, z_i) + origin; the first array is the active
/// scalar; fieldData as one-value field arrays (TimeValue, …). Throws std::runtime_error naming
/// the file on an I/O error.
void writeCylinderMap(const std::string& path, const lube::FilmGrid& grid, const std::vector<double>& z,
                      const Eigen::Vector3d& origin, const std::vector<CylinderMapArray>& arrays,
                      const std::vector<FieldValue>& fieldData = {});

}  // namespace flexehd::cosim
