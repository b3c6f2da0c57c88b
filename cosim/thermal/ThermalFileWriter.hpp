#pragma once
// Writes thermal.h5, the compact thermal-displacement file that `flexehd run` reads
// (cosim/clearance/ThermalDisplacementFile.hpp; format in docs/thermal.md §6 and
// docs/file-formats.md):
//   root attributes  format = "flexehd-thermal", version = 1
//   /piston, /liner (each optional): datasets axial (n_z, m), theta (n_θ, rad),
//   radial_displacement (n_z × n_θ, m, outward positive), on_surface (n_z × n_θ, uint8);
//   attribute units = "m" and the numeric summary attributes given.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cosim/thermal/CylindricalSurfaceSampler.hpp"

namespace flexehd::cosim {

struct ThermalBodyTable {
    SurfaceTable table;
    std::vector<std::pair<std::string, double>> attributes;  ///< e.g. temperature_max_k
    std::vector<std::pair<std::string, std::string>> textAttributes;  ///< e.g. mesh, surface
};

/// Writes atomically; throws std::runtime_error naming the file on failure or if a value
/// is not finite or the tables are inconsistent.
void writeThermalFile(const std::string& path, const std::optional<ThermalBodyTable>& piston,
                      const std::optional<ThermalBodyTable>& liner);

}  // namespace flexehd::cosim
