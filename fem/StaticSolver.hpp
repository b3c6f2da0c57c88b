#pragma once
// Linear static solve K u = f with a sparse Cholesky factorization (CHOLMOD, supernodal
// LLᵀ). Factor once, solve for as many right-hand sides as needed.
#include <memory>

#include <Eigen/Core>

#include "fem/SparsityPattern.hpp"

namespace flexehd::fem {

class StaticSolver {
public:
    /// Factors K (upper triangle stored). Throws std::runtime_error if K is not positive
    /// definite, which for a stiffness matrix means rigid-body motion is not constrained.
    explicit StaticSolver(const SparseMatrix& upper);
    ~StaticSolver();
    StaticSolver(StaticSolver&&) noexcept;
    StaticSolver& operator=(StaticSolver&&) noexcept;

    Eigen::VectorXd solve(const Eigen::VectorXd& f) const;
    Eigen::MatrixXd solve(const Eigen::MatrixXd& F) const;
    Eigen::Index size() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace flexehd::fem
