#include "fem/DofMap.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace flexehd::fem {

unsigned parseComponents(const std::string& text) {
    std::string s = text;
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    if (s == "all" || s == "xyz") return kAllComponents;
    unsigned mask = 0;
    for (char c : s) {
        if (c == 'x') mask |= kX;
        else if (c == 'y') mask |= kY;
        else if (c == 'z') mask |= kZ;
        else {
            mask = 0;
            break;
        }
    }
    if (mask == 0)
        throw std::invalid_argument("components '" + text + "': expected a combination of x, y, z or 'all'");
    return mask;
}

DofMap::DofMap(Index numNodes, int dofsPerNode)
    : dofsPerNode_(dofsPerNode),
      equation_(std::size_t(numNodes) * dofsPerNode, 0),
      prescribed_(Eigen::VectorXd::Zero(Index(numNodes) * dofsPerNode)) {}

void DofMap::constrain(const std::vector<Index>& nodes, unsigned components, double value) {
    for (Index n : nodes)
        for (int c = 0; c < dofsPerNode_; ++c)
            if (components & (1u << c)) constrainDof(dofsPerNode_ * n + c, value);
}

void DofMap::constrainDof(Index dof, double value) {
    if (final_) throw std::logic_error("DofMap: constraints added after finalize()");
    if (dof < 0 || dof >= numDofs())
        throw std::out_of_range("DofMap: DOF " + std::to_string(dof) + " out of range");
    if (equation_[dof] == -2)
        throw std::invalid_argument("DofMap: DOF " + std::to_string(dof) + " is tied by a rigid link, cannot be held");
    equation_[dof] = -1;
    prescribed_(dof) = value;
}

int DofMap::addRigidLink(const std::vector<Index>& nodes, const Eigen::Matrix3Xd& x, const Eigen::Vector3d& point) {
    if (final_) throw std::logic_error("DofMap: link added after finalize()");
    if (dofsPerNode_ != 3) throw std::logic_error("DofMap: rigid links need 3 DOFs per node");
    if (nodes.empty()) throw std::invalid_argument("rigid link: the node set is empty");
    Link link{nodes, Eigen::Matrix3Xd(3, nodes.size())};
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const Index n = nodes[k];
        for (int c = 0; c < 3; ++c) {
            Index& e = equation_[3 * n + c];
            if (e == -1) throw std::invalid_argument("rigid link: node " + std::to_string(n) + " is also held");
            if (e == -2) throw std::invalid_argument("rigid link: node " + std::to_string(n) + " is in two links");
            e = -2;
        }
        link.offsets.col(k) = x.col(n) - point;
    }
    links_.push_back(std::move(link));
    return numLinks() - 1;
}

void DofMap::finalize() {
    if (final_) return;
    numFree_ = 0;
    for (auto& e : equation_)
        if (e >= 0) e = numFree_++;
    numFree_ += 6 * numLinks();
    // T: identity rows for free DOFs; [I  -[d]x] blocks for linked nodes (θ × d = -[d]x θ).
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(equation_.size() + 12 * equation_.size() / 3);
    for (Index d = 0; d < numDofs(); ++d)
        if (equation_[d] >= 0) t.emplace_back(d, equation_[d], 1.0);
    for (int l = 0; l < numLinks(); ++l) {
        const Index r = linkEquation(l);
        const Link& link = links_[l];
        for (std::size_t k = 0; k < link.nodes.size(); ++k) {
            const Eigen::Vector3d dv = link.offsets.col(k);
            Eigen::Matrix3d skew;
            skew << 0, -dv(2), dv(1), dv(2), 0, -dv(0), -dv(1), dv(0), 0;
            for (int i = 0; i < 3; ++i) {
                const Index row = 3 * link.nodes[k] + i;
                t.emplace_back(row, r + i, 1.0);
                for (int j = 0; j < 3; ++j)
                    if (skew(i, j) != 0.0) t.emplace_back(row, r + 3 + j, -skew(i, j));
            }
        }
    }
    T_.resize(numDofs(), numFree_);
    T_.setFromTriplets(t.begin(), t.end());
    final_ = true;
}

void DofMap::requireFinal(const char* what) const {
    if (!final_) throw std::logic_error(std::string("DofMap::") + what + " before finalize()");
}

SparseMatrix DofMap::reduce(const SparseMatrix& K) const {
    requireFinal("reduce");
    if (K.rows() != numDofs() || K.cols() != numDofs())
        throw std::invalid_argument("DofMap::reduce: matrix size does not match the DOF map");
    std::vector<int> outer(std::size_t(numFree_) + 1, 0);
    for (Index j = 0; j < numDofs(); ++j) {
        const Index cj = equation_[j];
        if (cj < 0) continue;
        for (SparseMatrix::InnerIterator it(K, j); it; ++it)
            if (equation_[it.row()] >= 0) ++outer[cj + 1];
    }
    for (Index j = 0; j < numFree_; ++j) outer[j + 1] += outer[j];
    SparseMatrix R(numFree_, numFree_);
    R.resizeNonZeros(outer.back());
    std::copy(outer.begin(), outer.end(), R.outerIndexPtr());
    int p = 0;
    for (Index j = 0; j < numDofs(); ++j) {
        if (equation_[j] < 0) continue;
        for (SparseMatrix::InnerIterator it(K, j); it; ++it)
            if (const Index ri = equation_[it.row()]; ri >= 0) {
                R.innerIndexPtr()[p] = ri;
                R.valuePtr()[p++] = it.value();
            }
    }
    if (numLinks() > 0) appendLinkColumns(K, R);
    return R;
}

// Rigid links: T = [S L] with S selecting the free nodal DOFs and L the reference DOFs
// (numbered last). Sᵀ K S is the selection above; the last 6·links columns of Tᵀ K T are
// [Sᵀ K L; Lᵀ K L], formed with KL = K L in one pass over K's upper triangle — O(nnz),
// where the general sparse product Tᵀ K T costs several full passes and copies.
void DofMap::appendLinkColumns(const SparseMatrix& K, SparseMatrix& R) const {
    const Index nl = 6 * numLinks(), first = numFree_ - nl;
    const Eigen::MatrixXd L = Eigen::MatrixXd(T_.rightCols(nl));
    Eigen::MatrixXd KL = Eigen::MatrixXd::Zero(numDofs(), nl);
    for (Index j = 0; j < numDofs(); ++j)
        for (SparseMatrix::InnerIterator it(K, j); it; ++it) {
            const Index i = it.row();
            if (equation_[j] == -2) KL.row(i) += it.value() * L.row(j);
            if (i != j && equation_[i] == -2) KL.row(j) += it.value() * L.row(i);
        }
    const Eigen::MatrixXd LKL = L.transpose() * KL;
    std::vector<int> outer(R.outerIndexPtr(), R.outerIndexPtr() + first + 1);
    std::vector<int> inner(R.innerIndexPtr(), R.innerIndexPtr() + outer.back());
    std::vector<double> values(R.valuePtr(), R.valuePtr() + outer.back());
    for (Index c = 0; c < nl; ++c) {
        for (Index d = 0; d < numDofs(); ++d)
            if (equation_[d] >= 0 && KL(d, c) != 0.0) {
                inner.push_back(equation_[d]);
                values.push_back(KL(d, c));
            }
        for (Index r = 0; r <= c; ++r) {
            inner.push_back(first + r);
            values.push_back(LKL(r, c));
        }
        outer.push_back(static_cast<int>(inner.size()));
    }
    R = SparseMatrix(numFree_, numFree_);
    R.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
    std::copy(outer.begin(), outer.end(), R.outerIndexPtr());
    std::copy(inner.begin(), inner.end(), R.innerIndexPtr());
    std::copy(values.begin(), values.end(), R.valuePtr());
}

Eigen::VectorXd DofMap::reduceLoad(const Eigen::VectorXd& f, const SparseMatrix& K) const {
    requireFinal("reduceLoad");
    if (f.size() != numDofs()) throw std::invalid_argument("DofMap::reduceLoad: load size mismatch");
    if (numLinks() > 0) {  // f_r = Tᵀ (f - K g)
        if (prescribed_.cwiseAbs().maxCoeff() == 0.0) return T_.transpose() * f;
        return T_.transpose() * (f - K.selfadjointView<Eigen::Upper>() * prescribed_);
    }
    Eigen::VectorXd r(numFree_);
    for (Index d = 0; d < numDofs(); ++d)
        if (equation_[d] >= 0) r(equation_[d]) = f(d);
    if (prescribed_.cwiseAbs().maxCoeff() == 0.0) return r;
    // Upper storage: entry (i, j), i <= j, stands for K_ij and K_ji.
    for (Index j = 0; j < numDofs(); ++j)
        for (SparseMatrix::InnerIterator it(K, j); it; ++it) {
            const Index i = it.row();
            if (i == j) continue;
            if (equation_[i] >= 0 && equation_[j] < 0) r(equation_[i]) -= it.value() * prescribed_(j);
            if (equation_[j] >= 0 && equation_[i] < 0) r(equation_[j]) -= it.value() * prescribed_(i);
        }
    return r;
}

Eigen::VectorXd DofMap::expand(const Eigen::VectorXd& free) const {
    requireFinal("expand");
    if (numLinks() > 0) return T_ * free + prescribed_;
    Eigen::VectorXd u = prescribed_;
    for (Index d = 0; d < numDofs(); ++d)
        if (equation_[d] >= 0) u(d) = free(equation_[d]);
    return u;
}

Eigen::MatrixXd DofMap::expandHomogeneous(const Eigen::MatrixXd& free) const {
    requireFinal("expandHomogeneous");
    if (numLinks() > 0) return T_ * free;
    Eigen::MatrixXd u = Eigen::MatrixXd::Zero(numDofs(), free.cols());
    for (Index d = 0; d < numDofs(); ++d)
        if (equation_[d] >= 0) u.row(d) = free.row(equation_[d]);
    return u;
}

}  // namespace flexehd::fem
