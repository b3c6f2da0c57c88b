#include "lube/MultigridSolver.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace flexehd::lube {

namespace {

// 9-point stencils on structured levels: entry s = (di+1)*3 + (dj+1) couples node (i, j) to
// (i+di, j+dj) (θ wrapped when periodic). The fine level has only the 5-point entries.
constexpr int kDiag = 4;
constexpr int sidx(int di, int dj) { return (di + 1) * 3 + (dj + 1); }
constexpr std::size_t kDirectMax = 400;  // coarsest level solved by dense LDLT up to this size
constexpr std::size_t sj(int j) { return static_cast<std::size_t>(j); }

enum class Lines { Z, Theta, Both };

// Stencil layouts: coarse levels store 9 entries per node in sidx order; the fine level, whose
// operator is the 5-point finite-volume one, stores only (S, W, C, E, N) = sidx entries
// 1, 3, 4, 5, 7 — 40 instead of 72 bytes per node, which matters because the fine-level passes
// are memory-bound.
template <bool Five>
struct Stencil {
    static constexpr int n = Five ? 5 : 9;
    static constexpr int S = Five ? 0 : 1, W = Five ? 1 : 3, C = Five ? 2 : 4, E = Five ? 3 : 5,
                         N = Five ? 4 : 7;
};
constexpr int kFivePos[9] = {-1, 0, -1, 1, 2, 3, -1, 4, -1};  // sidx → 5-point slot

struct Level {
    int nz = 0, nt = 0;
    bool periodic = false;
    std::vector<double> z;     // axial coordinates (prolongation weights)
    std::vector<double> a;     // stencil entries per node: 9, or 5 on the fine level (Stencil)
    std::vector<char> free;    // unknown of the correction problem (else e = 0)
    Eigen::VectorXd x, f, r;   // correction, right-hand side, residual
    Eigen::VectorXd q;         // zebra line-solve work array
    // Line factorizations, kept while the stencil and truncation of the line are unchanged:
    // z-lines (per node: Thomas multipliers zm = 1/pivot, zw = upper·zm; valid per column),
    // θ-lines (per node: tm, tw, lower coefficient tl, Sherman–Morrison vector tu; per row:
    // corner terms and denominator; valid per row).
    std::vector<double> zm, zw, tm, tw, tl, tu;
    std::vector<double> tAlpha, tGamma, tDen;
    std::vector<char> colOk, rowOk;
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
    int size() const { return nz * nt; }
    /// Entry s (9-point numbering sidx) of node k's stencil, whatever the layout.
    double coef(std::size_t k, int s) const;
    void invalidateLines() {
        std::fill(colOk.begin(), colOk.end(), 0);
        std::fill(rowOk.begin(), rowOk.end(), 0);
    }
    void invalidateLines(int k) {
        rowOk[static_cast<std::size_t>(k / nt)] = 0;
        colOk[static_cast<std::size_t>(k % nt)] = 0;
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
    const int m = kFivePos[s];
    return m < 0 ? 0.0 : a[5 * k + static_cast<std::size_t>(m)];
}

// Σ_{s ≠ diag} a_s x_nb at node (i, j). Five: the 5-point stencil of the fine level (the corner
// entries are zero there and skipped).
template <bool Five = false>
inline double offDiagonalSum(const Level& L, const double* x, int i, int j) {
    using St = Stencil<Five>;
    const double* c = &L.a[static_cast<std::size_t>(St::n * (i * L.nt + j))];
    const int jm = L.jm(j), jp = L.jp(j);
    const double* xm = x + L.im(i) * L.nt;
    const double* x0 = x + i * L.nt;
    const double* xp = x + L.ip(i) * L.nt;
    if constexpr (Five) return c[St::S] * xm[j] + c[St::W] * x0[jm] + c[St::E] * x0[jp] + c[St::N] * xp[j];
    return c[0] * xm[jm] + c[1] * xm[j] + c[2] * xm[jp] + c[3] * x0[jm] + c[5] * x0[jp] +
           c[6] * xp[jm] + c[7] * xp[j] + c[8] * xp[jp];
}

// Smoother direction of a level from its couplings summed over the free nodes: line relaxation
// along z alone when the axial couplings are at least twice the circumferential ones (skirts,
// Δz < RΔθ), along θ alone in the opposite case (long bearings, few axial nodes), alternating
// otherwise. A line smoother along the strong direction smooths well for any ratio ≥ 2
// (Trottenberg, Oosterlee & Schüller, Multigrid, 2001, §5.1); the alternating one is the robust
// fallback near isotropy.
void chooseLines(Level& L) {
    double sz = 0.0, st = 0.0;
    for (int k = 0; k < L.size(); ++k) {
        if (!L.free[static_cast<std::size_t>(k)]) continue;
        const auto sk = static_cast<std::size_t>(k);
        const double corners = L.coef(sk, 0) + L.coef(sk, 2) + L.coef(sk, 6) + L.coef(sk, 8);
        sz -= L.coef(sk, 1) + L.coef(sk, 7) + 0.5 * corners;  // corners couple both ways
        st -= L.coef(sk, 3) + L.coef(sk, 5) + 0.5 * corners;
    }
    L.lines = sz >= 2.0 * st ? Lines::Z : st >= 2.0 * sz ? Lines::Theta : Lines::Both;
}

}  // namespace

struct MultigridSolver::Hierarchy {
    std::vector<Level> levels;
    std::vector<char> film;        // Film nodes of the fine grid
    std::vector<char> cachedFree;  // truncation the Galerkin operators were built for
    bool galerkinValid = false;
    std::vector<double> lo, d, up, rhs;  // line-solve work arrays
    Eigen::LDLT<Eigen::MatrixXd> ldlt;  // coarsest level
    Eigen::VectorXd dir;                // line-search direction
    Eigen::VectorXd invDiag;            // 1/A_kk on the fine Film nodes (0 elsewhere)

    void buildGeometry(const FilmGrid& g);
    void extractFine(const ReynoldsSystem& sys);
    // Coarse nodes whose Galerkin rows must be rebuilt: flags, list, and flags per coarse row.
    struct Dirty {
        std::vector<char> flag, rows;
        std::vector<int> list;
    };
    void galerkin(std::size_t l, const Dirty* dirty);  // levels[l+1] from levels[l]
    void dirtyParents(std::size_t l, const std::vector<int>& changed, Dirty& dirty) const;
    void updateCoarse();
    void factorCoarsest();
    void factorZ(Level& L);
    template <bool Five> void factorZT(Level& L);
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
    std::size_t maxLine = 0;
    for (Level& L : levels) {
        const auto n = static_cast<std::size_t>(L.size());
        L.a.assign((L.five ? 5 : 9) * n, 0.0);
        L.free.assign(n, 0);
        L.x = Eigen::VectorXd::Zero(L.size());
        L.f = Eigen::VectorXd::Zero(L.size());
        L.r = Eigen::VectorXd::Zero(L.size());
        L.q = Eigen::VectorXd::Zero(L.size());
        for (auto* v : {&L.zm, &L.zw, &L.tm, &L.tw, &L.tl, &L.tu}) v->clear();  // on first use
        for (auto* v : {&L.tAlpha, &L.tGamma, &L.tDen}) v->assign(static_cast<std::size_t>(L.nz), 0.0);
        L.colOk.assign(static_cast<std::size_t>(L.nt), 0);
        L.rowOk.assign(static_cast<std::size_t>(L.nz), 0);
        maxLine = std::max({maxLine, static_cast<std::size_t>(L.nz), static_cast<std::size_t>(L.nt)});
    }
    for (auto* v : {&lo, &d, &up, &rhs}) v->assign(maxLine, 0.0);
    galerkinValid = false;
}

void MultigridSolver::Hierarchy::extractFine(const ReynoldsSystem& sys) {
    Level& L = levels[0];
    std::fill(L.a.begin(), L.a.end(), 0.0);
    const SparseMatrix& A = sys.matrix();  // symmetric: column k is row k
    film.assign(static_cast<std::size_t>(L.size()), 0);
    const int nt = L.nt;
    for (int k = 0; k < L.size(); ++k) {
        if (!sys.isFilm(k)) continue;
        film[static_cast<std::size_t>(k)] = 1;
        double* c = &L.a[static_cast<std::size_t>(5 * k)];  // 5-point layout
        for (SparseMatrix::InnerIterator e(A, k); e; ++e) {
            const int r = static_cast<int>(e.row());
            if (r != k && !sys.isFilm(r)) continue;
            // 5-point neighbours by index difference (θ fastest; periodic wrap ±(nθ − 1)).
            const int d = r - k;
            using St = Stencil<true>;
            const int s = d == 0 ? St::C : d == -nt ? St::S : d == nt ? St::N
                        : (d == -1 || d == nt - 1) ? St::W : St::E;
            c[s] += e.value();
        }
    }
    invDiag = Eigen::VectorXd::Zero(L.size());
    for (int k = 0; k < L.size(); ++k)
        if (film[static_cast<std::size_t>(k)]) invDiag[k] = 1.0 / L.a[static_cast<std::size_t>(5 * k + Stencil<true>::C)];
    L.invalidateLines();
    galerkinValid = false;
}

// Galerkin coarse operator C = Pᵀ T A T P (T: truncation to the free nodes) of levels[l+1] from
// levels[l], accumulated fine node by fine node. With `dirty` (one flag per coarse node), only the
// dirty coarse rows are zeroed and re-accumulated — the same sums as a full rebuild restricted to
// those rows, so a row with no free child gets an exact zero diagonal.
void MultigridSolver::Hierarchy::galerkin(std::size_t l, const Dirty* dirty) {
    const Level& F = levels[l];
    Level& C = levels[l + 1];
    if (!dirty) {
        std::fill(C.a.begin(), C.a.end(), 0.0);
    } else {
        for (int K : dirty->list) std::fill_n(C.a.begin() + 9 * K, 9, 0.0);
    }
    // Per fine node k: y = row k of (T A T) P, gathered in a 3×3 buffer over the coarse nodes
    // around k's first parent (Iref, Jref) — the 9-point structure keeps every coupling within
    // ±1 coarse row/column — then scattered into the rows of k's parents with their weights.
    const int ntC = C.nt;
    auto wrap = [&](int d) {
        if (C.periodic) {
            if (d > 1) d -= ntC;
            else if (d < -1) d += ntC;
        }
        return d;
    };
    for (int i = 0; i < F.nz; ++i) {
        const auto si = static_cast<std::size_t>(i);
        const int Iref = F.pz0[si];
        if (dirty && !dirty->rows[static_cast<std::size_t>(F.pz0[si])] &&
            !dirty->rows[static_cast<std::size_t>(F.pz1[si])])
            continue;  // no parent row of this fine row is rebuilt
        const int rows[3] = {F.im(i), i, F.ip(i)};
        for (int j = 0; j < F.nt; ++j) {
            const int k = i * F.nt + j;
            if (!F.free[static_cast<std::size_t>(k)]) continue;
            const auto sj = static_cast<std::size_t>(j);
            int np = 0, PI[4], PJ[4];
            double PW[4];
            for (int a = 0; a < 2; ++a) {
                const double wz = a ? F.wz1[si] : F.wz0[si];
                if (wz == 0.0) continue;
                for (int b = 0; b < 2; ++b) {
                    const double wt = b ? F.wt1[sj] : F.wt0[sj];
                    if (wt == 0.0) continue;
                    const int I = a ? F.pz1[si] : F.pz0[si], J = b ? F.pt1[sj] : F.pt0[sj];
                    if (dirty && !dirty->flag[static_cast<std::size_t>(I * ntC + J)]) continue;
                    PI[np] = I;
                    PJ[np] = J;
                    PW[np++] = wz * wt;
                }
            }
            if (np == 0) continue;
            const int Jref = F.pt0[sj];
            double Y[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
            const int cols[3] = {F.jm(j), j, F.jp(j)};
            const Level::Rel* zr = &F.zRel[3 * si];
            const Level::Rel* tr = &F.tRel[3 * sj];
            // Nonzero stencil entries (sidx, value): the 5-point fine level has only 5.
            static constexpr int kFiveSidx[5] = {1, 3, 4, 5, 7};
            const int ns = F.five ? 5 : 9;
            const double* ak = &F.a[static_cast<std::size_t>(ns * k)];
            for (int e = 0; e < ns; ++e) {
                const int s = F.five ? kFiveSidx[e] : e;
                const int di = s / 3, dj = s % 3;
                if (!F.free[static_cast<std::size_t>(rows[di] * F.nt + cols[dj])]) continue;
                const double a = ak[e];
                const Level::Rel& Z = zr[di];
                const Level::Rel& T = tr[dj];
                Y[Z.r[0]][T.r[0]] += Z.w[0] * T.w[0] * a;
                Y[Z.r[0]][T.r[1]] += Z.w[0] * T.w[1] * a;
                Y[Z.r[1]][T.r[0]] += Z.w[1] * T.w[0] * a;
                Y[Z.r[1]][T.r[1]] += Z.w[1] * T.w[1] * a;
            }
            for (int p = 0; p < np; ++p) {
                // Slot (r, c) of Y is the coarse node at offset (r − 1 + dI, c − 1 + dJ) from the
                // parent; dI, dJ ∈ {−1, 0}, so r ≥ −dI and c ≥ −dJ keep it inside the 9 entries.
                const int dI = Iref - PI[p], dJ = wrap(Jref - PJ[p]);
                double* cp = &C.a[static_cast<std::size_t>(9 * (PI[p] * ntC + PJ[p]))];
                for (int r = -dI; r < 3; ++r)
                    for (int c = -dJ; c < 3; ++c) cp[sidx(r - 1 + dI, c - 1 + dJ)] += PW[p] * Y[r][c];
            }
        }
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
    Level& F = levels[0];
    std::vector<int> changed;
    if (galerkinValid) {
        for (std::size_t k = 0; k < F.free.size(); ++k)
            if (F.free[k] != cachedFree[k]) changed.push_back(static_cast<int>(k));
        if (changed.empty()) return;
        for (int k : changed) F.invalidateLines(k);
    }
    bool full = !galerkinValid;
    Dirty dirty;
    for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
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
        for (Level& L : levels) chooseLines(L);
    factorCoarsest();
    cachedFree = F.free;
    galerkinValid = true;
}

void MultigridSolver::Hierarchy::factorCoarsest() {
    Level& L = levels.back();
    L.dense.clear();
    L.direct = static_cast<std::size_t>(L.size()) <= kDirectMax;
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

template <bool Five>
void MultigridSolver::Hierarchy::factorZT(Level& L) {
    using St = Stencil<Five>;
    const int nt = L.nt;
    if (L.zm.empty()) {
        L.zm.assign(static_cast<std::size_t>(L.size()), 0.0);
        L.zw.assign(static_cast<std::size_t>(L.size()), 0.0);
    }
    bool any = false;
    for (char ok : L.colOk) any |= !ok;
    if (!any) return;
    // Row by row over the stale columns (contiguous memory).
    for (int i = 0; i < L.nz; ++i)
        for (int j = 0; j < nt; ++j) {
            if (L.colOk[static_cast<std::size_t>(j)]) continue;
            const auto sk = static_cast<std::size_t>(i * nt + j);
            if (!L.free[sk]) {
                L.zm[sk] = L.zw[sk] = 0.0;
                continue;
            }
            const double* c = &L.a[St::n * sk];
            const double lo = i > 0 ? c[St::S] : 0.0;
            const double m = 1.0 / (c[St::C] - (i > 0 ? lo * L.zw[sk - static_cast<std::size_t>(nt)] : 0.0));
            L.zm[sk] = m;
            L.zw[sk] = c[St::N] * m;
        }
    std::fill(L.colOk.begin(), L.colOk.end(), 1);
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
                const double* c = &L.a[static_cast<std::size_t>(St::n * k)];
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
    m[0] = 1.0 / d[0];
    w[0] = up[0] * m[0];
    for (int j = 1; j < nt; ++j) {
        m[j] = 1.0 / (d[sj(j)] - lo[sj(j)] * w[j - 1]);
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
            const double* c = &L.a[static_cast<std::size_t>(St::n * k)];
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
    const double* x = L.x.data();
    for (int i = 0; i < L.nz; ++i)
        for (int j = 0; j < L.nt; ++j) {
            const int k = i * L.nt + j;
            L.r[k] = L.free[static_cast<std::size_t>(k)]
                         ? L.f[k] - L.a[static_cast<std::size_t>(Stencil<Five>::n * k + Stencil<Five>::C)] * x[k] -
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
    L.x.setZero();
    if (l + 1 == levels.size()) {
        if (L.direct) {
            if (L.dense.empty()) return;
            for (std::size_t q = 0; q < L.dense.size(); ++q) L.denseRhs[static_cast<Eigen::Index>(q)] = L.f[L.dense[q]];
            const Eigen::VectorXd y = ldlt.solve(L.denseRhs);
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

int MultigridSolver::levels() const { return h_ ? static_cast<int>(h_->levels.size()) : 0; }

SolveReport MultigridSolver::solve(const ReynoldsSystem& sys, Eigen::VectorXd& p, double pLower,
                                   const SolverControl& control) {
    const FilmGrid& g = sys.grid();
    const int n = g.size();
    if (!h_ || h_->levels[0].nz != g.nAxial() || h_->levels[0].nt != g.nTheta() ||
        h_->levels[0].periodic != g.periodic() || h_->levels[0].z != g.axial()) {
        h_ = std::make_unique<Hierarchy>();
        h_->buildGeometry(g);
    }
    Hierarchy& H = *h_;
    H.extractFine(sys);
    Level& F = H.levels[0];
    const bool bounded = std::isfinite(pLower);
    const Eigen::VectorXd& b = sys.rhs();
    if (p.size() != n) p = sys.initialGuess(pLower);
    for (int k = 0; k < n; ++k)
        if (!sys.isFilm(k)) p[k] = g.prescribedPressure(k);
        else if (bounded && p[k] < pLower) p[k] = pLower;

    // Iteration cap: each iteration is a whole V-cycle, so PSOR's sweep budget is far too many.
    const int maxIt = std::min(control.maxIterations, 500);
    const double pAmb = g.ambientPressure();
    SolveReport rep;
    double first = -1.0;
    for (;;) {
        // 1. Projected Gauss–Seidel sweep (nonlinear pre-smoother), red–black ordering: the
        // updates of one colour are independent (5-point stencil), so they pipeline. Done as a
        // wavefront — red nodes of row i, then black nodes of row i − 1, whose red neighbours are
        // all updated by then — the same result as two full passes with half the memory traffic.
        double* x = p.data();
        const double* invDiag = H.invDiag.data();
        auto pgsRow = [&](int i, int colour) {
            for (int j = (i + colour) % 2; j < F.nt; j += 2) {
                const int k = i * F.nt + j;
                if (!H.film[static_cast<std::size_t>(k)]) continue;
                double v = (b[k] - offDiagonalSum<true>(F, x, i, j)) * invDiag[k];
                if (bounded && v < pLower) v = pLower;
                x[k] = v;
            }
        };
        for (int i = 0; i <= F.nz; ++i) {
            if (i < F.nz) pgsRow(i, 0);
            if (i > 0) pgsRow(i - 1, 1);
        }
        // 2. Defect b − Ap and the convergence criterion of ReynoldsSystem::residual; the
        // truncation (3.) of the same pass: nodes at the bound are frozen.
        double rmax = 0.0, scale = 0.0;
        for (int i = 0; i < F.nz; ++i)
            for (int j = 0; j < F.nt; ++j) {
                const int k = i * F.nt + j;
                const auto sk = static_cast<std::size_t>(k);
                scale = std::max(scale, std::abs(p[k] - pAmb));
                if (!H.film[sk]) {
                    F.f[k] = 0.0;
                    F.free[sk] = 0;
                    continue;
                }
                F.f[k] = b[k] - F.a[5 * sk + Stencil<true>::C] * x[k] - offDiagonalSum<true>(F, x, i, j);
                double rk = -F.f[k] * invDiag[k];
                if (bounded) rk = std::min(p[k] - pLower, rk);
                rmax = std::max(rmax, std::abs(rk));
                F.free[sk] = !(bounded && p[k] <= pLower);
            }
        rep.residual = rmax == 0.0 ? 0.0 : rmax / std::max(scale, std::numeric_limits<double>::min());
        if (first < 0.0) first = rep.residual;
        if (!std::isfinite(rep.residual) || rep.residual > 1e8 * std::max(first, 1.0))
            throw std::runtime_error("MultigridSolver: diverged after " +
                                     std::to_string(rep.iterations) + " iterations (residual " +
                                     std::to_string(rep.residual) + ")");
        if (rep.residual <= control.tolerance) return rep;
        if (rep.iterations == maxIt) break;
        // 3. The Galerkin operators follow the truncation.
        H.updateCoarse();
        // 4. One linear V-cycle on the inactive nodes, projection, exact line search.
        H.vcycle(0);
        H.dir.resize(n);
        double alphaMax = std::numeric_limits<double>::infinity();
        for (int k = 0; k < n; ++k) {
            double dk = F.free[static_cast<std::size_t>(k)] ? F.x[k] : 0.0;
            if (bounded && p[k] + dk < pLower) dk = pLower - p[k];
            H.dir[k] = dk;
            if (bounded && dk < 0.0) alphaMax = std::min(alphaMax, (p[k] - pLower) / -dk);
        }
        double num = 0.0, den = 0.0;  // dᵀ(b − Ap) and dᵀAd
        const double* dd = H.dir.data();
        for (int i = 0; i < F.nz; ++i)
            for (int j = 0; j < F.nt; ++j) {
                const int k = i * F.nt + j;
                const auto sk = static_cast<std::size_t>(k);
                if (!H.film[sk] || dd[k] == 0.0) continue;
                num += dd[k] * F.f[k];
                den += dd[k] * (F.a[5 * sk + Stencil<true>::C] * dd[k] + offDiagonalSum<true>(F, dd, i, j));
            }
        if (den > 0.0 && num > 0.0) {
            const double alpha = std::min(num / den, std::max(alphaMax, 1.0));
            for (int k = 0; k < n; ++k) {
                double v = p[k] + alpha * dd[k];
                if (bounded && H.film[static_cast<std::size_t>(k)] && v < pLower) v = pLower;
                p[k] = v;
            }
        }
        ++rep.iterations;
    }
    throw std::runtime_error("MultigridSolver: not converged after " + std::to_string(maxIt) +
                             " iterations (residual " + std::to_string(rep.residual) +
                             " > tolerance " + std::to_string(control.tolerance) + ")");
}

}  // namespace flexehd::lube
