#pragma once
// Sparsity of a symmetric finite-element matrix, built once from the element
// connectivity, so that assembly scatters element matrices straight into the values of
// a compressed column matrix (no triplet lists: those cost ~ 16 bytes per element entry,
// several GB at a million DOF). Only the upper triangle is stored, as CHOLMOD and
// Eigen's selfadjointView<Upper> expect. DOF numbering: dof = dofsPerNode * node + comp.
#include <algorithm>
#include <vector>

#include <Eigen/SparseCore>

#include "fem/Mesh.hpp"

namespace flexehd::fem {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

class SparsityPattern {
public:
    SparsityPattern(const ElementBlock& elements, Index numNodes, int dofsPerNode);

    Index numDofs() const { return numNodes_ * dofs_; }
    int dofsPerNode() const { return dofs_; }
    /// A compressed matrix with this pattern and zero values.
    SparseMatrix zeroMatrix() const;

    /// Adds the element matrix Ke (node-major: row d*a + c for local node a, component c)
    /// of an element with nodes `nodes[0..nen)` into A, which must come from zeroMatrix().
    template <typename Derived>
    void add(SparseMatrix& A, const Index* nodes, int nen, const Eigen::MatrixBase<Derived>& Ke) const {
        double* values = A.valuePtr();
        for (int b = 0; b < nen; ++b) {
            const Index j = nodes[b];
            const Index* nb = neighbours_.data() + nodeStart_[j];
            const Index count = nodeStart_[j + 1] - nodeStart_[j];
            for (int a = 0; a < nen; ++a) {
                const Index i = nodes[a];
                if (i > j) continue;  // lower triangle
                const Index k = static_cast<Index>(std::lower_bound(nb, nb + count, i) - nb);
                for (int cc = 0; cc < dofs_; ++cc) {
                    const int rmax = (i == j) ? cc : dofs_ - 1;
                    double* col = values + colStart_[std::size_t(j) * dofs_ + cc] + std::size_t(k) * dofs_;
                    for (int r = 0; r <= rmax; ++r) col[r] += Ke(dofs_ * a + r, dofs_ * b + cc);
                }
            }
        }
    }

private:
    Index numNodes_;
    int dofs_;
    std::vector<Index> nodeStart_;   ///< CSR offsets into neighbours_, per node
    std::vector<Index> neighbours_;  ///< for node j: sorted nodes i <= j sharing an element
    std::vector<int> colStart_;      ///< offset of each DOF column in the value array
};

}  // namespace flexehd::fem
