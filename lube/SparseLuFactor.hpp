#pragma once
// SparseLuFactor: sparse LU of a square matrix whose sparsity pattern stays the same over many
// factorizations (SuiteSparse KLU: BTF + AMD ordering, Gilbert–Peierls left-looking LU with
// partial pivoting). The ordering is computed once per pattern and kept; each factor() reuses
// it, and the last pivot sequence too while it suits the new values (klu_refactor, no pivot
// search), else factors the values with pivoting. For the JFO active set (lube::JfoSolver), whose matrix has
// one pattern per grid and new values per partition. With Ordering::Given the matrix's own order
// is the elimination order (no BTF, no AMD per pattern): for matrices the caller has already put in
// a fill-reducing order, as the JFO pad, whose node set changes from solve to solve (docs/lube.md §3b).
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <vector>

namespace flexehd::lube {

class SparseLuFactor {
public:
    /// Amd: BTF and AMD per pattern. Given: the rows and columns as they come.
    enum class Ordering { Amd, Given };
    explicit SparseLuFactor(Ordering ordering = Ordering::Amd);
    ~SparseLuFactor();
    SparseLuFactor(const SparseLuFactor&) = delete;
    SparseLuFactor& operator=(const SparseLuFactor&) = delete;

    /// Factorizes A (compressed, column-major); the ordering is redone only when the pattern
    /// differs from the last one. False when A is singular (numerically or structurally).
    bool factor(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& A);
    /// x = A⁻¹ b with the last factorization.
    Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
    /// B ← A⁻¹ B for all columns of B at once with the last factorization.
    void solveInPlace(Eigen::MatrixXd& B) const;
    /// A fill-reducing elimination order of A's pattern symmetrized (AMD on A + Aᵀ; Amestoy, Davis
    /// & Duff, SIAM J. Matrix Anal. Appl. 17 (1996) 886): the original index of each position.
    static std::vector<int> fillReducingOrder(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& A);
    /// Orderings computed so far (once per pattern seen).
    int analyses() const { return analyses_; }
    /// Factorizations that reused the last pivot sequence.
    long refactors() const { return refactors_; }
    /// A refactorization on the kept pivots is accepted when the crude reciprocal condition
    /// number min |U_ii| / max |U_ii| stays above this; else the values are factorized anew.
    static constexpr double kRefactorRcond = 1e-10;

private:
    struct Klu;
    std::unique_ptr<Klu> klu_;
    std::vector<int> colStart_, rows_;  // the analysed pattern
    Ordering ordering_;
    int analyses_ = 0;
    long refactors_ = 0;
};

}  // namespace flexehd::lube
