#pragma once
// MinimumFilmRegion: how many grid nodes span the region around the thinnest film, where the
// pressure changes fastest (docs/lube.md §8, "Grid resolution of the minimum film"). The region
// is the film within `band` of its minimum, h ≤ h_min + band; its span is counted through the
// thinnest node along its grid row (circumferentially) and along its column (axially). A span of
// a few nodes means the film's load there is not grid-converged.
#include <Eigen/Core>

#include "lube/FilmGrid.hpp"

namespace flexehd::lube {

struct MinimumFilmSpan {
    double minFilm = 0.0;   ///< m, the thinnest film over the grid's film nodes
    int node = -1;          ///< its grid node (−1: no film node)
    int circumferential = 0;  ///< nodes of the region along the thinnest node's row
    int axial = 0;            ///< nodes of the region along its column
    /// the thinnest node lies on the film's axial edge (a skirt edge in contact): the region is
    /// cut by the edge, and `axial` counts inwards only
    bool atAxialEdge = false;
};

/// The span of { h ≤ h_min + band } through the thinnest film node of `h` (one value per grid
/// node; void nodes ignored). `band` > 0, in m.
MinimumFilmSpan minimumFilmSpan(const FilmGrid& grid, const Eigen::VectorXd& h, double band);

}  // namespace flexehd::lube
