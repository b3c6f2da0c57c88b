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

struct Level {
    int nz = 0, nt = 0;
    bool periodic = false;
    std::vector<double> z;     // axial coordinates (prolongation weights)
    std::vector<double> a;     // 9 stencil entries per node
    std::vector<char> free;    // unknown of the correction problem (else e = 0)
    Eigen::VectorXd x, f, r;   // correction, right-hand side, residual
    Eigen::VectorXd w, q;      // zebra line-solve work arrays
    // Prolongation from the next coarser level: parents of each row / column of this level.
    std::vector<int> pz0, pz1, pt0, pt1;
    std::vector<double> wz0, wz1, wt0, wt1;
    // Coarsest level: dense factorisation on the free nodes.
    std::vector<int> dense;
    Eigen::VectorXd denseRhs;
    bool direct = false;

    int size() const { return nz * nt; }
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

// Σ_{s ≠ diag} a_s x_nb at node (i, j).
inline double offDiagonalSum(const Level& L, const double* x, int i, int j) {
    const double* c = &L.a[static_cast<std::size_t>(9 * (i * L.nt + j))];
    const int jm = L.jm(j), jp = L.jp(j);
    const double* xm = x + L.im(i) * L.nt;
    const double* x0 = x + i * L.nt;
    const double* xp = x + L.ip(i) * L.nt;
    return c[0] * xm[jm] + c[1] * xm[j] + c[2] * xm[jp] + c[3] * x0[jm] + c[5] * x0[jp] +
           c[6] * xp[jm] + c[7] * xp[j] + c[8] * xp[jp];
}

// Tridiagonal solve (Thomas) of lo_i x_{i-1} + d_i x_i + up_i x_{i+1} = r_i: factor() stores
// the elimination multipliers so that a second right-hand side costs only the substitutions.
struct Tridiagonal {
    std::vector<double> w, m;
    void factor(const std::vector<double>& lo, const std::vector<double>& d,
                const std::vector<double>& up, int n) {
        m[0] = 1.0 / d[0];
        w[0] = up[0] * m[0];
        for (int i = 1; i < n; ++i) {
            m[i] = 1.0 / (d[i] - lo[i] * w[i - 1]);
            w[i] = up[i] * m[i];
        }
    }
    void solve(const std::vector<double>& lo, double* r, int n) const {
        r[0] *= m[0];
        for (int i = 1; i < n; ++i) r[i] = (r[i] - lo[i] * r[i - 1]) * m[i];
        for (int i = n - 2; i >= 0; --i) r[i] -= w[i] * r[i + 1];
    }
};

// Cyclic tridiagonal system (corner terms lo_0 → x_{n−1}, up_{n−1} → x_0) by Sherman–Morrison
// (Numerical Recipes §2.7), in place in r.
void cyclicTridiagonal(const std::vector<double>& lo, std::vector<double>& d,
                       const std::vector<double>& up, std::vector<double>& r, int n,
                       Tridiagonal& t, std::vector<double>& u) {
    const double alpha = lo[0], beta = up[n - 1];
    if (alpha == 0.0 && beta == 0.0) {
        t.factor(lo, d, up, n);
        return t.solve(lo, r.data(), n);
    }
    const double gamma = -d[0];
    const double d0 = d[0], dn = d[n - 1];
    d[0] -= gamma;
    d[n - 1] -= alpha * beta / gamma;
    t.factor(lo, d, up, n);
    t.solve(lo, r.data(), n);
    std::fill(u.begin(), u.begin() + n, 0.0);
    u[0] = gamma;
    u[n - 1] = beta;
    t.solve(lo, u.data(), n);
    const double fact = (r[0] + alpha * r[n - 1] / gamma) / (1.0 + u[0] + alpha * u[n - 1] / gamma);
    for (int i = 0; i < n; ++i) r[i] -= fact * u[i];
    d[0] = d0;
    d[n - 1] = dn;
}

}  // namespace

struct MultigridSolver::Hierarchy {
    std::vector<Level> levels;
    std::vector<char> film;        // Film nodes of the fine grid
    std::vector<char> cachedFree;  // truncation the Galerkin operators were built for
    bool galerkinValid = false;
    std::vector<double> lo, d, up, rhs, u;  // line-solve work arrays
    Tridiagonal tri;
    Eigen::LDLT<Eigen::MatrixXd> ldlt;         // coarsest level
    Eigen::VectorXd dir, Adir, defect;

    void buildGeometry(const FilmGrid& g);
    void extractFine(const ReynoldsSystem& sys);
    void galerkin(std::size_t l);  // levels[l+1] from levels[l]
    void factorCoarsest();
    void lineSweepZ(Level& L, bool forward);
    void lineSweepTheta(Level& L, bool forward);
    void smooth(Level& L, bool pre);
    void residual(Level& L);
    void vcycle(std::size_t l);
    void applyFine(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
};

void MultigridSolver::Hierarchy::buildGeometry(const FilmGrid& g) {
    levels.clear();
    Level L0;
    L0.nz = g.nAxial();
    L0.nt = g.nTheta();
    L0.periodic = g.periodic();
    L0.z = g.axial();
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
        levels.push_back(std::move(C));
    }
    std::size_t maxLine = 0;
    for (Level& L : levels) {
        const auto n = static_cast<std::size_t>(L.size());
        L.a.assign(9 * n, 0.0);
        L.free.assign(n, 0);
        L.x = Eigen::VectorXd::Zero(L.size());
        L.f = Eigen::VectorXd::Zero(L.size());
        L.r = Eigen::VectorXd::Zero(L.size());
        L.w = Eigen::VectorXd::Zero(L.size());
        L.q = Eigen::VectorXd::Zero(L.size());
        maxLine = std::max({maxLine, static_cast<std::size_t>(L.nz), static_cast<std::size_t>(L.nt)});
    }
    for (auto* v : {&lo, &d, &up, &rhs, &u, &tri.w, &tri.m}) v->assign(maxLine, 0.0);
    galerkinValid = false;
}

void MultigridSolver::Hierarchy::extractFine(const ReynoldsSystem& sys) {
    const FilmGrid& g = sys.grid();
    Level& L = levels[0];
    std::fill(L.a.begin(), L.a.end(), 0.0);
    const SparseMatrix& A = sys.matrix();  // symmetric: column k is row k
    film.assign(static_cast<std::size_t>(L.size()), 0);
    for (int k = 0; k < L.size(); ++k) {
        if (!sys.isFilm(k)) continue;
        film[static_cast<std::size_t>(k)] = 1;
        const int i = g.axialIndex(k), j = g.thetaIndex(k);
        for (SparseMatrix::InnerIterator e(A, k); e; ++e) {
            const int r = static_cast<int>(e.row());
            if (r != k && !sys.isFilm(r)) continue;
            L.a[static_cast<std::size_t>(9 * k + L.offset(i, j, g.axialIndex(r), g.thetaIndex(r)))] +=
                e.value();
        }
    }
    galerkinValid = false;
}

void MultigridSolver::Hierarchy::galerkin(std::size_t l) {
    const Level& F = levels[l];
    Level& C = levels[l + 1];
    std::fill(C.a.begin(), C.a.end(), 0.0);
    struct Parent { int i, j; double w; };
    auto parents = [&](int i, int j, Parent* out) {
        const auto si = static_cast<std::size_t>(i), sj = static_cast<std::size_t>(j);
        int n = 0;
        const int zi[2] = {F.pz0[si], F.pz1[si]};
        const double zw[2] = {F.wz0[si], F.wz1[si]};
        const int tj[2] = {F.pt0[sj], F.pt1[sj]};
        const double tw[2] = {F.wt0[sj], F.wt1[sj]};
        for (int p = 0; p < 2; ++p)
            for (int q = 0; q < 2; ++q)
                if (zw[p] != 0.0 && tw[q] != 0.0) out[n++] = {zi[p], tj[q], zw[p] * tw[q]};
        return n;
    };
    Parent pf[4], pg[4];
    for (int i = 0; i < F.nz; ++i) {
        for (int j = 0; j < F.nt; ++j) {
            const int k = i * F.nt + j;
            if (!F.free[static_cast<std::size_t>(k)]) continue;
            const int nf = parents(i, j, pf);
            const int rows[3] = {F.im(i), i, F.ip(i)}, cols[3] = {F.jm(j), j, F.jp(j)};
            for (int s = 0; s < 9; ++s) {
                const double a = F.a[static_cast<std::size_t>(9 * k + s)];
                if (a == 0.0) continue;
                const int i2 = rows[s / 3], j2 = cols[s % 3];
                if (!F.free[static_cast<std::size_t>(i2 * F.nt + j2)]) continue;
                const int ng = parents(i2, j2, pg);
                for (int p = 0; p < nf; ++p)
                    for (int q = 0; q < ng; ++q)
                        C.a[static_cast<std::size_t>(9 * (pf[p].i * C.nt + pf[p].j) +
                                                     C.offset(pf[p].i, pf[p].j, pg[q].i, pg[q].j))] +=
                            pf[p].w * pg[q].w * a;
            }
        }
    }
    for (int k = 0; k < C.size(); ++k) C.free[static_cast<std::size_t>(k)] = C.a[static_cast<std::size_t>(9 * k + kDiag)] > 0.0;
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
            const double a = L.a[static_cast<std::size_t>(9 * k + s)];
            const int c = pos[static_cast<std::size_t>(rows[s / 3] * L.nt + cols[s % 3])];
            if (a != 0.0 && c >= 0) M(q, c) += a;
        }
    }
    // LDLT with pivoting tolerates the (rare) semidefinite coarse operator of a heavily
    // truncated basis: zero pivots give a zero component.
    ldlt.compute(M);
    L.denseRhs.resize(n);
}

// Zebra line Gauss–Seidel along z: the even θ columns, then the odd ones, each colour's
// tridiagonal systems eliminated together row by row (contiguous memory, unlike column-wise
// Thomas solves on a θ-fastest layout).
void MultigridSolver::Hierarchy::lineSweepZ(Level& L, bool forward) {
    double* x = L.x.data();
    double* W = L.w.data();
    double* R = L.q.data();
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
                    W[k] = R[k] = 0.0;
                    continue;
                }
                const double* c = &L.a[static_cast<std::size_t>(9 * k)];
                const int jm = L.jm(j), jp = L.jp(j);
                const double rhs = L.f[k] - (c[0] * xm[jm] + c[2] * xm[jp] + c[3] * x0[jm] +
                                             c[5] * x0[jp] + c[6] * xp[jm] + c[8] * xp[jp]);
                const double lo = i > 0 ? c[1] : 0.0;
                const double m = 1.0 / (c[4] - (i > 0 ? lo * W[k - nt] : 0.0));
                W[k] = c[7] * m;
                R[k] = (rhs - (i > 0 ? lo * R[k - nt] : 0.0)) * m;
            }
        }
        for (int i = L.nz - 1; i >= 0; --i)
            for (int j = colour; j < nt; j += 2) {
                const int k = i * nt + j;
                x[k] = i < L.nz - 1 ? R[k] - W[k] * x[k + nt] : R[k];
            }
    }
}

// Line Gauss–Seidel along θ (one tridiagonal solve per axial row, cyclic when periodic).
void MultigridSolver::Hierarchy::lineSweepTheta(Level& L, bool forward) {
    double* x = L.x.data();
    for (int ii = 0; ii < L.nz; ++ii) {
        const int i = forward ? ii : L.nz - 1 - ii;
        const double* xm = x + L.im(i) * L.nt;
        const double* xp = x + L.ip(i) * L.nt;
        for (int j = 0; j < L.nt; ++j) {
            const auto sj = static_cast<std::size_t>(j);
            const int k = i * L.nt + j;
            if (!L.free[static_cast<std::size_t>(k)]) {
                lo[sj] = up[sj] = rhs[sj] = 0.0;
                d[sj] = 1.0;
                continue;
            }
            const double* c = &L.a[static_cast<std::size_t>(9 * k)];
            const int jm = L.jm(j), jp = L.jp(j);
            lo[sj] = c[3];
            d[sj] = c[4];
            up[sj] = c[5];
            rhs[sj] = L.f[k] - (c[0] * xm[jm] + c[1] * xm[j] + c[2] * xm[jp] + c[6] * xp[jm] +
                                c[7] * xp[j] + c[8] * xp[jp]);
        }
        if (L.periodic) {
            cyclicTridiagonal(lo, d, up, rhs, L.nt, tri, u);
        } else {
            tri.factor(lo, d, up, L.nt);
            tri.solve(lo, rhs.data(), L.nt);
        }
        std::copy(rhs.begin(), rhs.begin() + L.nt, x + i * L.nt);
    }
}

// Alternating line Gauss–Seidel; the post-smoother runs in reverse (symmetric V-cycle).
void MultigridSolver::Hierarchy::smooth(Level& L, bool pre) {
    if (pre) {
        lineSweepZ(L, true);
        lineSweepTheta(L, true);
    } else {
        lineSweepTheta(L, false);
        lineSweepZ(L, false);
    }
}

void MultigridSolver::Hierarchy::residual(Level& L) {
    const double* x = L.x.data();
    for (int i = 0; i < L.nz; ++i)
        for (int j = 0; j < L.nt; ++j) {
            const int k = i * L.nt + j;
            L.r[k] = L.free[static_cast<std::size_t>(k)]
                         ? L.f[k] - L.a[static_cast<std::size_t>(9 * k + kDiag)] * x[k] -
                               offDiagonalSum(L, x, i, j)
                         : 0.0;
        }
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

// y = A x on the Film nodes of the fine grid (0 elsewhere).
void MultigridSolver::Hierarchy::applyFine(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    const Level& L = levels[0];
    y.resize(L.size());
    for (int i = 0; i < L.nz; ++i)
        for (int j = 0; j < L.nt; ++j) {
            const int k = i * L.nt + j;
            y[k] = film[static_cast<std::size_t>(k)]
                       ? L.a[static_cast<std::size_t>(9 * k + kDiag)] * x[k] +
                             offDiagonalSum(L, x.data(), i, j)
                       : 0.0;
        }
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
        // 1. Projected Gauss–Seidel sweep (nonlinear pre-smoother).
        double* x = p.data();
        for (int i = 0; i < F.nz; ++i)
            for (int j = 0; j < F.nt; ++j) {
                const int k = i * F.nt + j;
                if (!H.film[static_cast<std::size_t>(k)]) continue;
                double v = (b[k] - offDiagonalSum(F, x, i, j)) / F.a[static_cast<std::size_t>(9 * k + kDiag)];
                if (bounded && v < pLower) v = pLower;
                x[k] = v;
            }
        // 2. Defect b − Ap and the convergence criterion of ReynoldsSystem::residual.
        H.applyFine(p, H.Adir);
        double rmax = 0.0, scale = 0.0;
        for (int k = 0; k < n; ++k) {
            scale = std::max(scale, std::abs(p[k] - pAmb));
            if (!H.film[static_cast<std::size_t>(k)]) {
                F.f[k] = 0.0;
                continue;
            }
            F.f[k] = b[k] - H.Adir[k];
            double rk = -F.f[k] / F.a[static_cast<std::size_t>(9 * k + kDiag)];
            if (bounded) rk = std::min(p[k] - pLower, rk);
            rmax = std::max(rmax, std::abs(rk));
        }
        rep.residual = rmax == 0.0 ? 0.0 : rmax / std::max(scale, std::numeric_limits<double>::min());
        if (first < 0.0) first = rep.residual;
        if (!std::isfinite(rep.residual) || rep.residual > 1e8 * std::max(first, 1.0))
            throw std::runtime_error("MultigridSolver: diverged after " +
                                     std::to_string(rep.iterations) + " iterations (residual " +
                                     std::to_string(rep.residual) + ")");
        if (rep.residual <= control.tolerance) return rep;
        if (rep.iterations == maxIt) break;
        // 3. Truncation: nodes at the bound are frozen; Galerkin operators follow the set.
        for (int k = 0; k < n; ++k)
            F.free[static_cast<std::size_t>(k)] =
                H.film[static_cast<std::size_t>(k)] && !(bounded && p[k] <= pLower);
        if (!H.galerkinValid || F.free != H.cachedFree) {
            for (std::size_t l = 0; l + 1 < H.levels.size(); ++l) H.galerkin(l);
            H.factorCoarsest();
            H.cachedFree = F.free;
            H.galerkinValid = true;
        }
        // 4. One linear V-cycle on the inactive nodes, projection, exact line search.
        H.defect = F.f;
        H.vcycle(0);
        H.dir.resize(n);
        double alphaMax = std::numeric_limits<double>::infinity();
        for (int k = 0; k < n; ++k) {
            double dk = F.free[static_cast<std::size_t>(k)] ? F.x[k] : 0.0;
            if (bounded && p[k] + dk < pLower) dk = pLower - p[k];
            H.dir[k] = dk;
            if (bounded && dk < 0.0) alphaMax = std::min(alphaMax, (p[k] - pLower) / -dk);
        }
        H.applyFine(H.dir, H.Adir);
        const double num = H.dir.dot(H.defect), den = H.dir.dot(H.Adir);
        if (den > 0.0 && num > 0.0) {
            const double alpha = std::min(num / den, std::max(alphaMax, 1.0));
            p += alpha * H.dir;
            if (bounded)
                for (int k = 0; k < n; ++k)
                    if (H.film[static_cast<std::size_t>(k)] && p[k] < pLower) p[k] = pLower;
        }
        ++rep.iterations;
    }
    throw std::runtime_error("MultigridSolver: not converged after " + std::to_string(maxIt) +
                             " iterations (residual " + std::to_string(rep.residual) +
                             " > tolerance " + std::to_string(control.tolerance) + ")");
}

}  // namespace flexehd::lube
