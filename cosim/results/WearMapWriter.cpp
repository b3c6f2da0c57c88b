// WearMapWriter: the wear-rate maps of skirt and liner as .vts files.
#include "cosim/results/WearMapWriter.hpp"

#include <vector>

#include "cosim/io/CylinderMapWriter.hpp"

namespace flexehd::cosim {

void writeWearMaps(const std::string& directory, const lube::FilmGrid& g, const ArchardWear& wear) {
    const Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    writeCylinderMap(directory + "/wear_piston.vts", g, g.axial(), origin,
                     {{"wear_rate_m_per_h", [&](int i, int j) { return 3600.0 * wear.pistonRate()[g.index(i, j)]; }}});
    std::vector<double> z;
    for (int c = 0; c < wear.linerCells(); ++c) z.push_back(wear.linerCellZ(c));
    writeCylinderMap(directory + "/wear_liner.vts", g, z, origin,
                     {{"wear_rate_m_per_h", [&](int c, int j) {
                           return 3600.0 * wear.linerRate()[static_cast<Eigen::Index>(c) * g.nTheta() + j];
                       }}});
}

}  // namespace flexehd::cosim
