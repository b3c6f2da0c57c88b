#include "lube/MultigridSolver.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace flexehd::lube {

namespace {

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

double Level::coef(std::size_t k, int s) const {
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

// Smoother direction of a level from its couplings summed over the free nodes: line relaxation
// along z alone when the axial couplings are at least twice the circumferential ones (skirts,
// Δz < RΔθ), along θ alone in the opposite case (long bearings, few axial nodes), alternating
// otherwise. A line smoother along the strong direction smooths well for any ratio ≥ 2
// (Trottenberg, Oosterlee & Schüller, Multigrid, 2001, §5.1); the alternating one is the robust
// fallback near isotropy.
void chooseLines(Level& L) {
    double sz = 0.0, st = 0.0;
    if (L.five) {  // no corners; SymRow's entries, the row's addresses computed once
        constexpr int E = ReynoldsSystem::kStencilE, N = ReynoldsSystem::kStencilN;
        for (int i = 0, k = 0; i < L.nz; ++i) {
            const double* a0 = symRowPtr(L.a, L.nt, i);
            const double* aS = symRowPtr(L.a, L.nt, i > 0 ? i - 1 : L.nz - 1);
            for (int j = 0; j < L.nt; ++j, ++k) {
                if (!L.free[static_cast<std::size_t>(k)]) continue;
                const double* c = a0 + kSym * sj(j);
                const double* w = a0 + kSym * sj(ReynoldsSystem::westStencilColumn(j, L.nt));
                sz -= aS[kSym * sj(j) + N] + c[N];
                st -= w[E] + c[E];
            }
        }
        L.lines = sz >= 2.0 * st ? Lines::Z : st >= 2.0 * sz ? Lines::Theta : Lines::Both;
        return;
    }
    for (int i = 0, k = 0; i < L.nz; ++i)
        for (int j = 0; j < L.nt; ++j, ++k) {
            if (!L.free[static_cast<std::size_t>(k)]) continue;
            const double* c = L.a + 9 * static_cast<std::size_t>(k);
            const double corners = c[0] + c[2] + c[6] + c[8];
            sz -= c[1] + c[7] + 0.5 * corners;  // corners couple both ways
            st -= c[3] + c[5] + 0.5 * corners;
        }
    L.lines = sz >= 2.0 * st ? Lines::Z : st >= 2.0 * sz ? Lines::Theta : Lines::Both;
}

}  // namespace

struct MultigridSolver::Hierarchy {
    std::vector<Level> levels;
    // Level of the grid being solved: 0, or a coarser one for the nested coarse solves of a cold
    // start (ReynoldsSolver's grid sequencing), which thus share the fine grid's hierarchy and
    // its memory. Levels below it are not used.
    std::size_t base = 0;
    /// Level with the geometry of g, or −1.
    int find(const FilmGrid& g) const;
    std::vector<char> film;        // Film nodes of the fine grid
    std::vector<char> cachedFree;  // truncation the Galerkin operators were built for
    bool galerkinValid = false;
    std::vector<double> lo, d, up, rhs;  // line-solve work arrays
    std::vector<int> staleDown, staleUp;  // factorZT work lists
    std::vector<int> rangeLo, rangeHi;    // factorZT work arrays (one per column)
    Eigen::LDLT<Eigen::MatrixXd> ldlt;  // coarsest level
    Vec dir;                            // line-search direction
    Vec invDiag;                        // 1/A_kk on the fine Film nodes (0 elsewhere)
    // Storage of the per-node work vectors of all levels (Vec::bind): one block, on huge pages,
    // instead of one mapping per array (a page fault per 4 KiB below 1 MiB, a 2 MiB page per
    // array above; the levels of a 256×512 grid have 40 such arrays).
    LargeVector<double> arena;
    std::vector<char> near;             // fine Film nodes next to a frozen or non-Film node
    std::vector<char> colFree;          // markNear work array (one fine row)
    // Runs [first, second) of fine columns holding a Film node. The fine outer pass and the line
    // search visit only these: the other columns (masks spanning whole columns, such as a skirt's
    // pin-boss relief, a third of its nodes) hold prescribed values that never change.
    std::vector<std::pair<int, int>> filmRuns;
    void markNear(int i);

    void buildGeometry(const FilmGrid& g);
    void extractFine(const ReynoldsSystem& sys);
    // Coarse nodes whose Galerkin rows must be rebuilt: flags, list, and flags per coarse row.
    struct Dirty {
        std::vector<char> flag, rows;
        std::vector<int> list;
    };
    void galerkin(std::size_t l, const Dirty* dirty);  // levels[l+1] from levels[l]
    template <bool Five, bool Partial>
    static void galerkinT(const Level& F, Level& C, const Dirty* dirty);
    template <bool Five, bool Partial>
    static void galerkinHalvedT(const Level& F, Level& C, const Dirty* dirty);
    void dirtyParents(std::size_t l, const std::vector<int>& changed, Dirty& dirty) const;
    void updateCoarse();
    void factorCoarsest();
    void factorZ(Level& L);
    template <bool Five> bool factorZT(Level& L, bool mayDefer = false);
    void factorTheta(Level& L, int i);
    static void thomasSolve(const Level& L, int i, double* r);
    void lineSweepZ(Level& L, bool forward);
    template <bool Five> void lineSweepZT(Level& L, bool forward);
    template <bool Five> void lineSweepThetaT(Level& L, bool forward);
    void lineSweepTheta(Level& L, bool forward);
    void smooth(Level& L, bool pre);
    void residual(Level& L);
    template <bool Five> void residualT(Level& L);
    void vcycle(std::size_t l);
    // Line search of the outer iteration, accumulated row by row (LineSearch::direction, then
    // curvature one row behind).
    struct LineSearch {
        const double* p;
        double pLower;
        bool bounded;
        double* dir;
        const std::vector<std::pair<int, int>>* runs;  // Hierarchy::filmRuns
        double alphaMax = std::numeric_limits<double>::infinity(), num = 0.0, den = 0.0;
        void direction(const Level& F, int i);
        void curvature(const Level& F, int i);
    };
    template <bool Five> void vcycleZT(std::size_t l, LineSearch* ls);
};

void MultigridSolver::Hierarchy::buildGeometry(const FilmGrid& g) {
    levels.clear();
    Level L0;
    L0.nz = g.nAxial();
    L0.nt = g.nTheta();
    L0.periodic = g.periodic();
    L0.z = g.axial();
    L0.five = true;
    levels.push_back(std::move(L0));
    while (static_cast<std::size_t>(levels.back().size()) > kDirectMax) {
        Level& F = levels.back();
        const bool cz = F.nz >= 5;
        const bool ct = F.periodic ? (F.nt % 2 == 0 && F.nt / 2 >= 4)
                                   : (F.nt % 2 == 1 && (F.nt + 1) / 2 >= 3);
        if (!cz && !ct) break;
        Level C;
        C.periodic = F.periodic;
        std::vector<int> map;
        if (cz) {
            for (int i = 0; i < F.nz; i += 2) map.push_back(i);
            if (map.back() != F.nz - 1) map.push_back(F.nz - 1);
        } else {
            for (int i = 0; i < F.nz; ++i) map.push_back(i);
        }
        C.nz = static_cast<int>(map.size());
        for (int i : map) C.z.push_back(F.z[static_cast<std::size_t>(i)]);
        C.nt = ct ? (F.periodic ? F.nt / 2 : (F.nt + 1) / 2) : F.nt;
        const auto nzF = static_cast<std::size_t>(F.nz), ntF = static_cast<std::size_t>(F.nt);
        F.pz0.assign(nzF, 0); F.pz1.assign(nzF, 0); F.wz0.assign(nzF, 1.0); F.wz1.assign(nzF, 0.0);
        F.pt0.assign(ntF, 0); F.pt1.assign(ntF, 0); F.wt0.assign(ntF, 1.0); F.wt1.assign(ntF, 0.0);
        for (int I = 0; I + 1 < C.nz; ++I) {
            const int i0 = map[static_cast<std::size_t>(I)], i1 = map[static_cast<std::size_t>(I) + 1];
            for (int i = i0; i <= i1; ++i) {
                const auto si = static_cast<std::size_t>(i);
                if (i == i1) { F.pz0[si] = F.pz1[si] = I + 1; F.wz0[si] = 1; F.wz1[si] = 0; continue; }
                const double t = (F.z[si] - F.z[static_cast<std::size_t>(i0)]) /
                                 (F.z[static_cast<std::size_t>(i1)] - F.z[static_cast<std::size_t>(i0)]);
                F.pz0[si] = I; F.pz1[si] = I + 1; F.wz0[si] = 1 - t; F.wz1[si] = t;
            }
        }
        if (C.nz == 1) { F.pz0[0] = F.pz1[0] = 0; }
        for (int j = 0; j < F.nt; ++j) {
            const auto sj = static_cast<std::size_t>(j);
            F.thetaHalved = ct;
            if (!ct) { F.pt0[sj] = F.pt1[sj] = j; continue; }
            if (j % 2 == 0) { F.pt0[sj] = F.pt1[sj] = j / 2; continue; }
            F.pt0[sj] = j / 2;
            F.pt1[sj] = (j / 2 + 1) % C.nt;
            F.wt0[sj] = F.wt1[sj] = 0.5;
        }
        auto rel = [](int first, int p0, int p1, double w0, double w1, int nPeriodic) {
            auto slot = [&](int p) {
                int d = p - first;
                if (nPeriodic > 0) {
                    if (d > 1) d -= nPeriodic;
                    else if (d < -1) d += nPeriodic;
                }
                return d + 1;
            };
            Level::Rel q{{slot(p0), slot(p1)}, {w0, w1}};
            for (int m = 0; m < 2; ++m) {
                if (q.w[m] == 0.0) q.r[m] = 1;  // unused slot, weight 0
                if (q.r[m] < 0 || q.r[m] > 2)
                    throw std::logic_error("MultigridSolver: prolongation stencil wider than 3 coarse nodes");
            }
            return q;
        };
        F.zRel.resize(3 * nzF);
        F.tRel.resize(3 * ntF);
        for (int i = 0; i < F.nz; ++i)
            for (int di = -1; di <= 1; ++di) {
                const auto i2 = static_cast<std::size_t>(di < 0 ? F.im(i) : di > 0 ? F.ip(i) : i);
                F.zRel[static_cast<std::size_t>(3 * i + di + 1)] =
                    rel(F.pz0[static_cast<std::size_t>(i)], F.pz0[i2], F.pz1[i2], F.wz0[i2], F.wz1[i2], 0);
            }
        for (int j = 0; j < F.nt; ++j)
            for (int dj = -1; dj <= 1; ++dj) {
                const auto j2 = static_cast<std::size_t>(dj < 0 ? F.jm(j) : dj > 0 ? F.jp(j) : j);
                F.tRel[static_cast<std::size_t>(3 * j + dj + 1)] =
                    rel(F.pt0[static_cast<std::size_t>(j)], F.pt0[j2], F.pt1[j2], F.wt0[j2], F.wt1[j2],
                        C.periodic ? C.nt : 0);
            }
        levels.push_back(std::move(C));
    }
    // Arena slices, each a whole number of cache lines: per level x, f, q, zm, zw and the Galerkin
    // stencil (9 per node, coarse levels); dir and invDiag for the finest. The θ-line factors and
    // the residual of unfused levels (rare) get their own storage on first use.
    auto lines = [](std::size_t m) { return (m + 7) / 8 * 8; };
    std::size_t total = 2 * lines(static_cast<std::size_t>(levels[0].size()));
    for (std::size_t l = 0; l < levels.size(); ++l) {
        const auto n = static_cast<std::size_t>(levels[l].size());
        total += 5 * lines(n) + (l > 0 ? lines(9 * n) : 0);
    }
    arena.resize(total);  // not zero-filled: pages are touched as the arrays are written
    double* next = arena.data();
    auto slice = [&](Vec& v, std::size_t m) {
        v.bind(next, m);
        next += lines(m);
    };
    slice(dir, static_cast<std::size_t>(levels[0].size()));
    slice(invDiag, static_cast<std::size_t>(levels[0].size()));
    std::size_t maxLine = 0;
    for (std::size_t l = 0; l < levels.size(); ++l) {
        Level& L = levels[l];
        const auto n = static_cast<std::size_t>(L.size());
        for (Vec* v : {&L.x, &L.f, &L.q, &L.zm, &L.zw}) slice(*v, n);
        if (l > 0) {
            slice(L.own, 9 * n);
            L.own.resize(9 * n);  // filled by the first (full) Galerkin product
            L.a = L.own.data();
        }
        L.free.assign(n, 0);
        L.x.assign(n, 0.0);
        L.f.resize(n);  // zeroed before each restriction (coarse), or the defect (fine)
        L.r.resize(0);  // allocated by residualT (levels not smoothed by the fused z-line cycle)
        L.q.resize(n);  // written before it is read (line eliminations)
        for (auto* v : {&L.zm, &L.zw, &L.tm, &L.tw, &L.tl, &L.tu}) v->clear();  // on first use
        for (auto* v : {&L.tAlpha, &L.tGamma, &L.tDen}) v->assign(static_cast<std::size_t>(L.nz), 0.0);
        L.colOk.assign(static_cast<std::size_t>(L.nt), 0);
        L.colFrom.assign(static_cast<std::size_t>(L.nt), 0);
        L.colTo.assign(static_cast<std::size_t>(L.nt), L.nz - 1);
        L.colLo.assign(static_cast<std::size_t>(L.nt), L.nz);  // empty ranges
        L.colHi.assign(static_cast<std::size_t>(L.nt), -1);
        L.jmv.resize(static_cast<std::size_t>(L.nt));
        L.jpv.resize(static_cast<std::size_t>(L.nt));
        for (int j = 0; j < L.nt; ++j) {
            L.jmv[static_cast<std::size_t>(j)] = L.jm(j);
            L.jpv[static_cast<std::size_t>(j)] = L.jp(j);
        }
        L.rowOk.assign(static_cast<std::size_t>(L.nz), 0);
        maxLine = std::max({maxLine, static_cast<std::size_t>(L.nz), static_cast<std::size_t>(L.nt)});
    }
    for (auto* v : {&lo, &d, &up, &rhs}) v->assign(maxLine, 0.0);
    rangeLo.resize(maxLine);
    rangeHi.resize(maxLine);
    galerkinValid = false;
}

// near[k] for fine row i from the free flags of rows i − 1 … i + 1: a Film node with a frozen or
// non-Film node among its 8 neighbours.
void MultigridSolver::Hierarchy::markNear(int i) {
    const Level& F = levels[base];
    const int nt = F.nt;
    const char* fm = &F.free[static_cast<std::size_t>(F.im(i) * nt)];
    const char* f0 = &F.free[static_cast<std::size_t>(i * nt)];
    const char* fp = &F.free[static_cast<std::size_t>(F.ip(i) * nt)];
    char* out = &near[static_cast<std::size_t>(i * nt)];
    const char* fl = &film[static_cast<std::size_t>(i * nt)];
    // Columns whose three nodes (rows i − 1 … i + 1) are all free, then three columns at a time.
    char* col = colFree.data();
    for (int j = 0; j < nt; ++j) col[j] = static_cast<char>(fm[j] & f0[j] & fp[j]);
    out[0] = static_cast<char>(fl[0] & !(col[F.jm(0)] & col[0] & col[F.jp(0)]));
    for (int j = 1; j < nt - 1; ++j) out[j] = static_cast<char>(fl[j] & !(col[j - 1] & col[j] & col[j + 1]));
    if (nt > 1) out[nt - 1] = static_cast<char>(fl[nt - 1] & !(col[F.jm(nt - 1)] & col[nt - 1] & col[F.jp(nt - 1)]));
}

void MultigridSolver::Hierarchy::extractFine(const ReynoldsSystem& sys) {
    static_assert(ReynoldsSystem::kStencilSize == 3, "fine stencil layout = ReynoldsSystem's (SymRow)");
    Level& L = levels[base];
    L.a = sys.stencil().data();  // couplings to non-Film nodes are 0 there; non-Film rows unused
    L.five = true;
    for (std::size_t l = base + 1; l < levels.size(); ++l) {  // Galerkin levels (again)
        levels[l].five = false;
        levels[l].a = levels[l].own.data();
    }
    film.resize(static_cast<std::size_t>(L.size()));
    invDiag.resize(L.size());
    const NodeKind* kind = sys.grid().kinds();
    std::vector<char> colFilm(static_cast<std::size_t>(L.nt), 0);
    for (int i = 0, k = 0; i < L.nz; ++i)
        for (int j = 0; j < L.nt; ++j, ++k) {
            const bool f = kind[k] == NodeKind::Film;  // sys.isFilm(k)
            film[static_cast<std::size_t>(k)] = f;
            colFilm[sj(j)] |= static_cast<char>(f);
            invDiag[k] = f ? 1.0 / L.a[kSym * static_cast<std::size_t>(k) + ReynoldsSystem::kStencilC] : 0.0;
        }
    filmRuns.clear();
    for (int j = 0; j < L.nt; ++j) {
        if (!colFilm[static_cast<std::size_t>(j)]) continue;
        if (filmRuns.empty() || filmRuns.back().second != j) filmRuns.emplace_back(j, j + 1);
        else filmRuns.back().second = j + 1;
    }
    L.invalidateLines();
    galerkinValid = false;
}

// Galerkin coarse operator C = Pᵀ T A T P (T: truncation to the free nodes) of levels[l+1] from
// levels[l], accumulated fine node by fine node. With `dirty` (one flag per coarse node), only the
// dirty coarse rows are zeroed and re-accumulated — the same sums in the same order as a full
// rebuild restricted to those rows, so a row with no free child gets an exact zero diagonal.
void MultigridSolver::Hierarchy::galerkin(std::size_t l, const Dirty* dirty) {
    const Level& F = levels[l];
    Level& C = levels[l + 1];
    if (!dirty) {
        std::fill(C.own.begin(), C.own.end(), 0.0);
        if (F.thetaHalved) {
            if (F.five) galerkinHalvedT<true, false>(F, C, nullptr);
            else galerkinHalvedT<false, false>(F, C, nullptr);
        } else if (F.five) galerkinT<true, false>(F, C, nullptr);
        else galerkinT<false, false>(F, C, nullptr);
    } else {
        for (int K : dirty->list) std::fill_n(C.own.begin() + 9 * K, 9, 0.0);
        if (F.thetaHalved) {
            if (F.five) galerkinHalvedT<true, true>(F, C, dirty);
            else galerkinHalvedT<false, true>(F, C, dirty);
        } else if (F.five) galerkinT<true, true>(F, C, dirty);
        else galerkinT<false, true>(F, C, dirty);
    }
    auto setFree = [&](int K) {
        C.free[static_cast<std::size_t>(K)] = C.a[static_cast<std::size_t>(9 * K + kDiag)] > 0.0;
    };
    if (dirty) {
        for (int K : dirty->list) {
            setFree(K);
            C.invalidateLines(K);
        }
    } else {
        for (int K = 0; K < C.size(); ++K) setFree(K);
        C.invalidateLines();
    }
}

// Per fine node k: Y = row k of (T A T) P, gathered in a 4×4 buffer over the coarse nodes
// around k's first parent (Iref, Jref) — slot (r, c) is the coarse node (Iref − 1 + r,
// Jref − 1 + c); the 9-point structure keeps every coupling within ±1 coarse row/column, row
// and column 3 stay zero — then scattered into the 9 entries of each parent's row with its
// weight: a parent at (Iref + oI, Jref + oJ), oI, oJ ∈ {0, 1}, reads slots (oI + r, oJ + c).
template <bool Five, bool Partial>
void MultigridSolver::Hierarchy::galerkinT(const Level& F, Level& C, const Dirty* dirty) {
    const int ntC = C.nt, nt = F.nt;
    // Nonzero stencil entries as (row offset + 1, column offset + 1): 5 on the fine level.
    static constexpr int kFiveDi[5] = {0, 1, 1, 1, 2}, kFiveDj[5] = {1, 0, 1, 2, 1};
    constexpr int ns = Five ? 5 : 9;  // entries S, W, C, E, N (Stencil<true>), or 9
    double* own = C.own.data();
    for (int i = 0; i < F.nz; ++i) {
        const auto si = static_cast<std::size_t>(i);
        if (Partial && !dirty->rows[static_cast<std::size_t>(F.pz0[si])] &&
            !dirty->rows[static_cast<std::size_t>(F.pz1[si])])
            continue;  // no parent row of this fine row is rebuilt
        // Parent rows (1 or 2) and their offsets from Iref = pz0.
        int nI = 0, PI[2], oI[2];
        double WZ[2];
        if (F.wz0[si] != 0.0) { PI[nI] = F.pz0[si]; oI[nI] = 0; WZ[nI++] = F.wz0[si]; }
        if (F.wz1[si] != 0.0) { PI[nI] = F.pz1[si]; oI[nI] = F.pz1[si] - F.pz0[si]; WZ[nI++] = F.wz1[si]; }
        const int rowOf[3] = {F.im(i) * nt, i * nt, F.ip(i) * nt};
        const Level::Rel* zr = &F.zRel[3 * si];
        for (int j = 0; j < nt; ++j) {
            const int k = i * nt + j;
            if (!F.free[static_cast<std::size_t>(k)]) continue;
            const auto sj = static_cast<std::size_t>(j);
            int nJ = 0, PJ[2], oJ[2];
            double WT[2];
            if (F.wt0[sj] != 0.0) { PJ[nJ] = F.pt0[sj]; oJ[nJ] = 0; WT[nJ++] = F.wt0[sj]; }
            if (F.wt1[sj] != 0.0) { PJ[nJ] = F.pt1[sj]; oJ[nJ] = F.pt1[sj] == F.pt0[sj] ? 0 : 1; WT[nJ++] = F.wt1[sj]; }
            if constexpr (Partial) {
                bool any = false;
                for (int a = 0; a < nI; ++a)
                    for (int b = 0; b < nJ; ++b) any |= dirty->flag[static_cast<std::size_t>(PI[a] * ntC + PJ[b])] != 0;
                if (!any) continue;
            }
            double Y[4][4] = {};
            const int colOf[3] = {F.jm(j), j, F.jp(j)};
            const Level::Rel* tr = &F.tRel[3 * sj];
            const auto ak = stencilAt<Five>(F.a, F.nz, nt, i, j);
            for (int e = 0; e < ns; ++e) {
                const int di = Five ? kFiveDi[e] : e / 3, dj = Five ? kFiveDj[e] : e % 3;
                if (!F.free[static_cast<std::size_t>(rowOf[di] + colOf[dj])]) continue;
                const double a = ak[e];
                const Level::Rel& Z = zr[di];
                const Level::Rel& T = tr[dj];
                Y[Z.r[0]][T.r[0]] += Z.w[0] * T.w[0] * a;
                Y[Z.r[0]][T.r[1]] += Z.w[0] * T.w[1] * a;
                Y[Z.r[1]][T.r[0]] += Z.w[1] * T.w[0] * a;
                Y[Z.r[1]][T.r[1]] += Z.w[1] * T.w[1] * a;
            }
            for (int a = 0; a < nI; ++a)
                for (int b = 0; b < nJ; ++b) {
                    const int K = PI[a] * ntC + PJ[b];
                    if (Partial && !dirty->flag[static_cast<std::size_t>(K)]) continue;
                    const double w = WZ[a] * WT[b];
                    double* cp = own + 9 * static_cast<std::size_t>(K);
                    const double(*Yr)[4] = &Y[oI[a]];
                    const int c0 = oJ[b];
                    for (int r = 0; r < 3; ++r)
                        for (int c = 0; c < 3; ++c) cp[3 * r + c] += w * Yr[r][c0 + c];
                }
        }
    }
}

// galerkinT for a level whose θ columns are halved (the usual case): even fine column j sits on
// coarse column j/2, odd column j halfway between (j − 1)/2 and (j + 1)/2 (wrapped), so the
// θ-part of every prolongation stencil is known at compile time, column pair by column pair. Per
// fine node, with the z-slots of the rows i − 1, i, i + 1 as a 3×4 matrix Z (per row) and the
// θ-vectors T of the columns j − 1, j, j + 1: v_di = Σ_dj a(di, dj) T_dj, Y = Σ_di Z_di ⊗ v_di,
// then the same scatter as galerkinT. Same products, summed in a different order.
template <bool Five, bool Partial>
void MultigridSolver::Hierarchy::galerkinHalvedT(const Level& F, Level& C, const Dirty* dirty) {
    using St = Stencil<Five>;
    const int ntC = C.nt, nt = F.nt;
    double* own = C.own.data();
    const char* fr = F.free.data();
    for (int i = 0; i < F.nz; ++i) {
        const auto si = static_cast<std::size_t>(i);
        if (Partial && !dirty->rows[static_cast<std::size_t>(F.pz0[si])] &&
            !dirty->rows[static_cast<std::size_t>(F.pz1[si])])
            continue;
        int nI = 0, PI[2], oI[2];
        double WZ[2];
        if (F.wz0[si] != 0.0) { PI[nI] = F.pz0[si]; oI[nI] = 0; WZ[nI++] = F.wz0[si]; }
        if (F.wz1[si] != 0.0) { PI[nI] = F.pz1[si]; oI[nI] = F.pz1[si] - F.pz0[si]; WZ[nI++] = F.wz1[si]; }
        // Z[di][r]: weight of coarse row slot r (relative to pz0(i) − 1) in the prolongation of
        // fine row i + di − 1.
        double Z[3][4] = {};
        for (int di = 0; di < 3; ++di) {
            const Level::Rel& q = F.zRel[3 * si + static_cast<std::size_t>(di)];
            Z[di][q.r[0]] += q.w[0];
            Z[di][q.r[1]] += q.w[1];
        }
        // Row slots of Y that can be nonzero (a Z row slot with a nonzero weight): [rLo, rHi).
        // Y is only formed and scattered there — the other slots add exact zeros (on the usual
        // halved rows, half of a parent's 3 rows), as do the θ slots the column parity excludes.
        int rLo = 4, rHi = 0;
        for (int r = 0; r < 4; ++r)
            if (Z[0][r] != 0.0 || Z[1][r] != 0.0 || Z[2][r] != 0.0) {
                rLo = std::min(rLo, r);
                rHi = r + 1;
            }
        int sLo[2], sHi[2];  // per parent row a: scatter rows r with oI[a] + r in [rLo, rHi)
        for (int a = 0; a < nI; ++a) {
            sLo[a] = std::max(0, rLo - oI[a]);
            sHi[a] = std::min(3, rHi - oI[a]);
        }
        // Usual row shapes, unrolled at compile time: a fine row on a coarse row (one parent,
        // Y rows 0..2) and a row halfway between two (parents at offsets 0 and 1, Y rows 1..2);
        // anything else (ends of a graded or odd axis) uses the run-time bounds.
        const int rowShape = nI == 1 && oI[0] == 0 && rLo == 0 && rHi == 3                    ? 1
                             : nI == 2 && oI[0] == 0 && oI[1] == 1 && rLo == 1 && rHi == 3 ? 2
                                                                                             : 0;
        const char* frow[3] = {fr + F.im(i) * nt, fr + i * nt, fr + F.ip(i) * nt};
        auto node = [&](auto oddTag, auto shapeTag, int j, int jm, int jp) {
            constexpr bool Odd = decltype(oddTag)::value;
            constexpr int Shape = decltype(shapeTag)::value;
            const int k = i * nt + j;
            if (!fr[k]) return;
            const int J0 = j / 2;  // first parent column (Jref)
            const int J1 = Odd ? (J0 + 1 == ntC ? 0 : J0 + 1) : J0;
            const int nIs = Shape == 1 ? 1 : Shape == 2 ? 2 : nI;
            if constexpr (Partial) {
                bool any = false;
                for (int a = 0; a < nIs; ++a) {
                    any |= dirty->flag[static_cast<std::size_t>(PI[a] * ntC + J0)] != 0;
                    if (Odd) any |= dirty->flag[static_cast<std::size_t>(PI[a] * ntC + J1)] != 0;
                }
                if (!any) return;
            }
            // θ-vectors (slots 0..3 relative to J0 − 1): column j − 1, j, j + 1.
            constexpr double Tm[4] = {Odd ? 0.0 : 0.5, Odd ? 1.0 : 0.5, 0.0, 0.0};
            constexpr double T0[4] = {0.0, Odd ? 0.5 : 1.0, Odd ? 0.5 : 0.0, 0.0};
            constexpr double Tp[4] = {0.0, Odd ? 0.0 : 0.5, Odd ? 1.0 : 0.5, 0.0};
            const auto ak = stencilAt<Five>(F.a, F.nz, nt, i, j);
            const int cols[3] = {jm, j, jp};
            double v[3][4] = {};
            for (int di = 0; di < 3; ++di) {
                const char* f = frow[di];
                double am, a0, ap;  // couplings to (i + di − 1, j − 1 … j + 1), truncated
                if constexpr (Five) {
                    am = di == 1 && f[cols[0]] ? ak[St::W] : 0.0;
                    ap = di == 1 && f[cols[2]] ? ak[St::E] : 0.0;
                    a0 = f[cols[1]] ? ak[di == 0 ? St::S : di == 1 ? St::C : St::N] : 0.0;
                } else {
                    am = f[cols[0]] ? ak[3 * di] : 0.0;
                    a0 = f[cols[1]] ? ak[3 * di + 1] : 0.0;
                    ap = f[cols[2]] ? ak[3 * di + 2] : 0.0;
                }
                for (int c = 0; c < 4; ++c) v[di][c] = am * Tm[c] + a0 * T0[c] + ap * Tp[c];
            }
            // θ slots that can be nonzero: 0..2 (even column), 1..2 (odd column).
            constexpr int cLo = Odd ? 1 : 0, cHi = 3;
            const int yLo = Shape == 1 ? 0 : Shape == 2 ? 1 : rLo, yHi = Shape ? 3 : rHi;
            double Y[4][4];
            for (int r = yLo; r < yHi; ++r)
                for (int c = cLo; c < cHi; ++c)
                    Y[r][c] = Z[0][r] * v[0][c] + Z[1][r] * v[1][c] + Z[2][r] * v[2][c];
            for (int a = 0; a < nIs; ++a) {
                const int oIa = Shape == 1 ? 0 : Shape == 2 ? a : oI[a];
                const int r0 = Shape == 1 ? 0 : Shape == 2 ? 1 - a : sLo[a];
                const int r1 = Shape == 1 ? 3 : Shape == 2 ? 3 - a : sHi[a];
                const double(*Yr)[4] = &Y[oIa];
                for (int b = 0; b < (Odd ? 2 : 1); ++b) {
                    const int J = b ? J1 : J0;
                    const int K = PI[a] * ntC + J;
                    if (Partial && !dirty->flag[static_cast<std::size_t>(K)]) continue;
                    const double w = WZ[a] * (Odd ? 0.5 : 1.0);
                    double* cp = own + 9 * static_cast<std::size_t>(K);
                    // Stencil columns c with b + c in [cLo, cHi).
                    const int c0 = std::max(0, cLo - b), c1 = std::min(3, cHi - b);
                    for (int r = r0; r < r1; ++r)
                        for (int c = c0; c < c1; ++c) cp[3 * r + c] += w * Yr[r][b + c];
                }
            }
        };
        auto sweep = [&](auto shapeTag) {
            forColumns(F, 0, 1, [&](int j, int jm, int jp) {
                if (j % 2) node(std::true_type{}, shapeTag, j, jm, jp);
                else node(std::false_type{}, shapeTag, j, jm, jp);
            });
        };
        if (rowShape == 1) sweep(std::integral_constant<int, 1>{});
        else if (rowShape == 2) sweep(std::integral_constant<int, 2>{});
        else sweep(std::integral_constant<int, 0>{});
    }
}

// Coarse nodes whose Galerkin rows change when the fine rows `changed` of level l change (their
// free flag or their stencil): entry (K, K2) sums fine pairs (k, k2) with k a child of K and k2 a
// neighbour of k, so the rows to rebuild are the parents of the changed nodes and of their
// neighbours. Returns the number of dirty coarse nodes.
void MultigridSolver::Hierarchy::dirtyParents(std::size_t l, const std::vector<int>& changed,
                                              Dirty& dirty) const {
    const Level& F = levels[l];
    const Level& C = levels[l + 1];
    dirty.flag.assign(static_cast<std::size_t>(C.size()), 0);
    dirty.rows.assign(static_cast<std::size_t>(C.nz), 0);
    dirty.list.clear();
    auto mark = [&](int i, int j) {
        const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
        const int zi[2] = {F.pz0[si], F.pz1[si]}, tj[2] = {F.pt0[sj], F.pt1[sj]};
        for (int I : zi)
            for (int J : tj) {
                const int K = I * C.nt + J;
                char& d = dirty.flag[static_cast<std::size_t>(K)];
                if (d) continue;
                d = 1;
                dirty.rows[static_cast<std::size_t>(I)] = 1;
                dirty.list.push_back(K);
            }
    };
    for (int k : changed) {
        const int i = k / F.nt, j = k % F.nt;
        for (int i2 : {F.im(i), i, F.ip(i)})
            for (int j2 : {F.jm(j), j, F.jp(j)}) mark(i2, j2);
    }
}

// Brings the coarse operators up to date with the fine truncation F.free: a full rebuild the
// first time, afterwards only the rows reached by the nodes whose free flag changed (the cavitation
// front moves by a few cells per iteration, so this is a small fraction of the grid).
void MultigridSolver::Hierarchy::updateCoarse() {
    Level& F = levels[base];
    std::vector<int> changed;
    if (galerkinValid) {
        // Blocks of 64 flags compared at once (the front moves by a few cells: most are equal).
        const std::size_t n = F.free.size();
        const char* now = F.free.data();
        const char* was = cachedFree.data();
        for (std::size_t k0 = 0; k0 < n; k0 += 64) {
            const std::size_t k1 = std::min(n, k0 + 64);
            if (std::memcmp(now + k0, was + k0, k1 - k0) == 0) continue;
            for (std::size_t k = k0; k < k1; ++k)
                if (now[k] != was[k]) changed.push_back(static_cast<int>(k));
        }
        if (changed.empty()) return;
        for (int k : changed) F.invalidateLines(k);
    }
    bool full = !galerkinValid;
    Dirty dirty;
    for (std::size_t l = base; l + 1 < levels.size(); ++l) {
        if (!full) {
            dirtyParents(l, changed, dirty);
            full = 4 * dirty.list.size() > static_cast<std::size_t>(levels[l + 1].size());  // rebuild all
            if (!full) {
                galerkin(l, &dirty);
                changed.swap(dirty.list);
                continue;
            }
        }
        galerkin(l, nullptr);
    }
    if (!galerkinValid)  // first truncation of this solve: smoother directions
        for (std::size_t l = base; l < levels.size(); ++l) {
            chooseLines(levels[l]);
            levels[l].fusedZ = levels[l].lines == Lines::Z && l + 1 < levels.size();
        }
    factorCoarsest();
    cachedFree = F.free;
    galerkinValid = true;
}

void MultigridSolver::Hierarchy::factorCoarsest() {
    Level& L = levels.back();
    L.dense.clear();
    L.direct = static_cast<std::size_t>(L.size()) <= kDirectLimit;
    if (!L.direct) return;  // a grid that cannot coarsen far enough: smoothed instead
    std::vector<int> pos(static_cast<std::size_t>(L.size()), -1);
    for (int k = 0; k < L.size(); ++k)
        if (L.free[static_cast<std::size_t>(k)]) {
            pos[static_cast<std::size_t>(k)] = static_cast<int>(L.dense.size());
            L.dense.push_back(k);
        }
    const int n = static_cast<int>(L.dense.size());
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
    for (int q = 0; q < n; ++q) {
        const int k = L.dense[static_cast<std::size_t>(q)], i = k / L.nt, j = k % L.nt;
        const int rows[3] = {L.im(i), i, L.ip(i)}, cols[3] = {L.jm(j), j, L.jp(j)};
        for (int s = 0; s < 9; ++s) {
            const double a = L.coef(static_cast<std::size_t>(k), s);
            const int c = pos[static_cast<std::size_t>(rows[s / 3] * L.nt + cols[s % 3])];
            if (a != 0.0 && c >= 0) M(q, c) += a;
        }
    }
    // LDLT with pivoting tolerates the (rare) semidefinite coarse operator of a heavily
    // truncated basis: zero pivots give a zero component.
    ldlt.compute(M);
    L.denseRhs.resize(n);
}

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
    using St = Stencil<Five>;
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
    double* zm = L.zm.data();
    double* zw = L.zw.data();
    const char* fr = L.free.data();
    int* from = L.colFrom.data();
    int* to = L.colTo.data();
    // Fused levels: the free row range of each stale column; only the rows in range are factored
    // (the fused sweeps read no factor outside; the rows next to the range are frozen, whose
    // factors are 0, so the recursions start afresh at its ends). Other levels: all rows.
    const bool ranged = L.fusedZ;
    int* lo = L.colLo.data();
    int* hi = L.colHi.data();
    double* x = L.x.data();
    double* q = L.q.data();
    if (ranged) {
        // First and last free row of every column, row by row (contiguous, branch-free).
        int* a = rangeLo.data();
        int* b = rangeHi.data();
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
            // New range (from the scan above). The sweeps skip the rows outside, and read
            // them as neighbours (x) and as the eliminated row next to the range (q): x = 0 on the
            // rows that leave it (outside the old range it is 0 already), q = 0 next to it.
            const int a = rangeLo[sj(j)], b = rangeHi[sj(j)];
            for (int i = lo[j]; i <= hi[j]; ++i)
                if (i < a || i > b) x[i * nt + j] = 0.0;
            if (a > 0 && a < nz) q[(a - 1) * nt + j] = 0.0;
            if (b >= 0 && b + 1 < nz) q[(b + 1) * nt + j] = 0.0;
            lo[j] = a;
            hi[j] = b;
        }
    // Deferred to the caller when every column is stale over its whole free range.
    bool defer = mayDefer && ranged && down.size() + up.size() == static_cast<std::size_t>(nt);
    if (defer) {
        for (const int j : down) defer &= from[j] <= lo[j];
        for (const int j : up) defer &= to[j] >= hi[j];
    }
    // Row by row over the stale columns (contiguous memory), from the first changed row.
    for (int i = 0; i < nz && !defer; ++i)
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
    for (int i = nz - 1; i >= 0 && !defer; --i)
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
    if (ranged) {
        // Per-row lists of the columns in range.
        L.rowEven.assign(static_cast<std::size_t>(nz) + 1, 0);
        L.rowOdd.assign(static_cast<std::size_t>(nz) + 1, 0);
        L.evenRuns.clear();
        L.oddRuns.clear();
        std::vector<int>& live = staleDown;  // reused: columns with a free row, by parity
        std::vector<int>& liveOdd = staleUp;
        live.clear();
        liveOdd.clear();
        for (int j = 0; j < nt; ++j)
            if (lo[j] <= hi[j]) (j % 2 ? liveOdd : live).push_back(j);
        // Runs [first, end) of the in-range columns of one parity, column j + 2 continuing a run
        // that ends at j.
        auto build = [&](const std::vector<int>& cols, std::vector<int>& row, std::vector<int>& runs) {
            for (int i = 0; i < nz; ++i) {
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
        };
        build(live, L.rowEven, L.evenRuns);
        build(liveOdd, L.rowOdd, L.oddRuns);
    }
    std::fill(L.colOk.begin(), L.colOk.end(), 1);
    std::fill(L.colFrom.begin(), L.colFrom.end(), nz);
    std::fill(L.colTo.begin(), L.colTo.end(), -1);
    return defer;
}

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


MultigridSolver::MultigridSolver() = default;
MultigridSolver::~MultigridSolver() = default;
MultigridSolver::MultigridSolver(MultigridSolver&&) noexcept = default;
MultigridSolver& MultigridSolver::operator=(MultigridSolver&&) noexcept = default;

int MultigridSolver::levels() const { return h_ ? static_cast<int>(h_->levels.size() - h_->base) : 0; }

int MultigridSolver::Hierarchy::find(const FilmGrid& g) const {
    for (std::size_t l = 0; l < levels.size(); ++l) {
        const Level& L = levels[l];
        if (L.nz == g.nAxial() && L.nt == g.nTheta() && L.periodic == g.periodic() && L.z == g.axial())
            return static_cast<int>(l);
    }
    return -1;
}

void MultigridSolver::prepare(const FilmGrid& fine) {
    if (h_ && h_->find(fine) == 0) return;
    h_ = std::make_unique<Hierarchy>();
    h_->buildGeometry(fine);
}

bool MultigridSolver::hasLevel(const FilmGrid& g) const { return h_ && h_->find(g) >= 0; }

// Search direction of fine row i — the V-cycle correction on the free nodes, projected so that
// p + d ≥ p_cav — with the largest feasible step and dᵀ(b − Ap).
void MultigridSolver::Hierarchy::LineSearch::direction(const Level& F, int i) {
    // Accumulated in locals: the members would be reloaded after every store through dir.
    const double lo = pLower;
    const bool bd = bounded;
    double aMax = alphaMax, nm = num;
    const double* fx = F.x.data();
    const double* ff = F.f.data();
    const char* fr = F.free.data();
    double* d = dir;
    for (const auto& [j0, j1] : *runs)  // d = 0 elsewhere (set once per solve)
        for (int k = i * F.nt + j0, kEnd = i * F.nt + j1; k < kEnd; ++k) {
            double dk = fr[k] ? fx[k] : 0.0;  // 0 on frozen and non-Film nodes
            if (bd && dk < 0.0) {
                if (p[k] + dk < lo) dk = lo - p[k];
                if (dk < 0.0) aMax = std::min(aMax, (p[k] - lo) / -dk);
            }
            d[k] = dk;
            nm += dk * ff[k];
        }
    alphaMax = aMax;
    num = nm;
}

// dᵀAd over fine row i (the direction of rows i − 1 … i + 1 is known).
void MultigridSolver::Hierarchy::LineSearch::curvature(const Level& F, int i) {
    const int nt = F.nt;
    const double* dm = dir + F.im(i) * nt;
    const double* d0 = dir + i * nt;
    const double* dp = dir + F.ip(i) * nt;
    const double* a0 = symRowPtr(F.a, nt, i);
    const double* aS = symSouthPtr(F.a, F.nz, nt, i);
    double sum = 0.0;
    for (const auto& [j0, j1] : *runs)
        forColumnsIn(F, j0, j1, 1, [&](int j, int jm, int jp, int jw) {
            if (d0[j] == 0.0) return;
            const SymRow c = symAt(a0, aS, j, jw);
            sum += d0[j] * (c[Stencil<true>::C] * d0[j] + offDiag<true>(c, dm, d0, dp, j, jm, jp));
        });
    den += sum;
}

SolveReport MultigridSolver::solve(const ReynoldsSystem& sys, Eigen::VectorXd& p, double pLower,
                                   const SolverControl& control) {
    const FilmGrid& g = sys.grid();
    const int n = g.size();
    const int found = h_ ? h_->find(g) : -1;
    if (found < 0) {
        h_ = std::make_unique<Hierarchy>();
        h_->buildGeometry(g);
    }
    Hierarchy& H = *h_;
    H.base = found < 0 ? 0 : static_cast<std::size_t>(found);
    H.extractFine(sys);
    Level& F = H.levels[H.base];
    const bool bounded = std::isfinite(pLower);
    const double* __restrict b = sys.rhs().data();
    if (p.size() != n) p = sys.initialGuess(pLower);
    // Prescribed values on the non-Film nodes, the bound on the Film nodes, and the free
    // boundary of the starting point (for the local relaxation of the first iteration).
    const double* pp = g.prescribedPressures();
    for (int k = 0; k < n; ++k) {
        const auto sk = static_cast<std::size_t>(k);
        if (!H.film[sk]) p[k] = pp[k];
        else if (bounded && p[k] < pLower) p[k] = pLower;
        F.free[sk] = H.film[sk] && !(bounded && p[k] <= pLower);
    }
    H.dir.assign(n, 0.0);  // stays 0 outside the Film columns
    H.near.resize(static_cast<std::size_t>(n));
    H.colFree.resize(static_cast<std::size_t>(F.nt));
    for (int i = 0; i < F.nz; ++i) H.markNear(i);
    // Columns without Film nodes, skipped by the passes below: no defect, not free, and their
    // (constant) share of the pressure scale.
    double deadScale = 0.0;
    for (int i = 0; i < F.nz; ++i) {
        int j = 0;
        for (std::size_t r = 0; r <= H.filmRuns.size(); ++r) {
            const int jEnd = r < H.filmRuns.size() ? H.filmRuns[r].first : F.nt;
            for (int k = i * F.nt + j; j < jEnd; ++j, ++k) {
                F.f[k] = 0.0;
                deadScale = std::max(deadScale, std::abs(p[k] - g.ambientPressure()));
            }
            if (r < H.filmRuns.size()) j = H.filmRuns[r].second;
        }
    }
    double* __restrict x = p.data();
    double* __restrict dir = H.dir.data();
    const double* __restrict invDiag = H.invDiag.data();
    const char* __restrict film = H.film.data();
    const int nz = F.nz, nt = F.nt;

    // Iteration cap: each iteration is a whole V-cycle, so PSOR's sweep budget is far too many.
    const int maxIt = std::min(control.maxIterations, 500);
    const double pAmb = g.ambientPressure();
    SolveReport rep;
    double first = -1.0;
    double alpha = 0.0;  // step along dir still to be applied (line search of the last iteration)
    for (;;) {
        // 1. The step of the previous iteration, p ← max(p_cav, p + α d); 2. one projected
        // Gauss–Seidel sweep (the nonlinear pre-smoother) in red–black order, and a second one
        // on the nodes next to the free boundary (near); 3. the defect b − Ap, the convergence
        // criterion of ReynoldsSystem::residual and the truncation (nodes at the bound are
        // frozen), and the near flags for the next iteration. Fused into one wavefront over the
        // rows — at step t: step of row t, red nodes of row t − 1, black of t − 2, near red of
        // t − 3, near black of t − 4, defect of t − 5, near flags of t − 6: each uses only rows
        // that are final for it, so the result is that of separate passes, in one pass over
        // memory. Locals, not captured references: the lambdas store through double pointers,
        // after which referenced doubles would have to be reloaded.
        const double lo = pLower, step = alpha;
        const auto& runs = H.filmRuns;
        auto stepRow = [&, lo, step, bounded](int i) {
            for (const auto& [j0, j1] : runs)
                for (int k = i * nt + j0, kEnd = i * nt + j1; k < kEnd; ++k) {
                    if (dir[k] == 0.0) continue;
                    double v = x[k] + step * dir[k];
                    if (bounded && v < lo) v = lo;
                    x[k] = v;
                }
        };
        const double* __restrict A = F.a;
        // Projected Gauss–Seidel update of the nodes of one colour in row i (all Film nodes, or
        // only those flagged in `only`).
        auto pgsRow = [&, lo, bounded](int i, int colour, const char* only) {
            const double* xm = x + F.im(i) * nt;
            double* x0 = x + i * nt;
            const double* xp = x + F.ip(i) * nt;
            const char* sel = (only ? only : film) + i * nt;
            const int parity = (i + colour) % 2;
            const double* a0 = symRowPtr(A, nt, i);
            const double* aS = symSouthPtr(A, nz, nt, i);
            for (const auto& [j0, j1] : runs)
                forColumnsIn(F, j0 + ((j0 + parity) & 1), j1, 2, [&](int j, int jm, int jp, int jw) {
                    if (!sel[j]) return;
                    const int k = i * nt + j;
                    double v = (b[k] - offDiag<true>(symAt(a0, aS, j, jw), xm, x0, xp, j, jm, jp)) * invDiag[k];
                    if (bounded && v < lo) v = lo;
                    x0[j] = v;
                });
        };
        // The second red–black sweep runs on the nodes next to the free boundary only (H.near: a
        // frozen or non-Film node among the 8 neighbours, from the last truncation) — local
        // relaxation where the coarse-grid correction is weakest (cavitation fronts, mask edges,
        // open ends).
        const char* near = H.near.data();
        double rmax = 0.0, scale = deadScale;
        double* __restrict ff = F.f.data();
        char* __restrict fr = F.free.data();
        auto defectRow = [&, lo, bounded, pAmb](int i) {
            const double* xm = x + F.im(i) * nt;
            const double* x0 = x + i * nt;
            const double* xp = x + F.ip(i) * nt;
            double rm = 0.0, sc = 0.0;
            const double* a0 = symRowPtr(A, nt, i);
            const double* aS = symSouthPtr(A, nz, nt, i);
            for (const auto& [j0, j1] : runs)
                forColumnsIn(F, j0, j1, 1, [&](int j, int jm, int jp, int jw) {
                    const int k = i * nt + j;
                    sc = std::max(sc, std::abs(x0[j] - pAmb));
                    if (!film[k]) {
                        ff[k] = 0.0;
                        fr[k] = 0;
                        return;
                    }
                    const SymRow c = symAt(a0, aS, j, jw);
                    const double w = b[k] - c[Stencil<true>::C] * x0[j] - offDiag<true>(c, xm, x0, xp, j, jm, jp);
                    ff[k] = w;
                    double rk = -w * invDiag[k];
                    if (bounded) rk = std::min(x0[j] - lo, rk);
                    rm = std::max(rm, std::abs(rk));
                    fr[k] = !(bounded && x0[j] <= lo);
                });
            rmax = std::max(rmax, rm);
            scale = std::max(scale, sc);
        };
        for (int t = 0; t < nz + 6; ++t) {
            if (alpha != 0.0 && t < nz) stepRow(t);
            if (t >= 1 && t - 1 < nz) pgsRow(t - 1, 0, nullptr);
            if (t >= 2 && t - 2 < nz) pgsRow(t - 2, 1, nullptr);
            if (t >= 3 && t - 3 < nz) pgsRow(t - 3, 0, near);
            if (t >= 4 && t - 4 < nz) pgsRow(t - 4, 1, near);
            if (t >= 5 && t - 5 < nz) defectRow(t - 5);
            if (t >= 6) H.markNear(t - 6);
        }
        rep.residual = rmax == 0.0 ? 0.0 : rmax / std::max(scale, std::numeric_limits<double>::min());
        if (first < 0.0) first = rep.residual;
        if (!std::isfinite(rep.residual) || rep.residual > 1e8 * std::max(first, 1.0))
            throw std::runtime_error("MultigridSolver: diverged after " +
                                     std::to_string(rep.iterations) + " iterations (residual " +
                                     std::to_string(rep.residual) + ")");
        if (rep.residual <= control.tolerance && rep.iterations >= std::min(control.minIterations, maxIt))
            return rep;
        if (rep.iterations == maxIt) break;
        // 4. The Galerkin operators follow the truncation.
        H.updateCoarse();
        // 5. One linear V-cycle on the inactive nodes; its correction, projected, is the search
        // direction, with the exact line search α = dᵀ(b − Ap)/dᵀAd (fused into the V-cycle's
        // last pass on z-line levels).
        Hierarchy::LineSearch ls{x, pLower, bounded, dir, &H.filmRuns};
        if (F.fusedZ) {
            H.vcycleZT<true>(H.base, &ls);
        } else {
            H.vcycle(H.base);
            for (int i = 0; i < nz; ++i) ls.direction(F, i);
            for (int i = 0; i < nz; ++i) ls.curvature(F, i);
        }
        alpha = ls.den > 0.0 && ls.num > 0.0 ? std::min(ls.num / ls.den, std::max(ls.alphaMax, 1.0)) : 0.0;
        ++rep.iterations;
    }
    throw std::runtime_error("MultigridSolver: not converged after " + std::to_string(maxIt) +
                             " iterations (residual " + std::to_string(rep.residual) +
                             " > tolerance " + std::to_string(control.tolerance) + ")");
}

}  // namespace flexehd::lube
