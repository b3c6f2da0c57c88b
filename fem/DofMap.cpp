#include "fem/DofMap.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include <Eigen/LU>

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
    if (linked_.count(dof))
        throw std::invalid_argument("DofMap: DOF " + std::to_string(dof) + " belongs to a link, cannot be held");
    equation_[dof] = -1;
    prescribed_(dof) = value;
}

void DofMap::markLinked(const std::vector<Index>& nodes, bool tied) {
    if (final_) throw std::logic_error("DofMap: link added after finalize()");
    if (dofsPerNode_ != 3) throw std::logic_error("DofMap: links need 3 DOFs per node");
    if (nodes.empty()) throw std::invalid_argument("link: the node set is empty");
    for (Index n : nodes) {  // validate everything before changing anything
        if (n < 0 || 3 * n + 2 >= numDofs()) throw std::out_of_range("link: node " + std::to_string(n) + " out of range");
        for (int c = 0; c < 3; ++c) {
            if (equation_[3 * n + c] == -1)
                throw std::invalid_argument("link: node " + std::to_string(n) + " is also held");
            if (linked_.count(3 * n + c))
                throw std::invalid_argument("link: node " + std::to_string(n) + " is in two links (overlapping interfaces)");
        }
    }
    for (Index n : nodes)
        for (int c = 0; c < 3; ++c) {
            linked_.insert(3 * n + c);
            if (tied) equation_[3 * n + c] = -2;
        }
}

int DofMap::addRigidLink(const std::vector<Index>& nodes, const Eigen::Matrix3Xd& x, const Eigen::Vector3d& point) {
    // The reference rotation must be fixed by the set: at least three non-collinear nodes
    // (rank of Σ GᵀG = 6), else the rotation about their line has no stiffness.
    Eigen::Matrix<double, 6, 6> GtG = Eigen::Matrix<double, 6, 6>::Zero();
    for (Index n : nodes) {
        Eigen::Matrix<double, 3, 6> G;
        const Eigen::Vector3d d = x.col(n) - point;
        G.leftCols<3>().setIdentity();
        G.rightCols<3>() << 0, d(2), -d(1), -d(2), 0, d(0), d(1), -d(0), 0;
        GtG += G.transpose() * G;
    }
    if (Eigen::FullPivLU<Eigen::Matrix<double, 6, 6>>(GtG).rank() < 6)
        throw std::invalid_argument("rigid link: the nodes are collinear (or fewer than 3), the reference rotation is undefined");
    markLinked(nodes, true);
    Link link;
    link.nodes = nodes;
    link.offsets.resize(3, Eigen::Index(nodes.size()));
    for (std::size_t k = 0; k < nodes.size(); ++k) link.offsets.col(k) = x.col(nodes[k]) - point;
    links_.push_back(std::move(link));
    return numLinks() - 1;
}

int DofMap::addAveragingLink(const std::vector<Index>& nodes, const Eigen::Matrix3Xd& x,
                             const Eigen::Vector3d& point) {
    if (nodes.size() < 3) throw std::invalid_argument("averaging link: needs at least 3 nodes");
    const Index ns = static_cast<Index>(nodes.size());
    Link link;
    link.nodes = nodes;
    link.offsets.resize(3, ns);
    link.averaging = true;
    Eigen::MatrixXd G(3 * ns, 6);
    for (Index k = 0; k < ns; ++k) {
        const Eigen::Vector3d d = x.col(nodes[k]) - point;
        link.offsets.col(k) = d;
        G.block<3, 3>(3 * k, 0).setIdentity();
        G.block<3, 3>(3 * k, 3) << 0, d(2), -d(1), -d(2), 0, d(0), d(1), -d(0), 0;  // -[d]x
    }
    const Eigen::MatrixXd GtG = G.transpose() * G;
    Eigen::FullPivLU<Eigen::MatrixXd> lu(GtG);
    if (lu.rank() < 6) throw std::invalid_argument("averaging link: the nodes are collinear, no rotation defined");
    const Eigen::MatrixXd R = lu.solve(G.transpose());  // 6 x 3ns
    // Dependent DOFs: among the 9 components of three far-apart nodes, the 6 whose columns
    // of R are best conditioned (largest |det|), so the elimination is stable.
    Index a = 0, b = 0, c = 0;
    for (Index k = 0; k < ns; ++k)
        if ((link.offsets.col(k) - link.offsets.col(a)).norm() > (link.offsets.col(b) - link.offsets.col(a)).norm()) b = k;
    const Eigen::Vector3d ab = (link.offsets.col(b) - link.offsets.col(a)).normalized();
    double best = -1.0;
    for (Index k = 0; k < ns; ++k) {
        const Eigen::Vector3d v = link.offsets.col(k) - link.offsets.col(a);
        if (const double dist = (v - v.dot(ab) * ab).norm(); dist > best) best = dist, c = k;
    }
    const Index cand[9] = {3 * a, 3 * a + 1, 3 * a + 2, 3 * b, 3 * b + 1, 3 * b + 2, 3 * c, 3 * c + 1, 3 * c + 2};
    double bestDet = 0.0;
    std::vector<Index> pick;
    for (unsigned mask = 0; mask < 512; ++mask) {
        if (__builtin_popcount(mask) != 6) continue;
        std::vector<Index> sel;
        for (int i = 0; i < 9; ++i)
            if (mask & (1u << i)) sel.push_back(cand[i]);
        Eigen::Matrix<double, 6, 6> Rg;
        for (int i = 0; i < 6; ++i) Rg.col(i) = R.col(sel[i]);
        if (const double det = std::abs(Rg.determinant()); det > bestDet) bestDet = det, pick = sel;
    }
    if (bestDet <= 0.0) throw std::invalid_argument("averaging link: no stable set of dependent DOFs");
    Eigen::Matrix<double, 6, 6> Rg;
    for (int i = 0; i < 6; ++i) Rg.col(i) = R.col(pick[i]);
    std::vector<Index> restLocal;
    for (Index j = 0; j < 3 * ns; ++j)
        if (std::find(pick.begin(), pick.end(), j) == pick.end()) restLocal.push_back(j);
    Eigen::MatrixXd Rrest(6, restLocal.size());
    for (std::size_t j = 0; j < restLocal.size(); ++j) Rrest.col(j) = R.col(restLocal[j]);
    // R_g u_dep + R_rest u_rest = q_r  =>  u_dep = R_g⁻¹ q_r - R_g⁻¹ R_rest u_rest.
    const Eigen::Matrix<double, 6, 6> RgInv = Rg.inverse();
    link.fromReference = RgInv;
    link.fromRest = -RgInv * Rrest;
    auto global = [&](Index local) { return 3 * nodes[local / 3] + local % 3; };
    for (Index j : pick) link.dependent.push_back(global(j));
    for (Index j : restLocal) link.rest.push_back(global(j));
    markLinked(nodes, false);
    for (Index d : link.dependent) equation_[d] = -2;
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
        if (link.averaging) {  // six dense rows: u_dep = fromReference q_r + fromRest u_rest
            for (int i = 0; i < 6; ++i) {
                for (int j = 0; j < 6; ++j) t.emplace_back(link.dependent[i], r + j, link.fromReference(i, j));
                for (std::size_t j = 0; j < link.rest.size(); ++j)
                    t.emplace_back(link.dependent[i], equation_[link.rest[j]], link.fromRest(i, j));
            }
            continue;
        }
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
    if (hasAveragingLinks()) {  // dense rows couple the whole set: the general Tᵀ K T
        const SparseMatrix full = K.selfadjointView<Eigen::Upper>();
        const SparseMatrix R = T_.transpose() * full * T_;
        return R.triangularView<Eigen::Upper>();
    }
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

bool DofMap::hasAveragingLinks() const {
    return std::any_of(links_.begin(), links_.end(), [](const Link& l) { return l.averaging; });
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
