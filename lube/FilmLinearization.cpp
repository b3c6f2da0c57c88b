#include "lube/FilmLinearization.hpp"

#include <Eigen/CholmodSupport>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "lube/ColouredDifference.hpp"

namespace flexehd::lube {

struct FilmLinearization::Factor {
    // Simplicial: the film's 2-D factor has small supernodes, on which the supernodal method's BLAS
    // kernels gain nothing and OpenBLAS's worker threads spin (docs/benchmarks.md).
    Eigen::CholmodSimplicialLLT<SparseMatrix, Eigen::Lower> llt;
    std::vector<int> analysedFree;  // the free set whose pattern llt has analysed
    // CHOLMOD prints nothing itself: a failed factorization is reported by linearize's exception.
    Factor() { llt.cholmod().print = 0; }
};


FilmLinearization::FilmLinearization(const FilmGrid& grid)
    : grid_(&grid), colouring_(distanceTwoColouring(grid)), factor_(std::make_unique<Factor>()) {}

FilmLinearization::~FilmLinearization() = default;
FilmLinearization::FilmLinearization(FilmLinearization&&) noexcept = default;
FilmLinearization& FilmLinearization::operator=(FilmLinearization&&) noexcept = default;

void FilmLinearization::linearize(const FilmState& film, const Eigen::VectorXd& rho, const Eigen::VectorXd& eta,
                                  const Eigen::VectorXd& p, double pLower) {
    const FilmGrid& g = *grid_;
    const int n = g.size();
    if (p.size() != n)
        throw std::invalid_argument("FilmLinearization: pressure has " + std::to_string(p.size()) +
                                    " values, the grid has " + std::to_string(n) + " nodes");
    const ReynoldsSystem sys(g, film, rho, eta);
    const SparseMatrix& A = sys.matrix();
    const Eigen::VectorXd& D = sys.diagonal();
    const Eigen::VectorXd w = A * p - sys.rhs();

    // Free rows: Film nodes off the bound (the active-set rule of ActiveSetSolver).
    const bool bounded = std::isfinite(pLower);
    std::vector<char> free(static_cast<std::size_t>(n), 0);
    cavitated_ = 0;
    for (int k = 0; k < n; ++k) {
        if (!sys.isFilm(k)) continue;
        const bool cav = bounded && w[k] / D[k] > p[k] - pLower;
        free[static_cast<std::size_t>(k)] = !cav;
        cavitated_ += cav;
    }

    // The free rows, numbered: the linearised system lives on them alone.
    freeIndex_.clear();
    std::vector<int> slot(static_cast<std::size_t>(n), -1);
    for (int k = 0; k < n; ++k)
        if (free[static_cast<std::size_t>(k)]) {
            slot[static_cast<std::size_t>(k)] = int(freeIndex_.size());
            freeIndex_.push_back(k);
        }
    const int nf = int(freeIndex_.size());

    // ∂w/∂ḣ: w is affine in ḣ, so one difference with δḣ = 1 m/s is exact.
    {
        FilmState f1 = film;
        if (f1.dhdt.size() != n) f1.dhdt = Eigen::VectorXd::Zero(n);
        f1.dhdt.array() += 1.0;
        const ReynoldsSystem s1(g, f1, rho, eta);
        dwdhdt_.resize(nf);
        for (int r = 0; r < nf; ++r) dwdhdt_[r] = sys.rhs()[freeIndex_[r]] - s1.rhs()[freeIndex_[r]];
    }

    // ∂w/∂h by colour (ColouredDifference), on the free rows.
    Eigen::VectorXd w0(nf);
    for (int i = 0; i < nf; ++i) w0[i] = w[freeIndex_[static_cast<std::size_t>(i)]];
    dwdh_ = colouredThicknessDerivative(g, colouring_, film, freeIndex_, w0, [&](const FilmState& fc) {
        const ReynoldsSystem sc(g, fc, rho, eta);
        const Eigen::VectorXd wc = sc.matrix() * p - sc.rhs();
        Eigen::VectorXd rows(nf);
        for (int i = 0; i < nf; ++i) rows[i] = wc[freeIndex_[static_cast<std::size_t>(i)]];
        return rows;
    });

    // A_FF: the free rows and columns of A (the held ones are p = p_cav, Fixed and Void are
    // prescribed: their δp is 0). Its pattern changes with the free set; analysed when it does.
    std::vector<Eigen::Triplet<double>> trip;
    for (int col = 0; col < n; ++col) {
        const int cj = slot[static_cast<std::size_t>(col)];
        if (cj < 0) continue;
        for (SparseMatrix::InnerIterator e(A, col); e; ++e) {
            const int ri = slot[static_cast<std::size_t>(e.row())];
            if (ri >= 0 && ri >= cj) trip.emplace_back(ri, cj, e.value());  // lower triangle
        }
    }
    SparseMatrix M(nf, nf);
    M.setFromTriplets(trip.begin(), trip.end());
    if (factor_->analysedFree != freeIndex_) {
        factor_->llt.analyzePattern(M);
        factor_->analysedFree = freeIndex_;
    }
    if (nf > 0) {
        factor_->llt.factorize(M);
        if (factor_->llt.info() != Eigen::Success)
            throw std::runtime_error(
                "the linearised film equations on the " + std::to_string(nf) +
                " uncavitated nodes are numerically not positive definite (film thickness ratios across the grid "
                "too large for double precision, e.g. nodes at the floor of a fluid film next to open ones)");
    }
}

Eigen::MatrixXd FilmLinearization::pressureChange(const Eigen::MatrixXd& dh, const Eigen::MatrixXd& dhdt,
                                                  double dhdtScale) const {
    const int n = grid_->size();
    const Eigen::Index k = dh.size() ? dh.cols() : dhdt.cols();
    if ((dh.size() && dh.rows() != n) || (dhdt.size() && (dhdt.rows() != n || dhdt.cols() != k)) ||
        (dh.size() && dhdt.size() && dh.cols() != dhdt.cols()))
        throw std::invalid_argument("FilmLinearization::pressureChange: columns of " + std::to_string(n) +
                                    " nodes expected, of equal number for δh and δḣ");
    const int nf = int(freeIndex_.size());
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, k);
    if (nf == 0) return out;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nf, k);
    if (dh.size()) rhs.noalias() -= dwdh_ * dh;
    if (dhdt.size()) {
        const Eigen::VectorXd d = dhdtScale * dwdhdt_;
        for (Eigen::Index c = 0; c < k; ++c)
            for (int i = 0; i < nf; ++i) rhs(i, c) -= d[i] * dhdt(freeIndex_[static_cast<std::size_t>(i)], c);
    }
    const Eigen::MatrixXd dpF = factor_->llt.solve(rhs);
    for (Eigen::Index c = 0; c < k; ++c)
        for (int i = 0; i < nf; ++i) out(freeIndex_[static_cast<std::size_t>(i)], c) = dpF(i, c);
    return out;
}

}  // namespace flexehd::lube
