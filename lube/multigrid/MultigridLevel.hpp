#pragma once
// One level of the multigrid hierarchy of MultigridSolver (docs/lube.md §3): its stencil in
// either layout (the fine level's symmetric 5-point one, the coarse levels' 9-point ones), the
// per-node work vectors, the cached line factorizations, the prolongation weights, and the
// stencil-access helpers of the hot loops (header-only so that they inline there).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "lube/LargeArrayAllocator.hpp"
#include "lube/ReynoldsSystem.hpp"

namespace flexehd::lube::multigrid {

// 9-point stencils on structured levels: entry s = (di+1)*3 + (dj+1) couples node (i, j) to
// (i+di, j+dj) (θ wrapped when periodic). The fine level has only the 5-point entries.
constexpr int kDiag = 4;
constexpr int sidx(int di, int dj) { return (di + 1) * 3 + (dj + 1); }
// Coarsening stops at this many nodes; the coarsest level is solved by dense LDLT (also a level
// that cannot coarsen further, up to kDirectLimit nodes; beyond that it is smoothed).
constexpr std::size_t kDirectMax = 64;
constexpr std::size_t kDirectLimit = 400;
constexpr std::size_t sj(int j) { return static_cast<std::size_t>(j); }

enum class Lines { Z, Theta, Both };

// Per-node work vector with the Eigen-like members used here: a slice of the hierarchy's arena
// (bind: one huge-page block for all the work vectors of all levels, §7 of docs/lube.md), or
// its own LargeArrayAllocator storage when it must grow beyond its slice. resize() leaves new
// doubles uninitialised (assign() zeroes) and, beyond the slice, does not keep the contents.
struct Vec {
    Vec() = default;
    Vec(Vec&&) noexcept = default;
    Vec& operator=(Vec&&) noexcept = default;
    Vec(const Vec&) = delete;  // p may point into store
    void bind(double* slice, std::size_t capacity) {
        p = slice;
        cap = capacity;
        n = 0;
    }
    void resize(std::size_t m) {
        if (m > cap) {
            store.resize(m);
            p = store.data();
            cap = m;
        }
        n = m;
    }
    void assign(std::size_t m, double v) {
        resize(m);
        std::fill(p, p + m, v);
    }
    void clear() { n = 0; }
    bool empty() const { return n == 0; }
    int size() const { return static_cast<int>(n); }
    double* data() { return p; }
    const double* data() const { return p; }
    double* begin() { return p; }
    double* end() { return p + n; }
    double& operator[](std::size_t k) { return p[k]; }
    const double& operator[](std::size_t k) const { return p[k]; }
    void setZero() { std::fill(p, p + n, 0.0); }

private:
    double* p = nullptr;
    std::size_t n = 0, cap = 0;
    LargeVector<double> store;
};

// Stencil layouts: coarse levels store 9 entries per node in sidx order; the fine level, whose
// operator is the symmetric 5-point finite-volume one, is ReynoldsSystem::stencil(): (C, E, N)
// per node, W and S read from the neighbours' E and N — 24 instead of 72 bytes per node, which
// matters because the fine-level passes are memory-bound. Entries of a node, whatever the
// layout: c[St::S] … c[St::N] with c = stencilAt<Five>(…) (a pointer, or a SymRow).
template <bool Five>
struct Stencil {
    static constexpr int S = Five ? 0 : 1, W = Five ? 1 : 3, C = Five ? 2 : 4, E = Five ? 3 : 5,
                         N = Five ? 4 : 7;
};

// The five couplings of a fine node from the symmetric storage: its own C, E, N, the E entry of
// its west neighbour (ReynoldsSystem::westStencilColumn: the wrap, or the zero E entry of the
// last column of an open arc) and the N entry of its south neighbour (row i − 1; for i = 0 the
// last row, whose N entries are 0), so no branch is needed at the edges.
struct SymRow {
    const double* c;  // C, E, N of the node
    const double* w;  // … of the west neighbour
    const double* s;  // … of the south neighbour
    double operator[](int e) const {
        switch (e) {
            case Stencil<true>::S: return s[ReynoldsSystem::kStencilN];
            case Stencil<true>::W: return w[ReynoldsSystem::kStencilE];
            case Stencil<true>::C: return c[ReynoldsSystem::kStencilC];
            case Stencil<true>::E: return c[ReynoldsSystem::kStencilE];
            default: return c[ReynoldsSystem::kStencilN];
        }
    }
};
constexpr std::size_t kSym = ReynoldsSystem::kStencilSize;

// Stencil of node (i, j) of a level with nz × nt nodes and entries A: a SymRow on the fine
// level (Five), else a pointer to its 9 entries.
template <bool Five>
inline auto stencilAt(const double* A, int nz, int nt, int i, int j) {
    if constexpr (Five) {
        const auto row = static_cast<std::size_t>(i * nt);
        return SymRow{A + kSym * (row + sj(j)),
                      A + kSym * (row + sj(ReynoldsSystem::westStencilColumn(j, nt))),
                      A + kSym * (static_cast<std::size_t>((i > 0 ? i - 1 : nz - 1) * nt) + sj(j))};
    } else {
        (void)nz;
        return A + 9 * static_cast<std::size_t>(i * nt + j);
    }
}

struct Level {
    int nz = 0, nt = 0;
    bool periodic = false;
    std::vector<double> z;     // axial coordinates (prolongation weights)
    // Stencil entries per node: 9 (coarse levels, stored in `own`), or 5 on the fine level
    // (Stencil), which is ReynoldsSystem::stencil() itself (same layout, not copied).
    const double* a = nullptr;
    Vec own;
    std::vector<char> free;    // unknown of the correction problem (else e = 0)
    Vec x, f, r;               // correction, right-hand side, residual (r: unfused levels only)
    Vec q;                     // zebra line-solve work array
    // Line factorizations, kept while the stencil and truncation of the line are unchanged:
    // z-lines (per node: Thomas multipliers zm = 1/pivot, zw = upper·zm; valid per column),
    // θ-lines (per node: tm, tw, lower coefficient tl, Sherman–Morrison vector tu; per row:
    // corner terms and denominator; valid per row).
    Vec zm, zw, tm, tw, tl, tu;
    std::vector<double> tAlpha, tGamma, tDen;
    std::vector<char> colOk, rowOk;
    // Fused z-line levels: the rows colLo … colHi of each column between its first and last free
    // node (empty: colLo > colHi) — the line sweeps visit only these, x and the line work array q
    // are kept at 0 outside (masks and cavitated ends of the columns: a third of a skirt's Film
    // columns) — as per-row runs of the columns in range, by parity (CSR: rowEven[i] …
    // rowEven[i + 1] index evenRuns, pairs [first, end) of columns j = first, first + 2, … < end:
    // direct strided loops instead of a column index per node); neighbour columns (wrapped or
    // clamped).
    std::vector<int> colLo, colHi, rowEven, evenRuns, rowOdd, oddRuns, jmv, jpv;
    // Prolongation from the next coarser level: parents of each row / column of this level.
    std::vector<int> pz0, pz1, pt0, pt1;
    std::vector<double> wz0, wz1, wt0, wt1;
    // For the Galerkin product: the parents of the neighbour row i + di (column j + dj) as slots
    // 0..2 relative to the first parent of row i (column j), with weights (0 for a missing one).
    struct Rel {
        int r[2];
        double w[2];
    };
    std::vector<Rel> zRel, tRel;  // 3 per row (di = −1, 0, 1), 3 per column
    // Coarsest level: dense factorisation on the free nodes.
    std::vector<int> dense;
    Eigen::VectorXd denseRhs;
    bool direct = false;

    bool five = false;         // 5-point stencil layout (the fine level), see Stencil
    Lines lines = Lines::Both; // smoother direction(s), from the stencil (chooseLines)
    bool fusedZ = false;       // z-lines on a level with a coarser one: fused cycle (vcycleZT)
    bool thetaHalved = false;  // the next coarser level has every other θ column (galerkinHalvedT)
    int size() const { return nz * nt; }
    /// Entry s (9-point numbering sidx) of node k's stencil, whatever the layout.
    double coef(std::size_t k, int s) const;
    // Stale line factorizations. A z-line changed in rows colFrom … colTo only: its top-down
    // factors change from colFrom down, its bottom-up factors from colTo up.
    std::vector<int> colFrom, colTo;
    void invalidateLines() {
        std::fill(colOk.begin(), colOk.end(), 0);
        std::fill(rowOk.begin(), rowOk.end(), 0);
        std::fill(colFrom.begin(), colFrom.end(), 0);
        std::fill(colTo.begin(), colTo.end(), nz - 1);
    }
    void invalidateLines(int k) {
        const auto i = static_cast<std::size_t>(k / nt), j = static_cast<std::size_t>(k % nt);
        rowOk[i] = 0;
        colOk[j] = 0;
        colFrom[j] = std::min(colFrom[j], k / nt);
        colTo[j] = std::max(colTo[j], k / nt);
    }
    // Clamped neighbour indices: an invalid neighbour maps onto a valid node whose stencil
    // coefficient is zero, so the hot loops need no branches.
    int jm(int j) const { return j > 0 ? j - 1 : (periodic ? nt - 1 : 0); }
    int jp(int j) const { return j < nt - 1 ? j + 1 : (periodic ? 0 : nt - 1); }
    int im(int i) const { return i > 0 ? i - 1 : 0; }
    int ip(int i) const { return i < nz - 1 ? i + 1 : nz - 1; }
    // Stencil entry of the coupling from (i, j) to (i2, j2), which must be a neighbour.
    int offset(int i, int j, int i2, int j2) const {
        int dt = j2 - j;
        if (periodic) {
            if (dt > 1) dt -= nt;
            if (dt < -1) dt += nt;
        }
        return sidx(i2 - i, dt);
    }
};

inline double Level::coef(std::size_t k, int s) const {
    if (!five) return a[9 * k + static_cast<std::size_t>(s)];
    constexpr int kFivePos[9] = {-1, Stencil<true>::S, -1, Stencil<true>::W, Stencil<true>::C,
                                 Stencil<true>::E, -1, Stencil<true>::N, -1};  // sidx → SymRow entry
    const int m = kFivePos[s];
    const int i = static_cast<int>(k) / nt, j = static_cast<int>(k) % nt;
    return m < 0 ? 0.0 : stencilAt<true>(a, nz, nt, i, j)[m];
}

// Σ_{s ≠ diag} a_s x_nb at node (i, j). Five: the 5-point stencil of the fine level (the corner
// entries are zero there and skipped).
template <bool Five = false>
inline double offDiagonalSum(const Level& L, const double* x, int i, int j) {
    using St = Stencil<Five>;
    const auto c = stencilAt<Five>(L.a, L.nz, L.nt, i, j);
    const int jm = L.jm(j), jp = L.jp(j);
    const double* xm = x + L.im(i) * L.nt;
    const double* x0 = x + i * L.nt;
    const double* xp = x + L.ip(i) * L.nt;
    if constexpr (Five) return c[St::S] * xm[j] + c[St::W] * x0[jm] + c[St::E] * x0[jp] + c[St::N] * xp[j];
    return c[0] * xm[jm] + c[1] * xm[j] + c[2] * xm[jp] + c[3] * x0[jm] + c[5] * x0[jp] +
           c[6] * xp[jm] + c[7] * xp[j] + c[8] * xp[jp];
}

// 1/pivot for a line factorization, or 0 (the node is left out of the line solve) when the pivot
// is not clearly positive: a heavily truncated Galerkin basis can make a coarse operator
// (nearly) semidefinite, and rounding then leaves pivots of either sign near 0 whose inverse
// would flood the correction with inf/NaN. diag is the node's diagonal entry (the scale).
inline double safeInverse(double pivot, double diag) {
    return pivot > 1e-12 * std::abs(diag) ? 1.0 / pivot : 0.0;
}

// Off-diagonal part of row k's stencil c applied to x, with the rows i − 1, i, i + 1 of x at
// xm, x0, xp and the neighbouring columns jm, jp (clamped onto a zero coefficient at open edges).
template <bool Five, class Cs>
inline double offDiag(const Cs& c, const double* xm, const double* x0, const double* xp, int j,
                      int jm, int jp) {
    using St = Stencil<Five>;
    double s = c[St::S] * xm[j] + c[St::W] * x0[jm] + c[St::E] * x0[jp] + c[St::N] * xp[j];
    if constexpr (!Five) s += c[0] * xm[jm] + c[2] * xm[jp] + c[6] * xp[jm] + c[8] * xp[jp];
    return s;
}

// fn(j, jm, jp) for the columns j0, j0 + step, … of a level, with the neighbouring columns: the
// end columns (wrap or clamp) peeled off so that the loop over the interior has no branches.
template <class Fn>
inline void forColumns(const Level& L, int j0, int step, Fn&& fn) {
    const int nt = L.nt;
    int j = j0;
    if (j == 0) {
        fn(0, L.jm(0), L.jp(0));
        j += step;
    }
    for (; j < nt - 1; j += step) fn(j, j - 1, j + 1);
    if (j == nt - 1) fn(j, L.jm(j), L.jp(j));
}

// forColumns restricted to the columns j0, j0 + step, … below j1, on the fine level: also the
// column of the west coupling's entry, jw = ReynoldsSystem::westStencilColumn(j) (SymRow).
template <class Fn>
inline void forColumnsIn(const Level& L, int j0, int j1, int step, Fn&& fn) {
    int j = j0;
    if (j == 0 && j < j1) {
        fn(0, L.jm(0), L.jp(0), L.nt - 1);
        j += step;
    }
    for (const int end = std::min(j1, L.nt - 1); j < end; j += step) fn(j, j - 1, j + 1, j - 1);
    if (j == L.nt - 1 && j < j1) fn(j, L.jm(j), L.jp(j), j - 1);
}

// SymRow of fine node (i, j) from the entries of its row (a0) and of its south neighbour's (aS)
// and jw = ReynoldsSystem::westStencilColumn(j): the row's address arithmetic is done once.
inline SymRow symAt(const double* a0, const double* aS, int j, int jw) {
    return SymRow{a0 + kSym * sj(j), a0 + kSym * sj(jw), aS + kSym * sj(j)};
}
// Stencils of the nodes of row i of a level (stencilAt with the row's address arithmetic done
// once): at(j).
template <bool Five>
struct RowStencil {
    const double* a0;  // the row's entries
    const double* aS;  // the south neighbour row's (Five)
    int nt;
    auto at(int j) const {
        if constexpr (Five) return symAt(a0, aS, j, ReynoldsSystem::westStencilColumn(j, nt));
        else return a0 + 9 * sj(j);
    }
};
template <bool Five>
inline RowStencil<Five> rowStencil(const double* A, int nz, int nt, int i) {
    if constexpr (Five) return {A + kSym * sj(i * nt), A + kSym * sj((i > 0 ? i - 1 : nz - 1) * nt), nt};
    else return {A + 9 * sj(i * nt), nullptr, nt};
}
// Entries of fine row i, and of its south neighbour row (stencilAt).
inline const double* symRowPtr(const double* A, int nt, int i) { return A + kSym * sj(i * nt); }
inline const double* symSouthPtr(const double* A, int nz, int nt, int i) {
    return A + kSym * sj((i > 0 ? i - 1 : nz - 1) * nt);
}
// Smoother direction(s) of a level from its couplings (sets L.lines).
void chooseLines(Level& L);

}  // namespace flexehd::lube::multigrid
