// The V-cycle of the truncated linear correction problem: the fused three-pass cycle of z-line
// levels (smoothing, residual, restriction, prolongation and the fine line search in shared
// sweeps) and the plain one of the other levels (docs/lube.md §3).
#include <algorithm>
#include <cmath>

#include "lube/multigrid/MultigridHierarchy.hpp"

namespace flexehd::lube {

using namespace multigrid;


namespace {

// The sweeps of one fused V-cycle step on a level smoothed by zebra z-lines (L.lines == Z) and
// its coarser level C, over the level's arrays (no two of them overlap: restrict lets the
// compiler keep loaded values across stores). Even columns are eliminated top down (Thomas),
// odd columns bottom up (reverse Thomas); see vcycleZT for the order of the passes.
template <bool Five>
class ZebraCycle {
    using St = Stencil<Five>;

public:
    ZebraCycle(Level& L, Level& C)
        : L_(L), nz_(L.nz), nt_(L.nt), x_(L.x.data()), R_(L.q.data()), f_(L.f.data()), M_(L.zm.data()),
          W_(L.zw.data()), colLo_(L.colLo.data()), colHi_(L.colHi.data()), fr_(L.free.data()), A_(L.a),
          allColumns_(L.periodic && L.nt % 2 == 1), jmv_(L.jmv.data()), jpv_(L.jpv.data()),
          evenRuns_(L.evenRuns.data()), rowEven_(L.rowEven.data()), oddRuns_(L.oddRuns.data()),
          rowOdd_(L.rowOdd.data()), cf_(C.f.data()), cx_(C.x.data()), ntC_(C.nt) {}

    // Pass A, row i: forward elimination of the even lines (pre: the correction starts at zero,
    // the right-hand side is f alone). Factor: also the deferred line factors of the row
    // (factorZT's top-down formulas).
    template <bool Factor>
    void evenElim(int i, bool pre) {
        double* __restrict R = R_;
        double* __restrict M = M_;
        double* __restrict W = W_;
        const double* xm = x_ + L_.im(i) * nt_;
        const double* x0 = x_ + i * nt_;
        const double* xp = x_ + L_.ip(i) * nt_;
        const int row = i * nt_;
        const auto rs = rowStencil<Five>(A_, nz_, nt_, i);
        eachEven(i, [&](const int j) {
            const int k = row + j;
            if (!fr_[k]) {
                R[k] = 0.0;
                if constexpr (Factor) M[k] = W[k] = 0.0;
                return;
            }
            const auto c = rs.at(j);
            if constexpr (Factor) {
                const double m = safeInverse(c[St::C] - (i > colLo_[j] ? c[St::S] * W[k - nt_] : 0.0), c[St::C]);
                M[k] = m;
                W[k] = c[St::N] * m;
            }
            const double s = i > 0 ? c[St::S] * R[k - nt_] : 0.0;
            const double rhs = pre ? f_[k] : lineRhs(c, f_[k], xm, x0, xp, jmv_[j], jpv_[j]);
            R[k] = (rhs - s) * M[k];
        });
    }
    void evenBack(int i) {
        double* __restrict x = x_;
        const double* __restrict R = R_;
        const double* __restrict W = W_;
        const int row = i * nt_;
        if (i + 1 < nz_)
            eachEven(i, [&](const int j) { x[row + j] = R[row + j] - W[row + j] * x[row + j + nt_]; });
        else
            eachEven(i, [&](const int j) { x[row + j] = R[row + j]; });
    }
    // Elimination of the odd lines, row i. Factor: also the deferred line factors of the row
    // (factorZT's bottom-up formulas; the rows below are done, pass B runs upwards).
    template <bool Factor>
    void oddElim(int i) {
        double* __restrict R = R_;
        double* __restrict M = M_;
        double* __restrict W = W_;
        const double* xm = x_ + L_.im(i) * nt_;
        const double* x0 = x_ + i * nt_;
        const double* xp = x_ + L_.ip(i) * nt_;
        const int row = i * nt_;
        const auto rs = rowStencil<Five>(A_, nz_, nt_, i);
        eachOdd(i, [&](const int j) {
            const int k = row + j;
            if (!fr_[k]) {
                R[k] = 0.0;
                if constexpr (Factor) M[k] = W[k] = 0.0;
                return;
            }
            const auto c = rs.at(j);
            if constexpr (Factor) {
                const double m = safeInverse(c[St::C] - (i < colHi_[j] ? c[St::N] * W[k + nt_] : 0.0), c[St::C]);
                M[k] = m;
                W[k] = c[St::S] * m;
            }
            const double nn = i + 1 < nz_ ? c[St::N] * R[k + nt_] : 0.0;
            R[k] = (lineRhs(c, f_[k], xm, x0, xp, jmv_[j], jpv_[j]) - nn) * M[k];
        });
    }
    void oddBack(int i) {
        double* __restrict x = x_;
        const double* __restrict R = R_;
        const double* __restrict W = W_;
        const int row = i * nt_;
        if (i > 0)
            eachOdd(i, [&](const int j) { x[row + j] = R[row + j] - W[row + j] * x[row + j - nt_]; });
        else
            eachOdd(i, [&](const int j) { x[row + j] = R[row + j]; });
    }
    // Pass A over all rows.
    template <bool Factor>
    void passA(bool pre) {
        for (int i = 0; i < nz_; ++i) evenElim<Factor>(i, pre);
    }
    // Pass B (rows ↑): back substitution of the even lines, elimination of the odd lines one row
    // behind (their right-hand side needs the new even values of rows i ± 1).
    template <bool Factor>
    void passB() {
        for (int i = nz_ - 1; i >= 0; --i) {
            evenBack(i);
            if (i + 1 < nz_) oddElim<Factor>(i + 1);
        }
        oddElim<Factor>(0);
    }
    // Residual of row i, restricted to the coarse right-hand side.
    void restrictRow(int i) {
        const auto si = static_cast<std::size_t>(i);
        double* c0 = cf_ + L_.pz0[si] * ntC_;
        double* c1 = cf_ + L_.pz1[si] * ntC_;
        const double w0 = L_.wz0[si], w1 = L_.wz1[si];
        const double* xm = x_ + L_.im(i) * nt_;
        const double* x0 = x_ + i * nt_;
        const double* xp = x_ + L_.ip(i) * nt_;
        const auto rs = rowStencil<Five>(A_, nz_, nt_, i);
        auto node = [&](int j) {
            const int k = i * nt_ + j;
            if (!fr_[k]) return;
            const auto c = rs.at(j);
            const double r = f_[k] - (c[St::C] * x0[j] + offDiag<Five>(c, xm, x0, xp, j, jmv_[j], jpv_[j]));
            const auto sj = static_cast<std::size_t>(j);
            const int J0 = L_.pt0[sj], J1 = L_.pt1[sj];
            const double wt1 = L_.wt1[sj], a0 = L_.wt0[sj] * r, a1 = wt1 * r;
            // Zero weights (a fine row or column on a coarse one: most nodes) skipped; the
            // tests are uniform along a row and within a column parity.
            c0[J0] += w0 * a0;
            if (wt1 != 0.0) c0[J1] += w0 * a1;
            if (w1 != 0.0) {
                c1[J0] += w1 * a0;
                if (wt1 != 0.0) c1[J1] += w1 * a1;
            }
        };
        eachEven(i, node);
        // An odd line was solved last, against the final even lines, so its residual is zero
        // (rounding aside) — except at a node left out of its line solve (zero pivot inverse).
        eachOdd(i, [&](const int j) {
            if (M_[i * nt_ + j] == 0.0) node(j);
        });
    }
    // Coarse correction of row i (the columns the post-smoothing reads).
    void correctRow(int i) {
        const auto si = static_cast<std::size_t>(i);
        const double* c0 = cx_ + L_.pz0[si] * ntC_;
        const double* c1 = cx_ + L_.pz1[si] * ntC_;
        const double w0 = L_.wz0[si], w1 = L_.wz1[si];
        double* __restrict x = x_;
        auto node = [&](int j) {
            const int k = i * nt_ + j;
            if (!fr_[k]) return;
            const auto sj = static_cast<std::size_t>(j);
            const int J0 = L_.pt0[sj], J1 = L_.pt1[sj];
            x[k] += w0 * (L_.wt0[sj] * c0[J0] + L_.wt1[sj] * c0[J1]) + w1 * (L_.wt0[sj] * c1[J0] + L_.wt1[sj] * c1[J1]);
        };
        eachOdd(i, node);
        if (allColumns_) eachEven(i, node);
    }

private:
    // Right-hand side of line j at row i from the other-coloured columns (and corners).
    template <class Coefficients>
    static double lineRhs(const Coefficients& c, double fk, const double* xm, const double* x0, const double* xp,
                          int jm, int jp) {
        double r = fk - (c[St::W] * x0[jm] + c[St::E] * x0[jp]);
        if constexpr (!Five) r -= c[0] * xm[jm] + c[2] * xm[jp] + c[6] * xp[jm] + c[8] * xp[jp];
        return r;
    }
    // fn(j) for the columns of row i in their free range, by parity (runs of factorZT).
    template <class Fn>
    static void eachCol(const int* runs, const int* rowRuns, int i, Fn&& fn) {
        for (int q = rowRuns[i], qEnd = rowRuns[i + 1]; q < qEnd; q += 2)
            for (int j = runs[q], end = runs[q + 1]; j < end; j += 2) fn(j);
    }
    template <class Fn>
    void eachEven(int i, Fn&& fn) const { eachCol(evenRuns_, rowEven_, i, fn); }
    template <class Fn>
    void eachOdd(int i, Fn&& fn) const { eachCol(oddRuns_, rowOdd_, i, fn); }

    const Level& L_;
    const int nz_, nt_;
    double* const x_;
    double* const R_;
    const double* const f_;
    double* const M_;
    double* const W_;
    const int* const colLo_;
    const int* const colHi_;
    const char* const fr_;
    const double* const A_;
    const bool allColumns_;  // a periodic level with an odd number of columns: even ones need the correction too
    const int* const jmv_;
    const int* const jpv_;
    const int* const evenRuns_;
    const int* const rowEven_;
    const int* const oddRuns_;
    const int* const rowOdd_;
    double* const cf_;
    const double* const cx_;
    const int ntC_;
};

}  // namespace

// One V-cycle step on a level smoothed by zebra z-lines (L.lines == Z), with the passes fused:
// pre-smoothing + residual + restriction in three sweeps over the rows, post-smoothing +
// prolongation in three more (plus, on the fine level, the search direction and the line-search
// products):
//   pass A (rows ↓): forward elimination of the even lines;
//   pass B (rows ↑): back substitution of the even lines, elimination of the odd lines one row
//                    behind;
//   pass C (rows ↓): back substitution of the odd lines; one row behind, the residual of the
//                    final values and its restriction (pre-smoothing), or the line search (fine
//                    level, post-smoothing).
// A line Gauss–Seidel step overwrites a whole line whatever its old values, so the correction
// starts at zero without clearing x (the pre-smoothing's even lines see f only), and the coarse
// correction need only be added to the odd columns before the post-smoothing (all columns when a
// periodic level has an odd number of columns, where columns nθ − 1 and 0 are both even).
template <bool Five>
void MultigridSolver::Hierarchy::vcycleZT(std::size_t l, LineSearch* ls) {
    Level& L = levels[l];
    Level& C = levels[l + 1];
    // The line factors, unless deferred to the pre-smoothing's eliminations (factorZT).
    const bool factorInPasses = factorZT<Five>(L, true);
    ZebraCycle<Five> z(L, C);
    const int nz = L.nz;

    // Pre-smoothing, residual, restriction.
    if (factorInPasses) {
        z.template passA<true>(true);
        z.template passB<true>();
    } else {
        z.template passA<false>(true);
        z.template passB<false>();
    }
    C.f.setZero();
    for (int i = 0; i < nz; ++i) {
        z.oddBack(i);
        if (i > 0) z.restrictRow(i - 1);
    }
    z.restrictRow(nz - 1);
    vcycle(l + 1);

    // Prolongation, post-smoothing (and the line search on the fine level).
    z.correctRow(0);
    for (int i = 0; i < nz; ++i) {
        if (i + 1 < nz) z.correctRow(i + 1);
        z.template evenElim<false>(i, false);
    }
    z.template passB<false>();
    if (!ls) {
        for (int i = 0; i < nz; ++i) z.oddBack(i);
        return;
    }
    for (int i = 0; i < nz; ++i) {
        z.oddBack(i);
        ls->direction(L, i);
        if (i > 0) ls->curvature(L, i - 1);
    }
    ls->curvature(L, nz - 1);
}

template <bool Five>
void MultigridSolver::Hierarchy::residualT(Level& L) {
    if (L.r.size() != L.size()) L.r.resize(L.size());
    const double* x = L.x.data();
    for (int i = 0; i < L.nz; ++i)
        for (int j = 0; j < L.nt; ++j) {
            const int k = i * L.nt + j;
            L.r[k] = L.free[static_cast<std::size_t>(k)]
                         ? L.f[k] - stencilAt<Five>(L.a, L.nz, L.nt, i, j)[Stencil<Five>::C] * x[k] -
                               offDiagonalSum<Five>(L, x, i, j)
                         : 0.0;
        }
}

void MultigridSolver::Hierarchy::residual(Level& L) {
    if (L.five) residualT<true>(L);
    else residualT<false>(L);
}

void MultigridSolver::Hierarchy::vcycle(std::size_t l) {
    Level& L = levels[l];
    if (L.fusedZ) {
        if (L.five) vcycleZT<true>(l, nullptr);
        else vcycleZT<false>(l, nullptr);
        return;
    }
    L.x.setZero();
    if (l + 1 == levels.size()) {
        if (L.direct) {
            if (L.dense.empty()) return;
            for (std::size_t q = 0; q < L.dense.size(); ++q) L.denseRhs[static_cast<Eigen::Index>(q)] = L.f[L.dense[q]];
            // LDLT solve by hand: pivots below 1e-11 of the largest count as zero (Eigen's own
            // solve only drops exact zeros). A heavily truncated basis can make the coarsest
            // operator semidefinite; rounding then leaves pivots of order 1e-16 instead of 0,
            // whose huge components would spoil the correction.
            Eigen::VectorXd y = ldlt.transpositionsP() * L.denseRhs;
            ldlt.matrixL().solveInPlace(y);
            const Eigen::VectorXd& D = ldlt.vectorD();
            const double tiny = 1e-11 * D.cwiseAbs().maxCoeff();
            for (Eigen::Index q = 0; q < y.size(); ++q) y[q] = std::abs(D[q]) > tiny ? y[q] / D[q] : 0.0;
            ldlt.matrixU().solveInPlace(y);
            y = ldlt.transpositionsP().transpose() * y;
            for (std::size_t q = 0; q < L.dense.size(); ++q) L.x[L.dense[q]] = y[static_cast<Eigen::Index>(q)];
        } else {
            for (int s = 0; s < 10; ++s) smooth(L, s % 2 == 0);  // grid that cannot coarsen
        }
        return;
    }
    Level& C = levels[l + 1];
    smooth(L, true);
    residual(L);
    C.f.setZero();
    for (int i = 0; i < L.nz; ++i)
        for (int j = 0; j < L.nt; ++j) {
            const int k = i * L.nt + j;
            if (!L.free[static_cast<std::size_t>(k)]) continue;
            const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
            const double r = L.r[k];
            C.f[L.pz0[si] * C.nt + L.pt0[sj]] += L.wz0[si] * L.wt0[sj] * r;
            C.f[L.pz0[si] * C.nt + L.pt1[sj]] += L.wz0[si] * L.wt1[sj] * r;
            C.f[L.pz1[si] * C.nt + L.pt0[sj]] += L.wz1[si] * L.wt0[sj] * r;
            C.f[L.pz1[si] * C.nt + L.pt1[sj]] += L.wz1[si] * L.wt1[sj] * r;
        }
    vcycle(l + 1);
    for (int i = 0; i < L.nz; ++i)
        for (int j = 0; j < L.nt; ++j) {
            const int k = i * L.nt + j;
            if (!L.free[static_cast<std::size_t>(k)]) continue;
            const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
            L.x[k] += L.wz0[si] * (L.wt0[sj] * C.x[L.pz0[si] * C.nt + L.pt0[sj]] +
                                   L.wt1[sj] * C.x[L.pz0[si] * C.nt + L.pt1[sj]]) +
                      L.wz1[si] * (L.wt0[sj] * C.x[L.pz1[si] * C.nt + L.pt0[sj]] +
                                   L.wt1[sj] * C.x[L.pz1[si] * C.nt + L.pt1[sj]]);
        }
    smooth(L, false);
}



template void MultigridSolver::Hierarchy::vcycleZT<true>(std::size_t, LineSearch*);
template void MultigridSolver::Hierarchy::vcycleZT<false>(std::size_t, LineSearch*);

}  // namespace flexehd::lube
