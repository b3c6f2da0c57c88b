#include "fem/SparsityPattern.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace flexehd::fem {

SparsityPattern::SparsityPattern(const ElementBlock& elements, Index numNodes, int dofsPerNode)
    : numNodes_(numNodes), dofs_(dofsPerNode) {
    const int nen = static_cast<int>(elements.nodes.rows());
    // Pass 1: count (with repeats) the upper-triangle node pairs per column node.
    std::vector<Index> count(numNodes + 1, 0);
    for (Index e = 0; e < elements.size(); ++e)
        for (int a = 0; a < nen; ++a)
            for (int b = 0; b < nen; ++b)
                if (elements.nodes(a, e) <= elements.nodes(b, e)) ++count[elements.nodes(b, e) + 1];
    std::vector<std::size_t> start(numNodes + 1, 0);
    for (Index j = 0; j < numNodes; ++j) start[j + 1] = start[j] + count[j + 1];
    std::vector<Index> raw(start[numNodes]);
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (Index e = 0; e < elements.size(); ++e)
        for (int a = 0; a < nen; ++a)
            for (int b = 0; b < nen; ++b)
                if (elements.nodes(a, e) <= elements.nodes(b, e))
                    raw[fill[elements.nodes(b, e)]++] = elements.nodes(a, e);
    // Pass 2: sort and deduplicate each node's list into the compact CSR arrays.
    nodeStart_.assign(numNodes + 1, 0);
    neighbours_.reserve(raw.size() / 4);
    for (Index j = 0; j < numNodes; ++j) {
        auto first = raw.begin() + start[j], last = raw.begin() + start[j + 1];
        std::sort(first, last);
        last = std::unique(first, last);
        if (first == last || *(last - 1) != j)
            throw std::runtime_error("node " + std::to_string(j) + " belongs to no element");
        neighbours_.insert(neighbours_.end(), first, last);
        nodeStart_[j + 1] = static_cast<Index>(neighbours_.size());
    }
    // Column offsets: column (j, cc) holds dofs*(m_j - 1) + cc + 1 entries.
    colStart_.assign(std::size_t(numNodes) * dofs_ + 1, 0);
    std::size_t nnz = 0;
    for (Index j = 0; j < numNodes; ++j) {
        const std::size_t m = nodeStart_[j + 1] - nodeStart_[j];
        for (int cc = 0; cc < dofs_; ++cc) {
            colStart_[std::size_t(j) * dofs_ + cc] = static_cast<int>(nnz);
            nnz += dofs_ * (m - 1) + cc + 1;
        }
    }
    if (nnz > std::size_t(std::numeric_limits<int>::max()))
        throw std::runtime_error("matrix too large for 32-bit sparse indices");
    colStart_.back() = static_cast<int>(nnz);
}

SparseMatrix SparsityPattern::zeroMatrix() const {
    const Index n = numDofs();
    const std::size_t nnz = colStart_.back();
    SparseMatrix A(n, n);
    A.resizeNonZeros(static_cast<Eigen::Index>(nnz));
    int* outer = A.outerIndexPtr();
    int* inner = A.innerIndexPtr();
    std::copy(colStart_.begin(), colStart_.end(), outer);
    for (Index j = 0; j < numNodes_; ++j) {
        const Index* nb = neighbours_.data() + nodeStart_[j];
        const Index m = nodeStart_[j + 1] - nodeStart_[j];
        for (int cc = 0; cc < dofs_; ++cc) {
            int* rows = inner + colStart_[std::size_t(j) * dofs_ + cc];
            int p = 0;
            for (Index k = 0; k < m; ++k) {
                const int rmax = (nb[k] == j) ? cc : dofs_ - 1;
                for (int r = 0; r <= rmax; ++r) rows[p++] = dofs_ * nb[k] + r;
            }
        }
    }
    std::fill(A.valuePtr(), A.valuePtr() + nnz, 0.0);
    return A;
}

}  // namespace flexehd::fem
