#pragma once
// ModalMapping: the load and deformation mappings pre-multiplied into the mode shapes of a
// reduced body (docs/mapping.md):
//     loadOperator = Φᵀ A   (modes × grid nodes): modal forces of grid pressures,
//     gridShapes   = D_r Φ  (grid nodes × modes): radial displacement of the grid per unit q,
// with A the LoadMapping matrix (3·nodes × grid), D_r the DeformationMapping radial operator
// (grid × 3·nodes) and Φ the reduced body's shapes (3·nodes × modes). Built once (one sparse ×
// dense product each); a coupling iteration then costs two dense products, O(grid × modes),
// independent of the structural mesh. Given the grid nodes that carry film (the panel nodes of a
// masked skirt grid), the products run over those nodes only: O(active nodes × modes).
#include <vector>

#include <Eigen/Core>

#include "cosim/mapping/DeformationMapping.hpp"
#include "cosim/mapping/LoadMapping.hpp"
#include "lube/NodeColumns.hpp"
#include "modal/ReducedBody.hpp"

namespace flexehd::cosim {

class ModalMapping {
public:
    /// The three must describe the same mesh and grid: throws std::invalid_argument on a size
    /// mismatch (node count of the body vs the operators, grid sizes of the two mappings).
    /// `active`: the grid nodes that carry film (ascending; empty = all). The products then skip
    /// the others: modalForce ignores p there (it must be zero there — ambient gauge pressure, no
    /// film — for the result to equal the unrestricted one), radialDisplacement returns 0 there.
    /// Throws std::invalid_argument for an active node out of range or not ascending.
    ModalMapping(const modal::ReducedBody& body, const LoadMapping& load, const DeformationMapping& deformation,
                 std::vector<int> active = {});

    /// modes × grid nodes: modal forces (N per unit q) = loadOperator · p (p in Pa, gauge); the
    /// columns of inactive nodes are zero.
    Eigen::MatrixXd loadOperator() const;
    /// grid nodes × modes: radial displacement (m, positive away from the axis) per unit q; the
    /// rows of inactive nodes are zero.
    Eigen::MatrixXd gridShapes() const;
    /// The grid nodes the products use (all grid nodes without a restriction).
    const std::vector<int>& activeNodes() const { return active_; }

    Eigen::VectorXd modalForce(const Eigen::VectorXd& p) const;
    void modalForce(const Eigen::VectorXd& p, Eigen::VectorXd& out) const;
    Eigen::VectorXd radialDisplacement(const Eigen::VectorXd& q) const;
    void radialDisplacement(const Eigen::VectorXd& q, Eigen::VectorXd& out) const;
    /// Modal forces of k pressure fields at once (grid nodes × k → modes × k; one matrix product).
    void modalForces(const Eigen::MatrixXd& P, Eigen::MatrixXd& out) const;
    /// modalForces of pressure fields given on a set of grid nodes (zero elsewhere): O(nodes × modes × k).
    void modalForces(const lube::NodeColumns& P, Eigen::MatrixXd& out) const;

private:
    /// The active columns whose grid node carries a load in some column of P (grid nodes × k).
    std::vector<Eigen::Index> loadedColumns(const Eigen::Ref<const Eigen::MatrixXd>& P) const;
    int gridSize_ = 0;
    std::vector<int> active_;
    std::vector<int> activeColumn_;  // per grid node: its column among the active ones, −1 if inactive
    Eigen::MatrixXd B_, G_;  // Φᵀ A and D_r Φ on the active nodes: modes × active, active × modes
};

}  // namespace flexehd::cosim
