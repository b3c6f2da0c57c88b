#include "lube/GridColouring.hpp"

#include <algorithm>

namespace flexehd::lube {

GridColouring distanceTwoColouring(const FilmGrid& grid) {
    GridColouring gc;
    const int n = grid.size();
    gc.colour.assign(static_cast<std::size_t>(n), -1);
    std::vector<int> seen(16, -1);
    for (int k = 0; k < n; ++k) {
        auto mark = [&](int a) {
            const int c = gc.colour[static_cast<std::size_t>(a)];
            if (c >= 0) {
                if (c >= int(seen.size())) seen.resize(static_cast<std::size_t>(c) + 1, -1);
                seen[static_cast<std::size_t>(c)] = k;
            }
        };
        forEachNeighbour(grid, k, [&](int a) {
            mark(a);
            forEachNeighbour(grid, a, mark);
        });
        int c = 0;
        while (c < int(seen.size()) && seen[static_cast<std::size_t>(c)] == k) ++c;
        gc.colour[static_cast<std::size_t>(k)] = c;
        gc.colours = std::max(gc.colours, c + 1);
    }
    return gc;
}

}  // namespace flexehd::lube
