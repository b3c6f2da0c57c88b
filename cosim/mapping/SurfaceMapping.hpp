#pragma once
// SurfaceMapping: a reduced body's surface seen from a film grid, the operations the
// co-simulation needs of it, computed once when the mapping is built and applied at every
// coupling pass (docs/mapping.md):
//   modal force      f = Φᵀ A p              of a grid pressure,
//   film change      Δh = σ D_r Φ q           of modal coordinates (0 on Void nodes),
//   their matrix forms (k pressure fields at once; Δh per unit q as grid × modes),
//   the resultant    of the nodal forces the body receives, as the check of conservation.
// σ: the sign with which the body's outward radial displacement changes the film thickness.
// `offset` is the body-frame z of the grid's origin (the grid slides along a liner; a piston's
// grid is fixed to it and ignores it). Implementations: PistonSurfaceMapping (grid fixed to the
// body), LinerSurfaceMapping (grid sliding along the bore).
#include <vector>

#include <Eigen/Core>

#include "lube/NodeColumns.hpp"

namespace flexehd::cosim {

class SurfaceMapping {
public:
    virtual ~SurfaceMapping() = default;

    /// Modal forces Φᵀ A p (N per unit modal coordinate) of the grid pressure p (Pa, gauge).
    virtual void modalForce(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& f) const = 0;
    /// modalForce of k pressure fields at once (grid nodes × k → modes × k).
    virtual void modalForces(const Eigen::MatrixXd& P, double offset, Eigen::MatrixXd& F) const = 0;
    /// modalForces of fields given on a set of the grid's nodes (zero elsewhere; gridSize nodes).
    virtual void modalForces(const lube::NodeColumns& P, int gridSize, double offset, Eigen::MatrixXd& F) const {
        modalForces(P.dense(gridSize), offset, F);
    }
    /// Film-thickness change (m) on the grid for the modal coordinates q (0 on Void nodes).
    virtual void filmChange(const Eigen::VectorXd& q, double offset, Eigen::VectorXd& dh) const = 0;
    /// filmChange per unit modal coordinate: grid nodes × modes.
    virtual void filmChangeShapes(double offset, Eigen::MatrixXd& Psi) const = 0;
    /// Force and moment about the body frame's origin (N, N·m) of the nodal forces the body
    /// receives for the grid pressure p.
    virtual Eigen::Matrix<double, 6, 1> resultant(const Eigen::VectorXd& p, double offset) const = 0;
    /// Grid nodes that carry film but lie outside the surface's image (no elastic motion there).
    const std::vector<int>& outsideNodes() const { return outside_; }

protected:
    std::vector<int> outside_;
};

}  // namespace flexehd::cosim
