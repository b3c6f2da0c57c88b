// Line Gauss–Seidel smoothers of the multigrid levels: zebra z-lines (Thomas, factorizations
// cached per column), cyclic θ-lines (Sherman–Morrison), alternating (docs/lube.md §3).
#include <algorithm>
#include <cmath>

#include "lube/multigrid/MultigridHierarchy.hpp"

namespace flexehd::lube {

using namespace multigrid;


namespace {

// First and last free row of every column into a, b (nz, −1: none), row by row (contiguous,
// branch-free).
void freeRowRanges(const Level& L, int* a, int* b) {
    const int nt = L.nt, nz = L.nz;
    const char* fr = L.free.data();
    std::fill_n(a, nt, nz);
    std::fill_n(b, nt, -1);
    for (int i = 0; i < nz; ++i) {
        const char* f = fr + i * nt;
        for (int j = 0; j < nt; ++j) {
            a[j] = f[j] && a[j] == nz ? i : a[j];
            b[j] = f[j] ? i : b[j];
        }
    }
}

// The stale columns' valid factor rows (from, to) and, on fused levels (ranged), their new free
// row ranges [a, b] from freeRowRanges, with x and q cleared where the sweeps read them outside.
void updateColumnRanges(Level& L, const std::vector<int>& down, const std::vector<int>& up, bool ranged,
                        const int* rangeLo, const int* rangeHi) {
    const int nt = L.nt, nz = L.nz;
    int* from = L.colFrom.data();
    int* to = L.colTo.data();
    int* lo = L.colLo.data();
    int* hi = L.colHi.data();
    double* x = L.x.data();
    double* q = L.q.data();
    for (const std::vector<int>* v : {&down, &up})
        for (const int j : *v) {
            // Rows outside the old range were not factored: a top-down factor is valid only up
            // to the old last free row, a bottom-up one down to the old first (empty range:
            // lo = nz, hi = −1, nothing valid).
            from[j] = std::min(from[j], hi[j] + 1);
            to[j] = std::max(to[j], lo[j] - 1);
            if (!ranged) {
                lo[j] = 0;
                hi[j] = nz - 1;
                continue;
            }
            // New range (from freeRowRanges). The sweeps skip the rows outside, and read
            // them as neighbours (x) and as the eliminated row next to the range (q): x = 0 on the
            // rows that leave it (outside the old range it is 0 already), q = 0 next to it.
            const int a = rangeLo[j], b = rangeHi[j];
            for (int i = lo[j]; i <= hi[j]; ++i)
                if (i < a || i > b) x[i * nt + j] = 0.0;
            if (a > 0 && a < nz) q[(a - 1) * nt + j] = 0.0;
            if (b >= 0 && b + 1 < nz) q[(b + 1) * nt + j] = 0.0;
            lo[j] = a;
            hi[j] = b;
        }
}

// The Thomas factors of the stale columns, row by row (contiguous memory) from the first changed
// row: top down for `down`, bottom up for `up`.
template <bool Five>
void factorColumns(Level& L, const std::vector<int>& down, const std::vector<int>& up) {
    using St = Stencil<Five>;
    const int nt = L.nt, nz = L.nz;
    double* zm = L.zm.data();
    double* zw = L.zw.data();
    const char* fr = L.free.data();
    const int* from = L.colFrom.data();
    const int* to = L.colTo.data();
    const int* lo = L.colLo.data();
    const int* hi = L.colHi.data();
    for (int i = 0; i < nz; ++i)
        for (const int j : down) {
            if (i < from[j] || i < lo[j] || i > hi[j]) continue;
            const auto sk = static_cast<std::size_t>(i * nt + j);
            if (!fr[sk]) {
                zm[sk] = zw[sk] = 0.0;
                continue;
            }
            const auto c = stencilAt<Five>(L.a, nz, nt, i, j);
            const double m = safeInverse(c[St::C] - (i > lo[j] ? c[St::S] * zw[sk - static_cast<std::size_t>(nt)] : 0.0), c[St::C]);
            zm[sk] = m;
            zw[sk] = c[St::N] * m;
        }
    for (int i = nz - 1; i >= 0; --i)
        for (const int j : up) {
            if (i > to[j] || i < lo[j] || i > hi[j]) continue;
            const auto sk = static_cast<std::size_t>(i * nt + j);
            if (!fr[sk]) {
                zm[sk] = zw[sk] = 0.0;
                continue;
            }
            const auto c = stencilAt<Five>(L.a, nz, nt, i, j);
            const double m = safeInverse(c[St::C] - (i < hi[j] ? c[St::N] * zw[sk + static_cast<std::size_t>(nt)] : 0.0), c[St::C]);
            zm[sk] = m;
            zw[sk] = c[St::S] * m;
        }
}

// Runs [first, end) of the in-range columns of one parity per row (row[i + 1]: the runs up to
// row i), column j + 2 continuing a run that ends at j.
void columnRuns(const Level& L, const std::vector<int>& cols, std::vector<int>& row, std::vector<int>& runs) {
    const int* lo = L.colLo.data();
    const int* hi = L.colHi.data();
    for (int i = 0; i < L.nz; ++i) {
        int first = -1, last = 0;
        for (const int j : cols) {
            if (lo[j] > i || i > hi[j]) continue;
            if (first >= 0 && j == last + 2) {
                last = j;
                continue;
            }
            if (first >= 0) runs.insert(runs.end(), {first, last + 2});
            first = last = j;
        }
        if (first >= 0) runs.insert(runs.end(), {first, last + 2});
        row[static_cast<std::size_t>(i) + 1] = static_cast<int>(runs.size());
    }
}

}  // namespace

// Factorization of the z-lines (columns) whose stencil or truncation changed: Thomas
// multipliers of lo_i x_{i−1} + d_i x_i + up_i x_{i+1} with lo = a(−1,0), d = a(0,0),
// up = a(+1,0); frozen nodes are identity rows.
void MultigridSolver::Hierarchy::factorZ(Level& L) {
    if (L.five) factorZT<true>(L);
    else factorZT<false>(L);
}

// mayDefer (fused levels, from vcycleZT): when every column is refactored over its whole free
// range (a new hierarchy's or a full Galerkin rebuild's first V-cycle), only the ranges and row
// lists are set up and true is returned — the caller then computes the factors row by row in its
// first eliminations (same formulas, same order within each column: the same values), instead
// of in a pass of its own over the stencil.
template <bool Five>
bool MultigridSolver::Hierarchy::factorZT(Level& L, bool mayDefer) {
    const int nt = L.nt, nz = L.nz;
    if (L.zm.empty()) {
        // Written below: on first use every column is stale from row 0 (invalidateLines).
        L.zm.resize(static_cast<std::size_t>(L.size()));
        L.zw.resize(static_cast<std::size_t>(L.size()));
    }
    // Levels smoothed by the fused zebra cycle (vcycleZ, L.lines == Z) eliminate the odd columns
    // from the bottom up (reverse Thomas: x_i = R'_i − w'_i x_{i−1}), the others top down.
    const bool reverseOdd = L.fusedZ;
    std::vector<int>& down = staleDown;  // stale columns factored top down / bottom up
    std::vector<int>& up = staleUp;
    down.clear();
    up.clear();
    for (int j = 0; j < nt; ++j)
        if (!L.colOk[static_cast<std::size_t>(j)]) (reverseOdd && j % 2 == 1 ? up : down).push_back(j);
    if (down.empty() && up.empty()) return false;
    // Fused levels: the free row range of each stale column; only the rows in range are factored
    // (the fused sweeps read no factor outside; the rows next to the range are frozen, whose
    // factors are 0, so the recursions start afresh at its ends). Other levels: all rows.
    const bool ranged = L.fusedZ;
    if (ranged) freeRowRanges(L, rangeLo.data(), rangeHi.data());
    updateColumnRanges(L, down, up, ranged, rangeLo.data(), rangeHi.data());
    // Deferred to the caller when every column is stale over its whole free range.
    bool defer = mayDefer && ranged && down.size() + up.size() == static_cast<std::size_t>(nt);
    if (defer) {
        for (const int j : down) defer &= L.colFrom[sj(j)] <= L.colLo[sj(j)];
        for (const int j : up) defer &= L.colTo[sj(j)] >= L.colHi[sj(j)];
    }
    if (!defer) factorColumns<Five>(L, down, up);
    if (ranged) {
        // Per-row lists of the columns in range, by parity.
        L.rowEven.assign(static_cast<std::size_t>(nz) + 1, 0);
        L.rowOdd.assign(static_cast<std::size_t>(nz) + 1, 0);
        L.evenRuns.clear();
        L.oddRuns.clear();
        std::vector<int>& live = staleDown;  // reused: columns with a free row, by parity
        std::vector<int>& liveOdd = staleUp;
        live.clear();
        liveOdd.clear();
        for (int j = 0; j < nt; ++j)
            if (L.colLo[sj(j)] <= L.colHi[sj(j)]) (j % 2 ? liveOdd : live).push_back(j);
        columnRuns(L, live, L.rowEven, L.evenRuns);
        columnRuns(L, liveOdd, L.rowOdd, L.oddRuns);
    }
    std::fill(L.colOk.begin(), L.colOk.end(), 1);
    std::fill(L.colFrom.begin(), L.colFrom.end(), nz);
    std::fill(L.colTo.begin(), L.colTo.end(), -1);
    return defer;
}

// Zebra line Gauss–Seidel along z: the even θ columns, then the odd ones, each colour's
// tridiagonal systems eliminated together row by row (contiguous memory, unlike column-wise
// Thomas solves on a θ-fastest layout), with the cached factorizations.
template <bool Five>
void MultigridSolver::Hierarchy::lineSweepZT(Level& L, bool forward) {
    factorZ(L);
    double* x = L.x.data();
    double* R = L.q.data();
    const double* W = L.zw.data();
    const double* M = L.zm.data();
    const int nt = L.nt;
    for (int cc = 0; cc < 2; ++cc) {
        const int colour = forward ? cc : 1 - cc;
        for (int i = 0; i < L.nz; ++i) {
            const double* xm = x + L.im(i) * nt;
            const double* x0 = x + i * nt;
            const double* xp = x + L.ip(i) * nt;
            for (int j = colour; j < nt; j += 2) {
                const int k = i * nt + j;
                if (!L.free[static_cast<std::size_t>(k)]) {
                    R[k] = 0.0;
                    continue;
                }
                using St = Stencil<Five>;
                const auto c = stencilAt<Five>(L.a, L.nz, nt, i, j);
                const int jm = L.jm(j), jp = L.jp(j);
                double rhs = L.f[k] - (c[St::W] * x0[jm] + c[St::E] * x0[jp]);
                if constexpr (!Five) rhs -= c[0] * xm[jm] + c[2] * xm[jp] + c[6] * xp[jm] + c[8] * xp[jp];
                R[k] = (rhs - (i > 0 ? c[St::S] * R[k - nt] : 0.0)) * M[k];
            }
        }
        for (int i = L.nz - 1; i >= 0; --i)
            for (int j = colour; j < nt; j += 2) {
                const int k = i * nt + j;
                x[k] = i < L.nz - 1 ? R[k] - W[k] * x[k + nt] : R[k];
            }
    }
}

// Factorization of θ-line (row) i: Thomas multipliers of lo_j x_{j−1} + d_j x_j + up_j x_{j+1}
// (lo = a(0,−1), d = a(0,0), up = a(0,+1); frozen nodes identity rows). Periodic rows are cyclic
// tridiagonal, solved by Sherman–Morrison (Numerical Recipes §2.7): the corner terms α = lo_0,
// β = up_{n−1} move into a rank-one update with γ = −d_0; its vector u = T⁻¹(γ, 0, …, β) and the
// denominator 1 + u_0 + α u_{n−1}/γ are stored.
void MultigridSolver::Hierarchy::factorTheta(Level& L, int i) {
    const int nt = L.nt;
    if (L.tm.empty())
        for (auto* v : {&L.tm, &L.tw, &L.tl, &L.tu}) v->assign(static_cast<std::size_t>(L.size()), 0.0);
    const auto row = static_cast<std::size_t>(i * nt);
    for (int j = 0; j < nt; ++j) {
        const auto sj = static_cast<std::size_t>(j);
        const std::size_t k = row + sj;
        if (!L.free[k]) {
            lo[sj] = up[sj] = 0.0;
            d[sj] = 1.0;
            continue;
        }
        lo[sj] = L.coef(k, 3);
        d[sj] = L.coef(k, kDiag);
        up[sj] = L.coef(k, 5);
    }
    const auto si = static_cast<std::size_t>(i);
    const double alpha = L.periodic ? lo[0] : 0.0, beta = L.periodic ? up[sj(nt - 1)] : 0.0;
    const bool cyclic = alpha != 0.0 || beta != 0.0;
    double gamma = 0.0;
    if (cyclic) {
        gamma = -d[0];
        d[0] -= gamma;
        d[sj(nt - 1)] -= alpha * beta / gamma;
    }
    double* m = &L.tm[row];
    double* w = &L.tw[row];
    m[0] = safeInverse(d[0], d[0]);
    w[0] = up[0] * m[0];
    for (int j = 1; j < nt; ++j) {
        m[j] = safeInverse(d[sj(j)] - lo[sj(j)] * w[j - 1], d[sj(j)]);
        w[j] = up[sj(j)] * m[j];
    }
    std::copy(lo.begin(), lo.begin() + nt, L.tl.begin() + static_cast<std::ptrdiff_t>(row));
    L.tAlpha[si] = alpha;
    L.tGamma[si] = gamma;
    if (cyclic) {
        double* u = &L.tu[row];
        std::fill(u, u + nt, 0.0);
        u[0] = gamma;
        u[nt - 1] = beta;
        thomasSolve(L, i, u);
        L.tDen[si] = 1.0 + u[0] + alpha * u[nt - 1] / gamma;
    }
    L.rowOk[si] = 1;
}

// r ← T⁻¹ r for the (non-cyclic) tridiagonal matrix T of row i.
void MultigridSolver::Hierarchy::thomasSolve(const Level& L, int i, double* r) {
    const int nt = L.nt;
    const auto row = static_cast<std::size_t>(i * nt);
    const double* m = &L.tm[row];
    const double* w = &L.tw[row];
    const double* l = &L.tl[row];
    r[0] *= m[0];
    for (int j = 1; j < nt; ++j) r[j] = (r[j] - l[j] * r[j - 1]) * m[j];
    for (int j = nt - 2; j >= 0; --j) r[j] -= w[j] * r[j + 1];
}

// Line Gauss–Seidel along θ (one tridiagonal solve per axial row, cyclic when periodic), with
// the cached factorizations.
template <bool Five>
void MultigridSolver::Hierarchy::lineSweepThetaT(Level& L, bool forward) {
    double* x = L.x.data();
    const int nt = L.nt;
    for (int ii = 0; ii < L.nz; ++ii) {
        const int i = forward ? ii : L.nz - 1 - ii;
        const auto si = static_cast<std::size_t>(i);
        if (!L.rowOk[si]) factorTheta(L, i);
        const double* xm = x + L.im(i) * nt;
        const double* xp = x + L.ip(i) * nt;
        double* r = rhs.data();
        for (int j = 0; j < nt; ++j) {
            const int k = i * nt + j;
            if (!L.free[static_cast<std::size_t>(k)]) {
                r[j] = 0.0;
                continue;
            }
            using St = Stencil<Five>;
            const auto c = stencilAt<Five>(L.a, L.nz, nt, i, j);
            const int jm = L.jm(j), jp = L.jp(j);
            r[j] = L.f[k] - (c[St::S] * xm[j] + c[St::N] * xp[j]);
            if constexpr (!Five) r[j] -= c[0] * xm[jm] + c[2] * xm[jp] + c[6] * xp[jm] + c[8] * xp[jp];
        }
        thomasSolve(L, i, r);
        const double alpha = L.tAlpha[si], gamma = L.tGamma[si];
        double* xi = x + i * nt;
        if (gamma != 0.0) {
            const double* u = &L.tu[static_cast<std::size_t>(i * nt)];
            const double fact = (r[0] + alpha * r[nt - 1] / gamma) / L.tDen[si];
            for (int j = 0; j < nt; ++j) xi[j] = r[j] - fact * u[j];
        } else {
            std::copy(r, r + nt, xi);
        }
    }
}

void MultigridSolver::Hierarchy::lineSweepZ(Level& L, bool forward) {
    if (L.five) lineSweepZT<true>(L, forward);
    else lineSweepZT<false>(L, forward);
}

void MultigridSolver::Hierarchy::lineSweepTheta(Level& L, bool forward) {
    if (L.five) lineSweepThetaT<true>(L, forward);
    else lineSweepThetaT<false>(L, forward);
}

// Line Gauss–Seidel along the strongly coupled direction, alternating when neither dominates
// (chooseLines); the post-smoother runs in reverse (symmetric V-cycle).
void MultigridSolver::Hierarchy::smooth(Level& L, bool pre) {
    if (L.lines == Lines::Z) return lineSweepZ(L, pre);
    if (L.lines == Lines::Theta) return lineSweepTheta(L, pre);
    if (pre) {
        lineSweepZ(L, true);
        lineSweepTheta(L, true);
    } else {
        lineSweepTheta(L, false);
        lineSweepZ(L, false);
    }
}

template bool MultigridSolver::Hierarchy::factorZT<true>(Level&, bool);
template bool MultigridSolver::Hierarchy::factorZT<false>(Level&, bool);

}  // namespace flexehd::lube
