#pragma once
// Map between the full DOF vector (dofsPerNode per node) and the free unknowns solved
// for, written as u = T u_free + g: constrained DOFs take prescribed values g, free DOFs
// are numbered in increasing order so that reduced matrices keep their upper-triangle
// storage. With only Dirichlet constraints T is a selection and reduce() extracts K_ff
// directly in O(nnz). Multi-point constraints (a node set tied to a reference node)
// extend the same picture: extra free DOFs for the reference node, dependent
// DOFs expressed as rows of T, reduce() = Tᵀ K T.
#include <string>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>

#include "fem/SparsityPattern.hpp"

namespace flexehd::fem {

/// Component selection for constraints: bit c set = component c constrained.
enum ComponentMask : unsigned { kX = 1u, kY = 2u, kZ = 4u, kAllComponents = 7u };

/// Parses "x", "xy", "xyz", "all" (case-insensitive); throws std::invalid_argument.
unsigned parseComponents(const std::string& text);

class DofMap {
public:
    DofMap(Index numNodes, int dofsPerNode);

    /// Prescribes `value` on the selected components of `nodes`. Later calls override
    /// earlier ones for the same DOF. Only before finalize().
    void constrain(const std::vector<Index>& nodes, unsigned components, double value = 0.0);
    void constrainDof(Index dof, double value);
    /// RBE2: ties the nodes rigidly to a new 6-DOF reference node at `point`,
    /// u_s = u_r + θ_r × (x_s - x_r). The reference DOFs (u_x, u_y, u_z, θ_x, θ_y, θ_z)
    /// become free unknowns numbered after all nodal ones, link by link. Needs
    /// dofsPerNode == 3. Returns the link's index. Only before finalize().
    int addRigidLink(const std::vector<Index>& nodes, const Eigen::Matrix3Xd& nodeCoordinates,
                     const Eigen::Vector3d& point);
    /// RBE3: a reference node at `point` that follows the average motion of the nodes,
    /// q_r = R u_S with R = (GᵀG)⁻¹Gᵀ the least-squares rigid fit (G_s = [I, -[x_s - x_r]×]),
    /// adding no stiffness. The reference DOFs become free unknowns (numbered last, like
    /// a rigid link's); six well-conditioned DOFs of the set are eliminated through the
    /// constraint, all others stay unknowns. Needs 3 non-collinear nodes.
    int addAveragingLink(const std::vector<Index>& nodes, const Eigen::Matrix3Xd& nodeCoordinates,
                         const Eigen::Vector3d& point);
    /// Numbers the free DOFs; call once after all constraints.
    void finalize();

    Index numDofs() const { return static_cast<Index>(equation_.size()); }
    Index numFree() const { return numFree_; }
    Index numConstrained() const { return numDofs() - numFree_ + 6 * numLinks(); }
    int numLinks() const { return static_cast<int>(links_.size()); }
    /// First free-equation number of link l's six reference DOFs.
    Index linkEquation(int l) const { return numFree_ - 6 * (numLinks() - l); }
    int dofsPerNode() const { return dofsPerNode_; }
    /// Free-equation number of a full DOF, -1 if constrained, -2 if tied by a link.
    Index equation(Index dof) const { return equation_[dof]; }
    const Eigen::VectorXd& prescribed() const { return prescribed_; }

    /// Reduced matrix K_ff from a full upper-triangle matrix (upper triangle).
    SparseMatrix reduce(const SparseMatrix& fullUpper) const;
    /// Reduced load f_f - K_fc g_c (the prescribed values moved to the right-hand side).
    Eigen::VectorXd reduceLoad(const Eigen::VectorXd& f, const SparseMatrix& fullUpper) const;
    /// Full vector(s) from free values: u = T u_free + g (g = 0 for `homogeneous`).
    Eigen::VectorXd expand(const Eigen::VectorXd& free) const;
    Eigen::MatrixXd expandHomogeneous(const Eigen::MatrixXd& free) const;

    /// The map as a matrix: u = T u_free + g (numDofs x numFree).
    const SparseMatrix& transformation() const { return T_; }

private:
    struct Link {
        std::vector<Index> nodes;
        Eigen::Matrix3Xd offsets;  ///< x_s - x_r per node
        bool averaging = false;    ///< RBE3
        std::vector<Index> dependent, rest;  ///< RBE3: eliminated set DOFs, the others
        Eigen::MatrixXd fromReference;       ///< RBE3: u_dep = fromReference q_r + fromRest u_rest
        Eigen::MatrixXd fromRest;
    };
    void markLinked(const std::vector<Index>& nodes, bool allDofs);
    void requireFinal(const char* what) const;
    void appendLinkColumns(const SparseMatrix& K, SparseMatrix& R) const;
    bool hasAveragingLinks() const;
    std::unordered_set<Index> linked_;  ///< DOFs of all link node sets
    std::vector<Link> links_;
    SparseMatrix T_;
    int dofsPerNode_;
    std::vector<Index> equation_;  ///< before finalize: 0 free, -1 constrained
    Eigen::VectorXd prescribed_;
    Index numFree_ = 0;
    bool final_ = false;
};

}  // namespace flexehd::fem
