#pragma once
// ThermalDisplacementFile: reads the compact thermal-displacement file `thermal.h5` written by
// `flexehd thermal` (seed §2.3: h_thermal,piston and h_thermal,liner of seed eq. 2).
//
// Format (agreed with the thermal analysis; docs/thermal.md, docs/coupling.md §5):
//   root attributes  format = "flexehd-thermal" (string), version = 1 (integer)
//   groups /piston and /liner (either may be absent), each with the float64 datasets
//     axial                n_z, m, strictly increasing: the cylinder-axis coordinate in the body's
//                          mesh frame (meshes/*.geo, the reduced-body files)
//     theta                n_θ, rad, uniform in [0, 2π) from the mesh +x axis towards +y, periodic
//     radial_displacement  n_z × n_θ (row-major), m, outward positive
// ThermalField::at interpolates bilinearly, periodic in θ.

#include <optional>
#include <string>
#include <vector>

namespace flexehd::cosim {

inline constexpr const char* kThermalFormat = "flexehd-thermal";
inline constexpr int kThermalFormatVersion = 1;

/// One body's radial thermal displacement on its (axial, θ) table.
struct ThermalField {
    std::string where;           ///< "FILE:/piston" or "FILE:/liner", for messages
    std::vector<double> axial;   ///< m, strictly increasing, n_z ≥ 2
    std::vector<double> theta;   ///< rad, θ_j = θ_0 + 2πj/n_θ, n_θ ≥ 3
    std::vector<double> radial;  ///< m, n_z × n_θ row-major

    /// u_r at (z, θ): bilinear, periodic in θ. z must lie in [axial.front(), axial.back()]
    /// (std::out_of_range naming `where`/axial otherwise).
    double at(double z, double theta) const;
    /// Throws std::runtime_error naming FILE, the dataset and `what` unless [zMin, zMax] lies
    /// within the axial range (a tolerance of 1e-9 m).
    void checkCovers(double zMin, double zMax, const std::string& what) const;
};

struct ThermalDisplacement {
    std::string path;
    std::optional<ThermalField> piston, liner;
};

/// Reads and validates a thermal-displacement file. Throws std::runtime_error naming the file
/// (and the group, dataset or attribute) if it is missing, not HDF5, of another format or
/// version, lacks a dataset, has sizes that do not match, a non-increasing axial table, a θ
/// table that is not uniform in [0, 2π), non-finite values, or neither group.
ThermalDisplacement readThermalDisplacementFile(const std::string& path);

}  // namespace flexehd::cosim
