#pragma once
// Writes thermal.h5, the compact thermal-displacement file that `flexehd run` reads
// (cosim/clearance/ThermalDisplacementFile.hpp; format in docs/thermal.md §6 and
// docs/file-formats.md):
//   root attributes  format = "flexehd-thermal", version = 1
//   /piston, /liner (each optional): datasets axial (n_z, m), theta (n_θ, rad),
//   radial_displacement (n_z × n_θ, m, outward positive), on_surface (n_z × n_θ, uint8);
//   attribute units = "m" and the numeric summary attributes given; /piston/ring_belt (optional):
//   datasets z_m (n, m) and temperature_k (n, K), the ring belt's outer-surface temperature over z.
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
    /// The piston's ring-belt surface temperature over z (K), written as GROUP/ring_belt; none: absent.
    std::optional<AxialProfile> ringBelt;
    std::string ringBeltSurface;  ///< its surface groups, comma separated (the group's attribute `surface`)
};

/// Writes atomically; throws std::runtime_error naming the file on failure or if a value
/// is not finite or the tables are inconsistent (a profile's z not strictly increasing, its
/// temperatures not positive, fewer than 2 rows).
void writeThermalFile(const std::string& path, const std::optional<ThermalBodyTable>& piston,
                      const std::optional<ThermalBodyTable>& liner);

}  // namespace flexehd::cosim
