#include "cosim/thermal/LinerTemperature.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace flexehd::cosim {

double thermocoupleTemperature(const std::vector<double>& radii, const std::vector<ThermocoupleStation>& stations,
                               double r, double z) {
    if (stations.empty() || radii.empty()) throw std::invalid_argument("liner temperature: no thermocouple data");
    // Axial interpolation of each depth's temperature, constant outside [z_first, z_last].
    auto atDepth = [&](std::size_t d) {
        if (z <= stations.front().z) return stations.front().temperatures[d];
        if (z >= stations.back().z) return stations.back().temperatures[d];
        const auto it = std::upper_bound(stations.begin(), stations.end(), z,
                                         [](double v, const ThermocoupleStation& s) { return v < s.z; });
        const auto& b = *it;
        const auto& a = *(it - 1);
        const double t = (z - a.z) / (b.z - a.z);
        return (1.0 - t) * a.temperatures[d] + t * b.temperatures[d];
    };
    if (radii.size() == 1) return atDepth(0);
    const double T0 = atDepth(0), T1 = atDepth(1);
    return T0 + (T1 - T0) * (r - radii[0]) / (radii[1] - radii[0]);
}

Eigen::VectorXd linerTemperature(const fem::Mesh& mesh, const std::vector<double>& radii,
                                 const std::vector<ThermocoupleStation>& stations) {
    Eigen::VectorXd T(mesh.numNodes());
    for (fem::Index n = 0; n < mesh.numNodes(); ++n)
        T(n) = thermocoupleTemperature(radii, stations, mesh.nodes.col(n).head<2>().norm(), mesh.nodes(2, n));
    return T;
}

}  // namespace flexehd::cosim
