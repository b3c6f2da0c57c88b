// The level hierarchy of a film grid: coarsening by 2 where a direction halves, the bilinear
// prolongation with the true axial coordinates, the arena of the work vectors, the fine
// operator and truncation taken from the ReynoldsSystem (docs/lube.md §3).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lube/multigrid/MultigridHierarchy.hpp"

namespace flexehd::lube {

using namespace multigrid;

namespace multigrid {


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

}  // namespace multigrid


namespace {

// The coarse level C of F (z halved if cz, θ halved if ct) and the prolongation weights of F's
// rows and columns from C's.
void coarsen(Level& F, Level& C, bool cz, bool ct) {
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
}

// A prolongation weight pair as slots −1, 0, +1 about the coarse node `first` (periodic: modulo
// nPeriodic).
Level::Rel prolongationSlots(int first, int p0, int p1, double w0, double w1, int nPeriodic) {
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
}

// The prolongation of each fine row and column's 3 neighbours relative to its own coarse node.
void prolongationRelations(Level& F, const Level& C) {
    const auto nzF = static_cast<std::size_t>(F.nz), ntF = static_cast<std::size_t>(F.nt);
    const auto rel = prolongationSlots;
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
}

// The per-level arrays that are not arena slices, sized and reset.
void resetLevelArrays(Level& L) {
    const auto n = static_cast<std::size_t>(L.size());
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
}

}  // namespace

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
        coarsen(F, C, cz, ct);
        prolongationRelations(F, C);
        levels.push_back(std::move(C));
    }
    allocateArena();
}

void MultigridSolver::Hierarchy::allocateArena() {
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
        resetLevelArrays(L);
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
int MultigridSolver::Hierarchy::find(const FilmGrid& g) const {
    for (std::size_t l = 0; l < levels.size(); ++l) {
        const Level& L = levels[l];
        if (L.nz == g.nAxial() && L.nt == g.nTheta() && L.periodic == g.periodic() && L.z == g.axial())
            return static_cast<int>(l);
    }
    return -1;
}

}  // namespace flexehd::lube
