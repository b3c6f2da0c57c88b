// SparseLuFactor: KLU with the symbolic analysis kept per pattern.
#include "lube/SparseLuFactor.hpp"

#include <klu.h>

#include <algorithm>
#include <stdexcept>

namespace flexehd::lube {

struct SparseLuFactor::Klu {
    klu_common common{};
    klu_symbolic* symbolic = nullptr;
    klu_numeric* numeric = nullptr;
    int n = 0;
    Klu() { klu_defaults(&common); }
    ~Klu() {
        if (numeric) klu_free_numeric(&numeric, &common);
        if (symbolic) klu_free_symbolic(&symbolic, &common);
    }
};

SparseLuFactor::SparseLuFactor(Ordering ordering) : klu_(std::make_unique<Klu>()), ordering_(ordering) {
    if (ordering_ == Ordering::Given) klu_->common.btf = 0;
}
SparseLuFactor::~SparseLuFactor() = default;

bool SparseLuFactor::factor(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& A) {
    if (!A.isCompressed() || A.rows() != A.cols())
        throw std::invalid_argument("SparseLuFactor: needs a square compressed matrix");
    const int n = static_cast<int>(A.cols());
    const int* Ap = A.outerIndexPtr();
    const int* Ai = A.innerIndexPtr();
    const int nnz = Ap[n];
    Klu& k = *klu_;
    const bool samePattern = k.symbolic && k.n == n && static_cast<int>(rows_.size()) == nnz &&
                             std::equal(Ap, Ap + n + 1, colStart_.begin()) && std::equal(Ai, Ai + nnz, rows_.begin());
    if (!samePattern) {
        if (k.numeric) klu_free_numeric(&k.numeric, &k.common);
        if (k.symbolic) klu_free_symbolic(&k.symbolic, &k.common);
        colStart_.assign(Ap, Ap + n + 1);
        rows_.assign(Ai, Ai + nnz);
        k.symbolic = ordering_ == Ordering::Given
                         ? klu_analyze_given(n, colStart_.data(), rows_.data(), nullptr, nullptr, &k.common)
                         : klu_analyze(n, colStart_.data(), rows_.data(), &k.common);
        if (!k.symbolic) return false;
        k.n = n;
        ++analyses_;
    }
    double* values = const_cast<double*>(A.valuePtr());
    if (k.numeric) {
        // The kept pivot sequence with the new values (no search); a factorization with pivoting
        // when that pivot sequence no longer suits them.
        if (klu_refactor(colStart_.data(), rows_.data(), values, k.symbolic, k.numeric, &k.common) &&
            k.common.status == KLU_OK && klu_rcond(k.symbolic, k.numeric, &k.common) && k.common.rcond > kRefactorRcond) {
            ++refactors_;
            return true;
        }
        klu_free_numeric(&k.numeric, &k.common);
    }
    k.numeric = klu_factor(colStart_.data(), rows_.data(), values, k.symbolic, &k.common);
    return k.numeric && k.common.status == KLU_OK;
}

std::vector<int> SparseLuFactor::fillReducingOrder(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& A) {
    if (!A.isCompressed() || A.rows() != A.cols())
        throw std::invalid_argument("SparseLuFactor: needs a square compressed matrix");
    const int n = static_cast<int>(A.cols());
    std::vector<int> Ap(A.outerIndexPtr(), A.outerIndexPtr() + n + 1);
    std::vector<int> Ai(A.innerIndexPtr(), A.innerIndexPtr() + Ap[static_cast<std::size_t>(n)]);
    Klu k;
    k.common.btf = 0;  // one block: Q is AMD's order of the whole matrix
    k.symbolic = klu_analyze(n, Ap.data(), Ai.data(), &k.common);
    if (!k.symbolic) throw std::runtime_error("SparseLuFactor: the fill-reducing ordering failed");
    return std::vector<int>(k.symbolic->Q, k.symbolic->Q + n);
}

Eigen::VectorXd SparseLuFactor::solve(const Eigen::VectorXd& b) const {
    Klu& k = *klu_;
    if (!k.numeric || b.size() != k.n) throw std::logic_error("SparseLuFactor::solve: no factorization of this size");
    Eigen::VectorXd x = b;
    klu_solve(k.symbolic, k.numeric, k.n, 1, x.data(), &k.common);
    return x;
}

void SparseLuFactor::solveInPlace(Eigen::MatrixXd& B) const {
    Klu& k = *klu_;
    if (!k.numeric || B.rows() != k.n) throw std::logic_error("SparseLuFactor::solveInPlace: no factorization of this size");
    if (B.cols() == 0) return;
    klu_solve(k.symbolic, k.numeric, k.n, static_cast<int>(B.cols()), B.data(), &k.common);
}

}  // namespace flexehd::lube
