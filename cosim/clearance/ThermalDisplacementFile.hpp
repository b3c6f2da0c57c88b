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
//   /piston/ring_belt (optional; files without it read as before), float64 datasets
//     z_m                  n ≥ 2, m, strictly increasing, piston frame
//     temperature_k        n, K, > 0: the circumferential mean temperature of the ring belt's
//                          outer surface at each z
// ThermalField::at interpolates bilinearly, periodic in θ; SurfaceTemperatureProfile is
// piecewise linear in z.

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

/// A body's surface temperature over z: the circumferential mean at each row, piecewise linear
/// between the rows.
struct SurfaceTemperatureProfile {
    std::string where;                ///< "FILE:/piston/ring_belt", for messages
    std::vector<double> z;            ///< m, strictly increasing, ≥ 2 rows
    std::vector<double> temperature;  ///< K, > 0, one per row

    /// The mean over [zLow, zHigh] (zLow < zHigh) of the piecewise-linear profile: its integral
    /// divided by the length. std::out_of_range naming `where` unless the range lies within z's
    /// (a tolerance of 1e-9 m).
    double mean(double zLow, double zHigh) const;
};

struct ThermalDisplacement {
    std::string path;
    std::optional<ThermalField> piston, liner;
    /// /piston/ring_belt: the piston's outer-surface temperature across the ring belt; absent in
    /// files written without it.
    std::optional<SurfaceTemperatureProfile> pistonRingBelt;
};

/// Reads and validates a thermal-displacement file. Throws std::runtime_error naming the file
/// (and the group, dataset or attribute) if it is missing, not HDF5, of another format or
/// version, lacks a dataset, has sizes that do not match, a non-increasing axial table, a θ
/// table that is not uniform in [0, 2π), non-finite values, or neither group; and for a
/// /piston/ring_belt group, a missing dataset, sizes that differ, fewer than 2 rows, a z table
/// that is not strictly increasing or a temperature that is not positive.
ThermalDisplacement readThermalDisplacementFile(const std::string& path);

}  // namespace flexehd::cosim
