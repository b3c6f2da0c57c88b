#pragma once
// Lowest eigenpairs of K φ = λ M φ (λ = ω²) by Lanczos (Spectra) in shift-invert mode:
// the operator (K - σM)⁻¹ M is applied through one CHOLMOD factorization of K - σM.
// A shift σ < 0 keeps K - σM positive definite for free bodies (λ = 0 rigid-body
// modes), so they are found with everything else.
#include <functional>
#include <Eigen/Core>

#include "fem/SparsityPattern.hpp"
#include "fem/StaticSolver.hpp"

namespace flexehd::fem {

struct EigenmodeOptions {
    int count = 10;            ///< number of modes (lowest first)
    double shift = 0.0;        ///< σ in (rad/s)^2; 0 = automatic (small negative, see docs)
    double tolerance = 1e-10;  ///< relative Ritz-value tolerance
    int maxIterations = 1000;  ///< Lanczos restarts
    /// Called during the iteration about every `progressSeconds` of wall time with the
    /// applications of (K − σM)⁻¹ so far and the seconds since the iteration began (progress
    /// output of long solves); empty = silent.
    std::function<void(int operations, double seconds)> progress;
    double progressSeconds = 5.0;
};

/// Size of the Lanczos basis for `count` modes of an n-DOF model: min(n, max(2 count + 1, 20))
/// vectors (the basis holds n × that many doubles).
Eigen::Index lanczosBasisSize(Eigen::Index n, int count);

struct Eigenmodes {
    Eigen::VectorXd eigenvalues;  ///< λ = ω², (rad/s)^2, ascending
    Eigen::MatrixXd shapes;       ///< columns φ_k, M-orthonormal (φᵀMφ = 1)
    double shift = 0.0;           ///< σ used
    int iterations = 0;           ///< Lanczos restarts
    int operations = 0;           ///< applications of (K - σM)⁻¹
    double factorSeconds = 0.0, solveSeconds = 0.0;
    /// f = sign(λ) √|λ| / 2π, Hz (tiny negatives of rigid-body modes keep their sign).
    Eigen::VectorXd frequenciesHz() const;
};

/// Eigenvalues below this are rigid-body modes: 1e-10 tr(K)/tr(M), where tr(K)/tr(M)
/// is the square of a typical element frequency. Independent of how many modes were
/// computed (a threshold relative to the largest computed eigenvalue is not).
double rigidBodyThreshold(const SparseMatrix& K, const SparseMatrix& M);

/// K and M: upper triangles of the (constrained) stiffness and mass matrices.
/// Throws std::runtime_error if the factorization fails or Lanczos does not converge.
/// With `factorOfK` (a factorization of K, which must then be positive definite, e.g. a
/// body held at its interface) the shift is 0 and that factorization is reused instead
/// of factoring K - σM again.
Eigenmodes solveEigenmodes(const SparseMatrix& K, const SparseMatrix& M, const EigenmodeOptions& options,
                           const StaticSolver* factorOfK = nullptr);

}  // namespace flexehd::fem
