#pragma once
// ModalMapping: the load and deformation mappings pre-multiplied into the mode shapes of a
// reduced body (issue 5; GUIDE "Mapping"; docs/mapping.md):
//     loadOperator = Φᵀ A   (modes × grid nodes): modal forces of grid pressures,
//     gridShapes   = D_r Φ  (grid nodes × modes): radial displacement of the grid per unit q,
// with A the LoadMapping matrix (3·nodes × grid), D_r the DeformationMapping radial operator
// (grid × 3·nodes) and Φ the reduced body's shapes (3·nodes × modes). Built once (one sparse ×
// dense product each); a coupling iteration then costs two dense products, O(grid × modes),
// independent of the structural mesh.
#include <Eigen/Core>

#include "cosim/DeformationMapping.hpp"
#include "cosim/LoadMapping.hpp"
#include "modal/ReducedBody.hpp"

namespace flexehd::cosim {

class ModalMapping {
public:
    /// The three must describe the same mesh and grid: throws std::invalid_argument on a size
    /// mismatch (node count of the body vs the operators, grid sizes of the two mappings).
    ModalMapping(const modal::ReducedBody& body, const LoadMapping& load, const DeformationMapping& deformation);

    /// modes × grid nodes: modal forces (N per unit q) = loadOperator · p (p in Pa, gauge).
    const Eigen::MatrixXd& loadOperator() const { return B_; }
    /// grid nodes × modes: radial displacement (m, positive away from the axis) per unit q.
    const Eigen::MatrixXd& gridShapes() const { return G_; }

    Eigen::VectorXd modalForce(const Eigen::VectorXd& p) const;
    void modalForce(const Eigen::VectorXd& p, Eigen::VectorXd& out) const;
    Eigen::VectorXd radialDisplacement(const Eigen::VectorXd& q) const;
    void radialDisplacement(const Eigen::VectorXd& q, Eigen::VectorXd& out) const;

private:
    Eigen::MatrixXd B_, G_;
};

}  // namespace flexehd::cosim
