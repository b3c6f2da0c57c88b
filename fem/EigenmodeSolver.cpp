#include "fem/EigenmodeSolver.hpp"
#include "fem/Stopwatch.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/CholmodSupport>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>

namespace flexehd::fem {
namespace {

// Spectra operator y = (K - σM)⁻¹ x on a CHOLMOD supernodal factorization.
class CholmodShiftInvert {
public:
    using Scalar = double;
    CholmodShiftInvert(const SparseMatrix& K, const SparseMatrix& M, const StaticSolver* factorOfK)
        : K_(K), M_(M), external_(factorOfK) {
        llt_.cholmod().print = 0;  // failures are reported by set_shift's message, not by CHOLMOD
    }
    Eigen::Index rows() const { return K_.rows(); }
    Eigen::Index cols() const { return K_.cols(); }
    void set_shift(double sigma) {
        if (external_) return;  // σ = 0: the caller's factorization of K
        const Stopwatch t0;
        llt_.compute(K_ - sigma * M_);
        if (llt_.info() != Eigen::Success)
            throw std::runtime_error("eigenmodes: K - sigma*M with sigma = " + std::to_string(sigma) +
                                     " is not positive definite; choose a shift below the lowest "
                                     "eigenvalue");
        factorSeconds = t0.seconds();
    }
    void perform_op(const double* x, double* y) const {
        const Eigen::Map<const Eigen::VectorXd> in(x, rows());
        Eigen::Map<Eigen::VectorXd>(y, rows()) = external_ ? external_->solve(Eigen::VectorXd(in)) : llt_.solve(in);
        ++operations;
        if (progress && lastReport.seconds() >= progressSeconds) {
            lastReport.restart();
            progress(operations, started.seconds());
        }
    }
    std::function<void(int, double)> progress;
    double progressSeconds = 5.0;
    Stopwatch started;
    mutable Stopwatch lastReport;
    double factorSeconds = 0.0;
    mutable int operations = 0;

private:
    const SparseMatrix& K_;
    const SparseMatrix& M_;
    const StaticSolver* external_;
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Upper> llt_;
};

// Automatic shift: a small fraction of the mean diagonal ratio K_ii / M_ii (the square of
// a typical element frequency). It sits far below the lowest elastic eigenvalue of any
// sensible mesh, yet far above round-off, so K - σM is safely positive definite.
double automaticShift(const SparseMatrix& K, const SparseMatrix& M) {
    const double k = K.diagonal().sum(), m = M.diagonal().sum();
    return -1e-8 * k / m;
}

}  // namespace

Eigen::Index lanczosBasisSize(Eigen::Index n, int count) {
    return std::min<Eigen::Index>(n, std::max<Eigen::Index>(2 * Eigen::Index(count) + 1, 20));
}

double rigidBodyThreshold(const SparseMatrix& K, const SparseMatrix& M) {
    return 1e-10 * K.diagonal().sum() / M.diagonal().sum();
}

Eigen::VectorXd Eigenmodes::frequenciesHz() const {
    Eigen::VectorXd f(eigenvalues.size());
    for (Eigen::Index i = 0; i < f.size(); ++i)
        f(i) = std::copysign(std::sqrt(std::abs(eigenvalues(i))), eigenvalues(i)) / (2.0 * std::numbers::pi);
    return f;
}

Eigenmodes solveEigenmodes(const SparseMatrix& K, const SparseMatrix& M, const EigenmodeOptions& opt,
                           const StaticSolver* factorOfK) {
    const Eigen::Index n = K.rows();
    if (K.cols() != n || M.rows() != n || M.cols() != n)
        throw std::invalid_argument("eigenmodes: K and M must be square and of equal size");
    if (opt.count < 1 || opt.count >= n)
        throw std::invalid_argument("eigenmodes: number of modes must be in [1, " + std::to_string(n - 1) +
                                    "], got " + std::to_string(opt.count));
    Eigenmodes out;
    if (factorOfK && factorOfK->size() != n)
        throw std::invalid_argument("eigenmodes: the given factorization does not match K");
    out.shift = factorOfK ? 0.0 : opt.shift != 0.0 ? opt.shift : automaticShift(K, M);

    CholmodShiftInvert op(K, M, factorOfK);
    op.progress = opt.progress;
    op.progressSeconds = opt.progressSeconds;
    Spectra::SparseSymMatProd<double, Eigen::Upper> Bop(M);
    const Eigen::Index ncv = lanczosBasisSize(n, opt.count);
    Spectra::SymGEigsShiftSolver<CholmodShiftInvert, decltype(Bop), Spectra::GEigsMode::ShiftInvert> eigs(
        op, Bop, opt.count, ncv, out.shift);
    const Stopwatch t0;
    op.started = op.lastReport = t0;
    eigs.init();
    Eigen::Index nconv = 0;
    try {
        nconv = eigs.compute(Spectra::SortRule::LargestMagn, opt.maxIterations, opt.tolerance,
                             Spectra::SortRule::SmallestAlge);
    } catch (const std::exception&) {  // Spectra's own words name its internals, not the problem
        throw std::runtime_error(
            "eigenmodes: the Lanczos iteration broke down on numbers that are not finite: the stiffness or "
            "mass matrix is out of range (check the material constants and the mesh's size and units)");
    }
    if (eigs.info() != Spectra::CompInfo::Successful)
        throw std::runtime_error("eigenmodes: Lanczos did not converge (" + std::to_string(nconv) + " of " +
                                 std::to_string(opt.count) + " modes after " +
                                 std::to_string(eigs.num_iterations()) + " restarts)");
    out.eigenvalues = eigs.eigenvalues();
    out.shapes = eigs.eigenvectors();
    // Normalise to φᵀMφ = 1 explicitly (independent of Spectra's internal scaling).
    for (Eigen::Index k = 0; k < out.shapes.cols(); ++k) {
        const double m = out.shapes.col(k).dot(M.selfadjointView<Eigen::Upper>() * out.shapes.col(k));
        out.shapes.col(k) /= std::sqrt(m);
    }
    out.iterations = static_cast<int>(eigs.num_iterations());
    out.operations = op.operations;
    out.factorSeconds = op.factorSeconds;
    out.solveSeconds = t0.seconds();
    return out;
}

}  // namespace flexehd::fem
