#pragma once
// WearMapWriter: the cycle's wear-rate maps (ArchardWear) as VTK structured grids for ParaView
// (docs/results-format.md, "Wear maps"): wear_piston.vts on the skirt's film grid in the piston
// frame (origin on the pin axis) and wear_liner.vts on the liner's cells in the liner frame
// (z = 0 at the deck), each with `wear_rate_m_per_h`. Written atomically.
#include "cosim/wear/ArchardWear.hpp"
#include "lube/FilmGrid.hpp"

#include <string>

namespace flexehd::cosim {

void writeWearMaps(const std::string& directory, const lube::FilmGrid& grid, const ArchardWear& wear);

}  // namespace flexehd::cosim
