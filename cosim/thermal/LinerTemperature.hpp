#pragma once
// The liner's temperature field from thermocouple data (docs/thermal.md §4): stations at
// axial positions z_k, each with temperatures at one or two radii (depths in the wall).
// At a node (r, z): linear in z between stations (constant beyond the first and last),
// then linear in r through the two depths (extrapolated linearly to the bore and the
// outer surface: the 1-D conduction profile of a thin wall); one depth → uniform in r.
#include <vector>

#include <Eigen/Core>

#include "cosim/thermal/ThermalCase.hpp"
#include "fem/Mesh.hpp"

namespace flexehd::cosim {

/// T at radius r and axial position z, K.
double thermocoupleTemperature(const std::vector<double>& radii, const std::vector<ThermocoupleStation>& stations,
                               double r, double z);

/// Nodal temperatures of the mesh (cylinder axis z), K.
Eigen::VectorXd linerTemperature(const fem::Mesh& mesh, const std::vector<double>& radii,
                                 const std::vector<ThermocoupleStation>& stations);

}  // namespace flexehd::cosim
