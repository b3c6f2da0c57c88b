#include "fem/StaticSolver.hpp"

#include <stdexcept>
#include <string>

#include <Eigen/CholmodSupport>

namespace flexehd::fem {

struct StaticSolver::Impl {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Upper> llt;
    // CHOLMOD prints nothing itself: a failed factorization is reported by the message below.
    Impl() { llt.cholmod().print = 0; }
};

StaticSolver::StaticSolver(const SparseMatrix& upper) : impl_(std::make_unique<Impl>()) {
    if (upper.rows() != upper.cols() || upper.rows() == 0)
        throw std::invalid_argument("StaticSolver: matrix must be square and non-empty");
    impl_->llt.compute(upper);
    if (impl_->llt.info() != Eigen::Success)
        throw std::runtime_error(
            "the matrix (" + std::to_string(upper.rows()) +
            " equations) is not positive definite: the body is not constrained against "
            "rigid-body motion, or material data are invalid");
}

StaticSolver::~StaticSolver() = default;
StaticSolver::StaticSolver(StaticSolver&&) noexcept = default;
StaticSolver& StaticSolver::operator=(StaticSolver&&) noexcept = default;

Eigen::Index StaticSolver::size() const { return impl_->llt.rows(); }

Eigen::VectorXd StaticSolver::solve(const Eigen::VectorXd& f) const {
    if (f.size() != size()) throw std::invalid_argument("StaticSolver::solve: right-hand side size mismatch");
    return impl_->llt.solve(f);
}

Eigen::MatrixXd StaticSolver::solve(const Eigen::MatrixXd& F) const {
    if (F.rows() != size()) throw std::invalid_argument("StaticSolver::solve: right-hand side size mismatch");
    return impl_->llt.solve(F);
}

}  // namespace flexehd::fem
