// The V-cycle of the truncated linear correction problem: the fused three-pass cycle of z-line
// levels (smoothing, residual, restriction, prolongation and the fine line search in shared
// sweeps) and the plain one of the other levels (docs/lube.md §3).
#include <algorithm>
#include <cmath>

#include "lube/multigrid/MultigridHierarchy.hpp"

namespace flexehd::lube {

using namespace multigrid;


// One V-cycle step on a level smoothed by zebra z-lines (L.lines == Z), with the passes fused:
// pre-smoothing + residual + restriction in three sweeps over the rows, post-smoothing +
// prolongation in three more (plus, on the fine level, the search direction and the line-search
// products). Even columns are eliminated top down (Thomas), odd columns bottom up (reverse
// Thomas), so that
//   pass A (rows ↓): forward elimination of the even lines;
//   pass B (rows ↑): back substitution of the even lines, elimination of the odd lines one row
//                    behind (their right-hand side needs the new even values of rows i ± 1);
//   pass C (rows ↓): back substitution of the odd lines; one row behind, the residual of the
//                    final values and its restriction (pre-smoothing), or the line search (fine
//                    level, post-smoothing).
// A line Gauss–Seidel step overwrites a whole line whatever its old values, so the correction
// starts at zero without clearing x (the pre-smoothing's even lines see f only), and the coarse
// correction need only be added to the odd columns before the post-smoothing (all columns when a
// periodic level has an odd number of columns, where columns nθ − 1 and 0 are both even).
template <bool Five>
void MultigridSolver::Hierarchy::vcycleZT(std::size_t l, LineSearch* ls) {
    using St = Stencil<Five>;
    Level& L = levels[l];
    Level& C = levels[l + 1];
    // The line factors, unless deferred to the pre-smoothing's eliminations (factorZT).
    const bool factorInPasses = factorZT<Five>(L, true);
    const int nz = L.nz, nt = L.nt;
    // No two of these overlap (restrict lets the compiler keep loaded values across stores).
    double* __restrict x = L.x.data();
    double* __restrict R = L.q.data();
    const double* __restrict f = L.f.data();
    double* __restrict M = L.zm.data();
    double* __restrict W = L.zw.data();
    const int* __restrict colLo = L.colLo.data();
    const int* __restrict colHi = L.colHi.data();
    const char* __restrict fr = L.free.data();
    const double* __restrict A = L.a;
    const bool allColumns = L.periodic && nt % 2 == 1;  // even columns need the correction too

    // Right-hand side of line j at row i from the other-coloured columns (and corners).
    auto lineRhs = [&](const auto& c, double fk, const double* xm, const double* x0, const double* xp,
                       int jm, int jp) {
        double r = fk - (c[St::W] * x0[jm] + c[St::E] * x0[jp]);
        if constexpr (!Five) r -= c[0] * xm[jm] + c[2] * xm[jp] + c[6] * xp[jm] + c[8] * xp[jp];
        return r;
    };
    const int* jmv = L.jmv.data();
    const int* jpv = L.jpv.data();
    // fn(j) for the columns of row i in their free range, by parity (runs of factorZT).
    auto eachCol = [](const int* runs, const int* rowRuns, int i, auto&& fn) {
        for (int q = rowRuns[i], qEnd = rowRuns[i + 1]; q < qEnd; q += 2)
            for (int j = runs[q], end = runs[q + 1]; j < end; j += 2) fn(j);
    };
    const int* evenRuns = L.evenRuns.data();
    const int* rowEven = L.rowEven.data();
    const int* oddRuns = L.oddRuns.data();
    const int* rowOdd = L.rowOdd.data();
    auto eachEven = [&](int i, auto&& fn) { eachCol(evenRuns, rowEven, i, fn); };
    auto eachOdd = [&](int i, auto&& fn) { eachCol(oddRuns, rowOdd, i, fn); };
    // Factor: also the deferred line factors of the row (factorZT's top-down formulas).
    auto evenElim = [&](auto factorTag, int i, bool pre) {
        constexpr bool Factor = decltype(factorTag)::value;
        const double* xm = x + L.im(i) * nt;
        const double* x0 = x + i * nt;
        const double* xp = x + L.ip(i) * nt;
        const int row = i * nt;
        const auto rs = rowStencil<Five>(A, nz, nt, i);
        eachEven(i, [&](const int j) {
            const int k = row + j;
            if (!fr[k]) {
                R[k] = 0.0;
                if constexpr (Factor) M[k] = W[k] = 0.0;
                return;
            }
            const auto c = rs.at(j);
            if constexpr (Factor) {
                const double m = safeInverse(c[St::C] - (i > colLo[j] ? c[St::S] * W[k - nt] : 0.0), c[St::C]);
                M[k] = m;
                W[k] = c[St::N] * m;
            }
            const double s = i > 0 ? c[St::S] * R[k - nt] : 0.0;
            const double rhs = pre ? f[k] : lineRhs(c, f[k], xm, x0, xp, jmv[j], jpv[j]);
            R[k] = (rhs - s) * M[k];
        });
    };
    auto evenBack = [&](int i) {
        const int row = i * nt;
        if (i + 1 < nz)
            eachEven(i, [&](const int j) { x[row + j] = R[row + j] - W[row + j] * x[row + j + nt]; });
        else
            eachEven(i, [&](const int j) { x[row + j] = R[row + j]; });
    };
    // Factor: also the deferred line factors of the row (factorZT's bottom-up formulas; the rows
    // below are done, pass B runs upwards).
    auto oddElim = [&](auto factorTag, int i) {
        constexpr bool Factor = decltype(factorTag)::value;
        const double* xm = x + L.im(i) * nt;
        const double* x0 = x + i * nt;
        const double* xp = x + L.ip(i) * nt;
        const int row = i * nt;
        const auto rs = rowStencil<Five>(A, nz, nt, i);
        eachOdd(i, [&](const int j) {
            const int k = row + j;
            if (!fr[k]) {
                R[k] = 0.0;
                if constexpr (Factor) M[k] = W[k] = 0.0;
                return;
            }
            const auto c = rs.at(j);
            if constexpr (Factor) {
                const double m = safeInverse(c[St::C] - (i < colHi[j] ? c[St::N] * W[k + nt] : 0.0), c[St::C]);
                M[k] = m;
                W[k] = c[St::S] * m;
            }
            const double nn = i + 1 < nz ? c[St::N] * R[k + nt] : 0.0;
            R[k] = (lineRhs(c, f[k], xm, x0, xp, jmv[j], jpv[j]) - nn) * M[k];
        });
    };
    auto oddBack = [&](int i) {
        const int row = i * nt;
        if (i > 0)
            eachOdd(i, [&](const int j) { x[row + j] = R[row + j] - W[row + j] * x[row + j - nt]; });
        else
            eachOdd(i, [&](const int j) { x[row + j] = R[row + j]; });
    };
    auto passB = [&](auto factorTag) {
        for (int i = nz - 1; i >= 0; --i) {
            evenBack(i);
            if (i + 1 < nz) oddElim(factorTag, i + 1);
        }
        oddElim(factorTag, 0);
    };
    // Residual of row i, restricted to the coarse right-hand side.
    double* __restrict cf = C.f.data();
    const int ntC = C.nt;
    auto restrictRow = [&](int i) {
        const auto si = static_cast<std::size_t>(i);
        double* c0 = cf + L.pz0[si] * ntC;
        double* c1 = cf + L.pz1[si] * ntC;
        const double w0 = L.wz0[si], w1 = L.wz1[si];
        const double* xm = x + L.im(i) * nt;
        const double* x0 = x + i * nt;
        const double* xp = x + L.ip(i) * nt;
        const auto rs = rowStencil<Five>(A, nz, nt, i);
        auto node = [&](int j) {
            const int k = i * nt + j;
            if (!fr[k]) return;
            const auto c = rs.at(j);
            const double r = f[k] - (c[St::C] * x0[j] + offDiag<Five>(c, xm, x0, xp, j, jmv[j], jpv[j]));
            const auto sj = static_cast<std::size_t>(j);
            const int J0 = L.pt0[sj], J1 = L.pt1[sj];
            const double wt1 = L.wt1[sj], a0 = L.wt0[sj] * r, a1 = wt1 * r;
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
            if (M[i * nt + j] == 0.0) node(j);
        });
    };
    // Coarse correction of row i (the columns the post-smoothing reads).
    const double* __restrict cx = C.x.data();
    auto correctRow = [&](int i) {
        const auto si = static_cast<std::size_t>(i);
        const double* c0 = cx + L.pz0[si] * ntC;
        const double* c1 = cx + L.pz1[si] * ntC;
        const double w0 = L.wz0[si], w1 = L.wz1[si];
        auto node = [&](int j) {
            const int k = i * nt + j;
            if (!fr[k]) return;
            const auto sj = static_cast<std::size_t>(j);
            const int J0 = L.pt0[sj], J1 = L.pt1[sj];
            x[k] += w0 * (L.wt0[sj] * c0[J0] + L.wt1[sj] * c0[J1]) + w1 * (L.wt0[sj] * c1[J0] + L.wt1[sj] * c1[J1]);
        };
        eachOdd(i, node);
        if (allColumns) eachEven(i, node);
    };

    // Pre-smoothing, residual, restriction.
    if (factorInPasses) {
        for (int i = 0; i < nz; ++i) evenElim(std::true_type{}, i, true);
        passB(std::true_type{});
    } else {
        for (int i = 0; i < nz; ++i) evenElim(std::false_type{}, i, true);
        passB(std::false_type{});
    }
    C.f.setZero();
    for (int i = 0; i < nz; ++i) {
        oddBack(i);
        if (i > 0) restrictRow(i - 1);
    }
    restrictRow(nz - 1);
    vcycle(l + 1);

    // Prolongation, post-smoothing (and the line search on the fine level).
    correctRow(0);
    for (int i = 0; i < nz; ++i) {
        if (i + 1 < nz) correctRow(i + 1);
        evenElim(std::false_type{}, i, false);
    }
    passB(std::false_type{});
    if (!ls) {
        for (int i = 0; i < nz; ++i) oddBack(i);
        return;
    }
    for (int i = 0; i < nz; ++i) {
        oddBack(i);
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
