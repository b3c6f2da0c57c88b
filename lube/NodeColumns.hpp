#pragma once
// NodeColumns: k columns of a grid field that is zero outside a set of nodes, kept on those nodes
// only — the pressure change of a starved film's linearisation lives on its few full-film nodes,
// its contact pressure change on the nodes in contact (docs/coupling.md §4). Products with it cost
// in proportion to its nodes, not to the grid.
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace flexehd::lube {

struct NodeColumns {
    std::vector<int> nodes;  ///< grid nodes, ascending
    Eigen::MatrixXd values;  ///< nodes.size() × k: row i is node nodes[i]

    Eigen::Index cols() const { return values.cols(); }

    /// The grid field (n × k), zero outside the nodes.
    Eigen::MatrixXd dense(int n) const {
        Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, values.cols());
        for (std::size_t i = 0; i < nodes.size(); ++i) out.row(nodes[i]) = values.row(static_cast<Eigen::Index>(i));
        return out;
    }

    /// The rows of a dense grid field (n × k) that are not zero in any column.
    static NodeColumns fromDense(const Eigen::Ref<const Eigen::MatrixXd>& D) {
        NodeColumns out;
        std::vector<char> nonzero(static_cast<std::size_t>(D.rows()), 0);
        for (Eigen::Index c = 0; c < D.cols(); ++c)  // column by column: D is column-major
            for (Eigen::Index r = 0; r < D.rows(); ++r)
                if (D(r, c) != 0.0) nonzero[static_cast<std::size_t>(r)] = 1;
        for (Eigen::Index r = 0; r < D.rows(); ++r)
            if (nonzero[static_cast<std::size_t>(r)]) out.nodes.push_back(static_cast<int>(r));
        out.values.resize(static_cast<Eigen::Index>(out.nodes.size()), D.cols());
        for (Eigen::Index c = 0; c < D.cols(); ++c)
            for (std::size_t i = 0; i < out.nodes.size(); ++i) out.values(static_cast<Eigen::Index>(i), c) = D(out.nodes[i], c);
        return out;
    }

    /// a + b on the union of their nodes (both with the same columns, or one of them empty).
    static NodeColumns sum(const NodeColumns& a, const NodeColumns& b) {
        if (b.nodes.empty() && b.values.cols() == 0) return a;
        if (a.nodes.empty() && a.values.cols() == 0) return b;
        NodeColumns out;
        out.values.resize(static_cast<Eigen::Index>(a.nodes.size() + b.nodes.size()), a.values.cols());
        std::size_t i = 0, j = 0;
        Eigen::Index r = 0;
        while (i < a.nodes.size() || j < b.nodes.size()) {
            const bool takeA = j == b.nodes.size() || (i < a.nodes.size() && a.nodes[i] <= b.nodes[j]);
            const bool takeB = i == a.nodes.size() || (j < b.nodes.size() && b.nodes[j] <= a.nodes[i]);
            if (takeA && takeB) {
                out.values.row(r) = a.values.row(static_cast<Eigen::Index>(i)) + b.values.row(static_cast<Eigen::Index>(j));
                out.nodes.push_back(a.nodes[i]);
                ++i, ++j;
            } else if (takeA) {
                out.values.row(r) = a.values.row(static_cast<Eigen::Index>(i));
                out.nodes.push_back(a.nodes[i++]);
            } else {
                out.values.row(r) = b.values.row(static_cast<Eigen::Index>(j));
                out.nodes.push_back(b.nodes[j++]);
            }
            ++r;
        }
        out.values.conservativeResize(r, a.values.cols());
        return out;
    }
};

}  // namespace flexehd::lube
