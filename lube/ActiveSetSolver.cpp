#include "lube/ActiveSetSolver.hpp"

#include <Eigen/CholmodSupport>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::lube {

struct ActiveSetSolver::Factor {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt;
};

ActiveSetSolver::ActiveSetSolver() = default;
ActiveSetSolver::~ActiveSetSolver() = default;
ActiveSetSolver::ActiveSetSolver(ActiveSetSolver&&) noexcept = default;
ActiveSetSolver& ActiveSetSolver::operator=(ActiveSetSolver&&) noexcept = default;

SolveReport ActiveSetSolver::solve(const ReynoldsSystem& sys, Eigen::VectorXd& p, double pLower,
                                   const SolverControl& control) {
    const FilmGrid& g = sys.grid();
    const SparseMatrix& A = sys.matrix();
    const Eigen::VectorXd& b = sys.rhs();
    const Eigen::VectorXd& D = sys.diagonal();
    const int n = g.size();
    const bool bounded = std::isfinite(pLower);
    if (p.size() != n) p = sys.initialGuess(pLower);
    for (int k = 0; k < n; ++k)
        if (!sys.isFilm(k)) p[k] = g.prescribedPressure(k);

    // Symbolic analysis once per sparsity pattern.
    const bool samePattern =
        factor_ && outerPattern_.size() == static_cast<std::size_t>(A.outerSize() + 1) &&
        innerPattern_.size() == static_cast<std::size_t>(A.nonZeros()) &&
        std::equal(outerPattern_.begin(), outerPattern_.end(), A.outerIndexPtr()) &&
        std::equal(innerPattern_.begin(), innerPattern_.end(), A.innerIndexPtr());
    if (!samePattern) {
        factor_ = std::make_unique<Factor>();
        factor_->llt.analyzePattern(A);
        outerPattern_.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
        innerPattern_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
    }

    std::vector<char> cav(static_cast<std::size_t>(n), 0), next(cav);
    auto updateSet = [&](std::vector<char>& set) {
        if (!bounded) return;
        const Eigen::VectorXd w = A * p - b;
        for (int k = 0; k < n; ++k)
            set[static_cast<std::size_t>(k)] =
                sys.isFilm(k) && (w[k] / D[k] > p[k] - pLower);
    };
    updateSet(cav);

    SparseMatrix M = A;  // same pattern; values rewritten each iteration
    Eigen::VectorXd rhs(n);
    SolveReport rep;
    for (int it = 1; it <= control.maxIterations; ++it) {
        // Decouple cavitated rows/columns: p_k = p_cav, moved to the right-hand side.
        rhs = b;
        for (int col = 0; col < n; ++col) {
            const bool cc = cav[static_cast<std::size_t>(col)];
            for (SparseMatrix::InnerIterator e(M, col), e0(A, col); e; ++e, ++e0) {
                const int row = e.row();
                const bool rc = cav[static_cast<std::size_t>(row)];
                if (row == col) {
                    e.valueRef() = e0.value();
                } else if (cc || rc) {
                    e.valueRef() = 0.0;
                    if (cc && !rc) rhs[row] -= e0.value() * pLower;
                } else {
                    e.valueRef() = e0.value();
                }
            }
            if (cc) rhs[col] = D[col] * pLower;
        }
        factor_->llt.factorize(M);
        if (factor_->llt.info() != Eigen::Success)
            throw std::runtime_error("ActiveSetSolver: Cholesky factorization failed at "
                                     "iteration " + std::to_string(it) +
                                     " (matrix not positive definite?)");
        p = factor_->llt.solve(rhs);
        rep.iterations = it;
        if (!p.allFinite())
            throw std::runtime_error("ActiveSetSolver: non-finite pressure at iteration " +
                                     std::to_string(it));
        updateSet(next);
        rep.residual = sys.residual(p, pLower);
        if (rep.residual <= control.tolerance) return rep;
        if (next == cav) {
            throw std::runtime_error("ActiveSetSolver: active set converged after " +
                                     std::to_string(it) + " iterations but residual " +
                                     messageNumber(rep.residual) + " > tolerance " +
                                     messageNumber(control.tolerance) +
                                     " (ill-conditioned film?)");
        }
        cav.swap(next);
    }
    rep.residual = sys.residual(p, pLower);
    throw std::runtime_error("ActiveSetSolver: active set still changing after " +
                             std::to_string(control.maxIterations) + " iterations (residual " +
                             messageNumber(rep.residual) + ")");
}

}  // namespace flexehd::lube
