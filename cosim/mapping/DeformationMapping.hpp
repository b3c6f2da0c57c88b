#pragma once
// DeformationMapping: structure → grid transfer of surface displacements as a C¹ piecewise
// cubic (Clough–Tocher) interpolant over the parameter plane (z, s = R θ) (seed §3.1;
// docs/mapping.md).
//
// Each surface triangle's vertex image (z, s) is split at its centroid into three cubic
// Bézier patches (Clough & Tocher 1965; Bézier form: Farin, CAGD 3 (1986) 83–127). The patches
// interpolate the vertex values and gradients, the normal derivative along every triangle
// edge is linear (so neighbouring triangles join C¹), and the split-edge ordinates follow from
// the C¹ conditions inside the macro-triangle. Vertex gradients are estimated by an unweighted
// least-squares quadratic fit in (z, s) to the surface nodes (vertices and TRI6 mid-nodes) of
// the triangles around the vertex (two rings when one has fewer than 10 nodes): the estimate is
// exact for quadratics, so the interpolant reproduces polynomials of degree ≤ 2 in (z, s)
// exactly and converges as O(h³) for smooth fields. Everything is linear in the nodal values:
// assembled once as a sparse matrix (grid nodes × mesh nodes), applied per component.
// Grid nodes outside the surface's image (skirt edges, panels' gaps) get empty rows: the
// mapped displacement there is 0, and they are listed by outsideNodes().
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "fem/Mesh.hpp"
#include "lube/FilmGrid.hpp"

namespace flexehd::cosim {

class DeformationMapping {
public:
    /// body z = grid z + axialOffset. Throws std::invalid_argument naming the surface if it
    /// is unknown, not a cylinder about z within radiusTolerance, or does not overlap the grid.
    DeformationMapping(const fem::Mesh& mesh, const std::string& surface, const lube::FilmGrid& grid,
                       double axialOffset = 0.0, double radiusTolerance = 1e-3);

    /// grid nodes × mesh nodes: grid values of a scalar nodal field (one component).
    const Eigen::SparseMatrix<double, Eigen::RowMajor>& scalar() const { return S_; }
    /// grid nodes × 3 mesh nodes: radial displacement u·(cos θ_n, sin θ_n, 0) at the grid
    /// nodes (positive away from the axis) from the full displacement vector.
    const Eigen::SparseMatrix<double, Eigen::RowMajor>& radial() const { return Rr_; }
    /// Grid nodes outside every triangle image (empty rows).
    const std::vector<int>& outsideNodes() const { return outside_; }

private:
    Eigen::SparseMatrix<double, Eigen::RowMajor> S_, Rr_;
    std::vector<int> outside_;
};

}  // namespace flexehd::cosim
