#include "lube/FilmLinearization.hpp"

#include <Eigen/CholmodSupport>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::lube {

struct FilmLinearization::Factor {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt;
    bool analysed = false;
};

namespace {

// The grid neighbours of node k (θ wrapped on a full circumference).
template <class Visit>
void forEachNeighbour(const FilmGrid& g, int k, Visit&& visit) {
    const int nz = g.nAxial(), nt = g.nTheta(), i = g.axialIndex(k), j = g.thetaIndex(k);
    if (i > 0) visit(g.index(i - 1, j));
    if (i + 1 < nz) visit(g.index(i + 1, j));
    if (j > 0 || g.periodic()) visit(g.index(i, (j + nt - 1) % nt));
    if (j + 1 < nt || g.periodic()) visit(g.index(i, (j + 1) % nt));
}

}  // namespace

FilmLinearization::FilmLinearization(const FilmGrid& grid) : grid_(&grid), factor_(std::make_unique<Factor>()) {
    // Greedy distance-2 colouring: a node takes the smallest colour not used within two steps.
    const int n = grid.size();
    colour_.assign(static_cast<std::size_t>(n), -1);
    std::vector<int> seen(16, -1);
    for (int k = 0; k < n; ++k) {
        auto mark = [&](int a) {
            const int c = colour_[static_cast<std::size_t>(a)];
            if (c >= 0) {
                if (c >= int(seen.size())) seen.resize(static_cast<std::size_t>(c) + 1, -1);
                seen[static_cast<std::size_t>(c)] = k;
            }
        };
        forEachNeighbour(grid, k, [&](int a) {
            mark(a);
            forEachNeighbour(grid, a, mark);
        });
        int c = 0;
        while (c < int(seen.size()) && seen[static_cast<std::size_t>(c)] == k) ++c;
        colour_[static_cast<std::size_t>(k)] = c;
        colours_ = std::max(colours_, c + 1);
    }
}

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
    free_.assign(static_cast<std::size_t>(n), 0);
    cavitated_ = 0;
    for (int k = 0; k < n; ++k) {
        if (!sys.isFilm(k)) continue;
        const bool cav = bounded && w[k] / D[k] > p[k] - pLower;
        free_[static_cast<std::size_t>(k)] = !cav;
        cavitated_ += cav;
    }

    // ∂w/∂ḣ: w is affine in ḣ, so one difference with δḣ = 1 m/s is exact.
    {
        FilmState f1 = film;
        if (f1.dhdt.size() != n) f1.dhdt = Eigen::VectorXd::Zero(n);
        f1.dhdt.array() += 1.0;
        const ReynoldsSystem s1(g, f1, rho, eta);
        dwdhdt_ = sys.rhs() - s1.rhs();
        for (int k = 0; k < n; ++k)
            if (!free_[static_cast<std::size_t>(k)]) dwdhdt_[k] = 0.0;
    }

    // ∂w/∂h by colour: row r's entry for node a (colour c) is the change of w_r when colour c
    // is perturbed, divided by δh_a. δh_a = 1e-7 h_a: truncation ~1e-7, round-off ~1e-9 relative.
    std::vector<Eigen::Triplet<double>> trip;
    trip.reserve(static_cast<std::size_t>(5 * n));
    FilmState fc = film;
    for (int c = 0; c < colours_; ++c) {
        fc.h = film.h;
        bool any = false;
        for (int k = 0; k < n; ++k)
            if (colour_[static_cast<std::size_t>(k)] == c && g.kind(k) != NodeKind::Void) {
                fc.h[k] *= 1.0 + 1e-7;
                any = true;
            }
        if (!any) continue;
        const ReynoldsSystem sc(g, fc, rho, eta);
        const Eigen::VectorXd wc = sc.matrix() * p - sc.rhs();
        for (int r = 0; r < n; ++r) {
            if (!free_[static_cast<std::size_t>(r)]) continue;
            auto add = [&](int a) {
                if (colour_[static_cast<std::size_t>(a)] != c || g.kind(a) == NodeKind::Void) return;
                const double v = (wc[r] - w[r]) / (fc.h[a] - film.h[a]);
                if (v != 0.0) trip.emplace_back(r, a, v);
            };
            add(r);
            forEachNeighbour(g, r, add);
        }
    }
    dwdh_.resize(n, n);
    dwdh_.setFromTriplets(trip.begin(), trip.end());

    // A_FF with the held (cavitated) rows and columns decoupled; the pattern stays A's.
    SparseMatrix M = A;
    for (int col = 0; col < n; ++col) {
        const bool cc = sys.isFilm(col) && !free_[static_cast<std::size_t>(col)];
        for (SparseMatrix::InnerIterator e(M, col); e; ++e) {
            const bool rc = sys.isFilm(int(e.row())) && !free_[static_cast<std::size_t>(e.row())];
            if (e.row() != col && (cc || rc)) e.valueRef() = 0.0;
        }
    }
    if (!factor_->analysed) {
        factor_->llt.analyzePattern(M);
        factor_->analysed = true;
    }
    factor_->llt.factorize(M);
    if (factor_->llt.info() != Eigen::Success)
        throw std::runtime_error("FilmLinearization: Cholesky factorization of the free film rows failed");
}

Eigen::MatrixXd FilmLinearization::pressureChange(const Eigen::MatrixXd& dh, const Eigen::MatrixXd& dhdt) const {
    const int n = grid_->size();
    const Eigen::Index k = dh.size() ? dh.cols() : dhdt.cols();
    if ((dh.size() && dh.rows() != n) || (dhdt.size() && (dhdt.rows() != n || dhdt.cols() != k)) ||
        (dh.size() && dhdt.size() && dh.cols() != dhdt.cols()))
        throw std::invalid_argument("FilmLinearization::pressureChange: columns of " + std::to_string(n) +
                                    " nodes expected, of equal number for δh and δḣ");
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, k);
    if (dh.size()) rhs.noalias() -= dwdh_ * dh;
    if (dhdt.size()) rhs -= dwdhdt_.asDiagonal() * dhdt;
    return factor_->llt.solve(rhs);
}

}  // namespace flexehd::lube
