// Galerkin coarse operators Pᵀ T A T P of the truncated hierarchy, rebuilt only where the
// frozen set changed, and the dense factorization of the coarsest level (docs/lube.md §3).
#include <algorithm>
#include <cmath>

#include "lube/multigrid/MultigridHierarchy.hpp"

namespace flexehd::lube {

using namespace multigrid;


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
namespace {

// The prolongation of fine row i of a θ-halved level: its parent coarse rows PI (with offsets oI
// from pz0(i) and weights WZ), Z[di][r] the weight of coarse row slot r (relative to pz0(i) − 1)
// in the prolongation of fine row i + di − 1, the row slots [rLo, rHi) of Y that can be nonzero
// (a Z row slot with a nonzero weight: Y is only formed and scattered there — the other slots add
// exact zeros, on the usual halved rows half of a parent's 3 rows, as do the θ slots the column
// parity excludes), per parent the scatter rows [sLo, sHi), and the row's shape: 1 a fine row on
// a coarse row (one parent, Y rows 0..2), 2 a row halfway between two (parents at offsets 0 and
// 1, Y rows 1..2), 0 anything else (ends of a graded or odd axis: run-time bounds).
struct HalvedRow {
    int nI = 0, PI[2] = {0, 0}, oI[2] = {0, 0};
    double WZ[2] = {0.0, 0.0};
    double Z[3][4] = {};
    int rLo = 4, rHi = 0, sLo[2] = {0, 0}, sHi[2] = {0, 0};
    int shape = 0;
};

HalvedRow halvedRow(const Level& F, int i) {
    HalvedRow R;
    const auto si = static_cast<std::size_t>(i);
    if (F.wz0[si] != 0.0) { R.PI[R.nI] = F.pz0[si]; R.oI[R.nI] = 0; R.WZ[R.nI++] = F.wz0[si]; }
    if (F.wz1[si] != 0.0) { R.PI[R.nI] = F.pz1[si]; R.oI[R.nI] = F.pz1[si] - F.pz0[si]; R.WZ[R.nI++] = F.wz1[si]; }
    for (int di = 0; di < 3; ++di) {
        const Level::Rel& q = F.zRel[3 * si + static_cast<std::size_t>(di)];
        R.Z[di][q.r[0]] += q.w[0];
        R.Z[di][q.r[1]] += q.w[1];
    }
    for (int r = 0; r < 4; ++r)
        if (R.Z[0][r] != 0.0 || R.Z[1][r] != 0.0 || R.Z[2][r] != 0.0) {
            R.rLo = std::min(R.rLo, r);
            R.rHi = r + 1;
        }
    for (int a = 0; a < R.nI; ++a) {
        R.sLo[a] = std::max(0, R.rLo - R.oI[a]);
        R.sHi[a] = std::min(3, R.rHi - R.oI[a]);
    }
    R.shape = R.nI == 1 && R.oI[0] == 0 && R.rLo == 0 && R.rHi == 3                   ? 1
              : R.nI == 2 && R.oI[0] == 0 && R.oI[1] == 1 && R.rLo == 1 && R.rHi == 3 ? 2
                                                                                      : 0;
    return R;
}

// Fine node (i, j) of a θ-halved level: its truncated stencil times the θ prolongation (column
// parity Odd), times the row's prolongation, scattered into its parents' Galerkin stencils
// (own: 9 per coarse node). frow: the free flags of rows i − 1, i, i + 1.
template <bool Five, bool Partial, bool Odd, int Shape, class Dirty>
inline void halvedNode(const Level& F, int ntC, double* own, const HalvedRow& R, const char* const frow[3],
                       const Dirty* dirty, int i, int j, int jm, int jp) {
    using St = Stencil<Five>;
    const int nt = F.nt;
    if (!frow[1][j]) return;
    const int J0 = j / 2;  // first parent column (Jref)
    const int J1 = Odd ? (J0 + 1 == ntC ? 0 : J0 + 1) : J0;
    const int nIs = Shape == 1 ? 1 : Shape == 2 ? 2 : R.nI;
    if constexpr (Partial) {
        bool any = false;
        for (int a = 0; a < nIs; ++a) {
            any |= dirty->flag[static_cast<std::size_t>(R.PI[a] * ntC + J0)] != 0;
            if (Odd) any |= dirty->flag[static_cast<std::size_t>(R.PI[a] * ntC + J1)] != 0;
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
    const int yLo = Shape == 1 ? 0 : Shape == 2 ? 1 : R.rLo, yHi = Shape ? 3 : R.rHi;
    double Y[4][4];
    for (int r = yLo; r < yHi; ++r)
        for (int c = cLo; c < cHi; ++c) Y[r][c] = R.Z[0][r] * v[0][c] + R.Z[1][r] * v[1][c] + R.Z[2][r] * v[2][c];
    for (int a = 0; a < nIs; ++a) {
        const int oIa = Shape == 1 ? 0 : Shape == 2 ? a : R.oI[a];
        const int r0 = Shape == 1 ? 0 : Shape == 2 ? 1 - a : R.sLo[a];
        const int r1 = Shape == 1 ? 3 : Shape == 2 ? 3 - a : R.sHi[a];
        const double(*Yr)[4] = &Y[oIa];
        for (int b = 0; b < (Odd ? 2 : 1); ++b) {
            const int J = b ? J1 : J0;
            const int K = R.PI[a] * ntC + J;
            if (Partial && !dirty->flag[static_cast<std::size_t>(K)]) continue;
            const double w = R.WZ[a] * (Odd ? 0.5 : 1.0);
            double* cp = own + 9 * static_cast<std::size_t>(K);
            // Stencil columns c with b + c in [cLo, cHi).
            const int c0 = std::max(0, cLo - b), c1 = std::min(3, cHi - b);
            for (int r = r0; r < r1; ++r)
                for (int c = c0; c < c1; ++c) cp[3 * r + c] += w * Yr[r][b + c];
        }
    }
}

// One fine row of a θ-halved level through halvedNode, by column parity, at the row's shape.
template <bool Five, bool Partial, int Shape, class Dirty>
void halvedSweep(const Level& F, int ntC, double* own, const HalvedRow& R, const Dirty* dirty, int i) {
    const char* fr = F.free.data();
    const int nt = F.nt;
    const char* const frow[3] = {fr + F.im(i) * nt, fr + i * nt, fr + F.ip(i) * nt};
    forColumns(F, 0, 1, [&](int j, int jm, int jp) {
        if (j % 2) halvedNode<Five, Partial, true, Shape>(F, ntC, own, R, frow, dirty, i, j, jm, jp);
        else halvedNode<Five, Partial, false, Shape>(F, ntC, own, R, frow, dirty, i, j, jm, jp);
    });
}

}  // namespace

template <bool Five, bool Partial>
void MultigridSolver::Hierarchy::galerkinHalvedT(const Level& F, Level& C, const Dirty* dirty) {
    const int ntC = C.nt;
    double* own = C.own.data();
    for (int i = 0; i < F.nz; ++i) {
        const auto si = static_cast<std::size_t>(i);
        if (Partial && !dirty->rows[static_cast<std::size_t>(F.pz0[si])] &&
            !dirty->rows[static_cast<std::size_t>(F.pz1[si])])
            continue;
        const HalvedRow R = halvedRow(F, i);
        if (R.shape == 1) halvedSweep<Five, Partial, 1>(F, ntC, own, R, dirty, i);
        else if (R.shape == 2) halvedSweep<Five, Partial, 2>(F, ntC, own, R, dirty, i);
        else halvedSweep<Five, Partial, 0>(F, ntC, own, R, dirty, i);
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

}  // namespace flexehd::lube
