#include "cosim/mapping/ModalMapping.hpp"

#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/SparseCore>

namespace flexehd::cosim {

ModalMapping::ModalMapping(const modal::ReducedBody& body, const LoadMapping& load,
                           const DeformationMapping& deformation, std::vector<int> active) {
    const Eigen::MatrixXd& phi = body.shapes;
    const auto& A = load.matrix();
    const auto& D = deformation.radial();
    if (A.rows() != phi.rows() || D.cols() != phi.rows())
        throw std::invalid_argument("ModalMapping: the reduced body has " + std::to_string(phi.rows()) +
                                    " dofs, the load mapping " + std::to_string(A.rows()) +
                                    " and the deformation mapping " + std::to_string(D.cols()) +
                                    ": not the same mesh");
    if (A.cols() != D.rows())
        throw std::invalid_argument("ModalMapping: the load mapping has " + std::to_string(A.cols()) +
                                    " grid nodes, the deformation mapping " + std::to_string(D.rows()) +
                                    ": not the same grid");
    gridSize_ = static_cast<int>(A.cols());
    if (active.empty()) {
        active.resize(static_cast<std::size_t>(gridSize_));
        for (int k = 0; k < gridSize_; ++k) active[static_cast<std::size_t>(k)] = k;
    }
    for (std::size_t i = 0; i < active.size(); ++i)
        if (active[i] < 0 || active[i] >= gridSize_ || (i > 0 && active[i] <= active[i - 1]))
            throw std::invalid_argument("ModalMapping: active grid node " + std::to_string(active[i]) +
                                        " is out of range (0.." + std::to_string(gridSize_ - 1) +
                                        ") or not ascending");
    active_ = std::move(active);
    activeColumn_.assign(static_cast<std::size_t>(gridSize_), -1);
    for (std::size_t c = 0; c < active_.size(); ++c) activeColumn_[static_cast<std::size_t>(active_[c])] = static_cast<int>(c);
    const Eigen::Index na = static_cast<Eigen::Index>(active_.size());
    // Φᵀ A and D Φ on the active columns / rows only (the column-major A's columns are cheap to
    // pick; the row-major D's rows too).
    Eigen::SparseMatrix<double> Aa(A.rows(), na);
    Eigen::SparseMatrix<double, Eigen::RowMajor> Da(na, D.cols());
    {
        std::vector<Eigen::Triplet<double>> ta, td;
        for (Eigen::Index c = 0; c < na; ++c) {
            const int k = active_[static_cast<std::size_t>(c)];
            for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it) ta.emplace_back(it.row(), c, it.value());
            for (std::remove_cvref_t<decltype(D)>::InnerIterator it(D, k); it; ++it) td.emplace_back(c, it.col(), it.value());
        }
        Aa.setFromTriplets(ta.begin(), ta.end());
        Da.setFromTriplets(td.begin(), td.end());
    }
    B_ = (Aa.transpose() * phi).transpose();  // Φᵀ A, via the column-major sparse transpose
    G_ = Da * phi;
}

Eigen::MatrixXd ModalMapping::loadOperator() const {
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(B_.rows(), gridSize_);
    for (std::size_t c = 0; c < active_.size(); ++c) full.col(active_[c]) = B_.col(static_cast<Eigen::Index>(c));
    return full;
}

Eigen::MatrixXd ModalMapping::gridShapes() const {
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(gridSize_, G_.cols());
    for (std::size_t c = 0; c < active_.size(); ++c) full.row(active_[c]) = G_.row(static_cast<Eigen::Index>(c));
    return full;
}

Eigen::VectorXd ModalMapping::modalForce(const Eigen::VectorXd& p) const {
    Eigen::VectorXd out;
    modalForce(p, out);
    return out;
}

std::vector<Eigen::Index> ModalMapping::loadedColumns(const Eigen::Ref<const Eigen::MatrixXd>& P) const {
    // A starved film loads a small share of the active nodes (its full-film and contact nodes,
    // docs/coupling.md §6); one streaming pass over P finds them.
    std::vector<char> nonzero(static_cast<std::size_t>(gridSize_), 0);
    for (Eigen::Index j = 0; j < P.cols(); ++j)
        for (Eigen::Index r = 0; r < P.rows(); ++r)
            if (P(r, j) != 0.0) nonzero[static_cast<std::size_t>(r)] = 1;
    std::vector<Eigen::Index> loaded;
    for (std::size_t c = 0; c < active_.size(); ++c)
        if (nonzero[static_cast<std::size_t>(active_[c])]) loaded.push_back(static_cast<Eigen::Index>(c));
    return loaded;
}

void ModalMapping::modalForce(const Eigen::VectorXd& p, Eigen::VectorXd& out) const {
    if (p.size() != gridSize_)
        throw std::invalid_argument("ModalMapping::modalForce: " + std::to_string(p.size()) +
                                    " pressures for a grid of " + std::to_string(gridSize_) + " nodes");
    const std::vector<Eigen::Index> loaded = loadedColumns(p);
    if (2 * loaded.size() >= active_.size()) {
        Eigen::VectorXd pa(static_cast<Eigen::Index>(active_.size()));
        for (std::size_t c = 0; c < active_.size(); ++c) pa[static_cast<Eigen::Index>(c)] = p[active_[c]];
        out.noalias() = B_ * pa;
        return;
    }
    out.setZero(B_.rows());
    for (const Eigen::Index c : loaded) out.noalias() += p[active_[static_cast<std::size_t>(c)]] * B_.col(c);
}

void ModalMapping::modalForces(const Eigen::MatrixXd& P, Eigen::MatrixXd& out) const {
    if (P.rows() != gridSize_)
        throw std::invalid_argument("ModalMapping::modalForces: " + std::to_string(P.rows()) +
                                    " pressures per column for a grid of " + std::to_string(gridSize_) + " nodes");
    const std::vector<Eigen::Index> loaded = loadedColumns(P);
    const auto nl = static_cast<Eigen::Index>(loaded.size());
    if (2 * nl >= static_cast<Eigen::Index>(active_.size())) {
        Eigen::MatrixXd pa(static_cast<Eigen::Index>(active_.size()), P.cols());
        for (std::size_t c = 0; c < active_.size(); ++c) pa.row(static_cast<Eigen::Index>(c)) = P.row(active_[c]);
        out.noalias() = B_ * pa;
        return;
    }
    Eigen::MatrixXd Bl(B_.rows(), nl), pl(nl, P.cols());
    for (Eigen::Index c = 0; c < nl; ++c) {
        Bl.col(c) = B_.col(loaded[static_cast<std::size_t>(c)]);
        pl.row(c) = P.row(active_[static_cast<std::size_t>(loaded[static_cast<std::size_t>(c)])]);
    }
    out.noalias() = Bl * pl;
}

void ModalMapping::modalForces(const lube::NodeColumns& P, Eigen::MatrixXd& out) const {
    std::vector<Eigen::Index> loaded, rows;  // active columns of B and their rows of P
    for (std::size_t i = 0; i < P.nodes.size(); ++i) {
        const int node = P.nodes[i];
        if (node < 0 || node >= gridSize_)
            throw std::invalid_argument("ModalMapping::modalForces: grid node " + std::to_string(node) +
                                        " out of range (0.." + std::to_string(gridSize_ - 1) + ")");
        const int c = activeColumn_[static_cast<std::size_t>(node)];
        if (c >= 0) loaded.push_back(c), rows.push_back(static_cast<Eigen::Index>(i));
    }
    const auto nl = static_cast<Eigen::Index>(loaded.size());
    Eigen::MatrixXd Bl(B_.rows(), nl);
    for (Eigen::Index c = 0; c < nl; ++c) Bl.col(c) = B_.col(loaded[static_cast<std::size_t>(c)]);
    if (nl == P.values.rows()) {  // every node active (a skirt's film nodes)
        out.noalias() = Bl * P.values;
        return;
    }
    Eigen::MatrixXd pl(nl, P.cols());
    for (Eigen::Index c = 0; c < nl; ++c) pl.row(c) = P.values.row(rows[static_cast<std::size_t>(c)]);
    out.noalias() = Bl * pl;
}

Eigen::VectorXd ModalMapping::radialDisplacement(const Eigen::VectorXd& q) const {
    Eigen::VectorXd out;
    radialDisplacement(q, out);
    return out;
}

void ModalMapping::radialDisplacement(const Eigen::VectorXd& q, Eigen::VectorXd& out) const {
    if (q.size() != G_.cols())
        throw std::invalid_argument("ModalMapping::radialDisplacement: " + std::to_string(q.size()) +
                                    " modal coordinates for " + std::to_string(G_.cols()) + " modes");
    const Eigen::VectorXd ua = G_ * q;
    out.setZero(gridSize_);
    for (std::size_t c = 0; c < active_.size(); ++c) out[active_[c]] = ua[static_cast<Eigen::Index>(c)];
}

}  // namespace flexehd::cosim
