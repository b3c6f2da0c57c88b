// grid: the skirt film's grid (docs/case-file.md, "grid").
#include "cosim/casefile/CaseSections.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace flexehd::cosim::casefile {

void readGrid(const YamlSection& top, const PistonSpec& piston, GridSpec& g) {
    const YamlSection grid(top.source(), top.get("grid"), "grid", {"axial_nodes", "circumferential_nodes"});
    g.axialNodes = integer(grid, "axial_nodes", 3, 100000, g.axialNodes, "nodes");
    g.circumferentialNodes = integer(grid, "circumferential_nodes", 8, 100000, g.circumferentialNodes, "nodes");
    // Each skirt panel (2 × half angle wide) must hold at least 3 grid columns.
    const double spacing = 2 * kPi / g.circumferentialNodes;
    const double halfAngle = std::min(piston.skirtHalfAngle, kPi / 2);
    if (2 * halfAngle / spacing < 2.0)
        grid.fail("circumferential_nodes",
                  fmt::format("{} nodes around the circumference leave fewer than 3 across a skirt panel of {:g} "
                              "deg; use at least {}",
                              g.circumferentialNodes, 2 * halfAngle / kDeg,
                              static_cast<int>(std::ceil(2.0 * 2 * kPi / (2 * halfAngle)))));
}

}  // namespace flexehd::cosim::casefile
