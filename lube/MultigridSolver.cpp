// The outer iteration of the truncated nonsmooth Newton multigrid method (MultigridSolver.hpp):
// projected Gauss–Seidel, the truncated V-cycle correction, the exact projected line search.
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

#include "lube/multigrid/MultigridHierarchy.hpp"

namespace flexehd::lube {

using namespace multigrid;

MultigridSolver::MultigridSolver() = default;
MultigridSolver::~MultigridSolver() = default;
MultigridSolver::MultigridSolver(MultigridSolver&&) noexcept = default;
MultigridSolver& MultigridSolver::operator=(MultigridSolver&&) noexcept = default;

int MultigridSolver::levels() const { return h_ ? static_cast<int>(h_->levels.size() - h_->base) : 0; }


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

// The starting point: prescribed values on the non-Film nodes, the bound on the Film nodes, the
// free boundary (for the local relaxation of the first iteration) and the near flags; returns the
// pressure scale's share of the columns without Film nodes (skipped by the passes: no defect, not
// free, constant).
double MultigridSolver::Hierarchy::startingPoint(const FilmGrid& g, Eigen::VectorXd& p, double pLower) {
    Hierarchy& H = *this;
    Level& F = H.levels[H.base];
    const int n = g.size();
    const bool bounded = std::isfinite(pLower);
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
    return deadScale;
}

// The nonlinear part of one iteration, returning the scaled residual of ReynoldsSystem::residual:
// 1. the step of the previous iteration, p ← max(p_cav, p + α d); 2. one projected Gauss–Seidel
// sweep (the nonlinear pre-smoother) in red–black order, and a second one on the nodes next to the
// free boundary (near); 3. the defect b − Ap, the convergence criterion and the truncation (nodes
// at the bound are frozen), and the near flags for the next iteration. Fused into one wavefront
// over the rows — at step t: step of row t, red nodes of row t − 1, black of t − 2, near red of
// t − 3, near black of t − 4, defect of t − 5, near flags of t − 6: each uses only rows that are
// final for it, so the result is that of separate passes, in one pass over memory. Locals, not
// captured references: the lambdas store through double pointers, after which referenced doubles
// would have to be reloaded.
double MultigridSolver::Hierarchy::nonlinearPass(const ReynoldsSystem& sys, Eigen::VectorXd& p, double pLower,
                                                 double alpha, double deadScale) {
    Hierarchy& H = *this;
    Level& F = H.levels[H.base];
    const bool bounded = std::isfinite(pLower);
    const double pAmb = sys.grid().ambientPressure();
    const double* __restrict b = sys.rhs().data();
    double* __restrict x = p.data();
    double* __restrict dir = H.dir.data();
    const double* __restrict invDiag = H.invDiag.data();
    const char* __restrict film = H.film.data();
    const int nz = F.nz, nt = F.nt;
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
    return rmax == 0.0 ? 0.0 : rmax / std::max(scale, std::numeric_limits<double>::min());
}

// The linear part of one iteration: 4. the Galerkin operators follow the truncation; 5. one linear
// V-cycle on the inactive nodes, whose correction, projected, is the search direction, with the
// exact line search α = dᵀ(b − Ap)/dᵀAd (fused into the V-cycle's last pass on z-line levels).
// Returns α.
double MultigridSolver::Hierarchy::correctionStep(Eigen::VectorXd& p, double pLower) {
    Hierarchy& H = *this;
    Level& F = H.levels[H.base];
    H.updateCoarse();
    LineSearch ls{p.data(), pLower, std::isfinite(pLower), H.dir.data(), &H.filmRuns};
    if (F.fusedZ) {
        H.vcycleZT<true>(H.base, &ls);
    } else {
        H.vcycle(H.base);
        for (int i = 0; i < F.nz; ++i) ls.direction(F, i);
        for (int i = 0; i < F.nz; ++i) ls.curvature(F, i);
    }
    return ls.den > 0.0 && ls.num > 0.0 ? std::min(ls.num / ls.den, std::max(ls.alphaMax, 1.0)) : 0.0;
}

SolveReport MultigridSolver::solve(const ReynoldsSystem& sys, Eigen::VectorXd& p, double pLower,
                                   const SolverControl& control) {
    const FilmGrid& g = sys.grid();
    const int found = h_ ? h_->find(g) : -1;
    if (found < 0) {
        h_ = std::make_unique<Hierarchy>();
        h_->buildGeometry(g);
    }
    Hierarchy& H = *h_;
    H.base = found < 0 ? 0 : static_cast<std::size_t>(found);
    H.extractFine(sys);
    return iterate(sys, p, pLower, control);
}

SolveReport MultigridSolver::resolve(const ReynoldsSystem& sys, Eigen::VectorXd& p, double pLower,
                                     const SolverControl& control) {
    if (!h_ || h_->levels[h_->base].a != sys.stencil().data() || h_->levels[h_->base].size() != sys.grid().size())
        return solve(sys, p, pLower, control);  // not the last solve's system
    return iterate(sys, p, pLower, control);
}

SolveReport MultigridSolver::iterate(const ReynoldsSystem& sys, Eigen::VectorXd& p, double pLower,
                                     const SolverControl& control) {
    const FilmGrid& g = sys.grid();
    Hierarchy& H = *h_;
    if (p.size() != g.size()) p = sys.initialGuess(pLower);
    const double deadScale = H.startingPoint(g, p, pLower);

    // Iteration cap: each iteration is a whole V-cycle, so PSOR's sweep budget is far too many.
    const int maxIt = std::min(control.maxIterations, 500);
    SolveReport rep;
    double first = -1.0;
    double alpha = 0.0;  // step along dir still to be applied (line search of the last iteration)
    for (;;) {
        rep.residual = H.nonlinearPass(sys, p, pLower, alpha, deadScale);
        if (first < 0.0) first = rep.residual;
        if (!std::isfinite(rep.residual) || rep.residual > 1e8 * std::max(first, 1.0))
            throw std::runtime_error("MultigridSolver: diverged after " +
                                     std::to_string(rep.iterations) + " iterations (residual " +
                                     messageNumber(rep.residual) + ")");
        if (rep.residual <= control.tolerance && rep.iterations >= std::min(control.minIterations, maxIt))
            return rep;
        if (rep.iterations == maxIt) break;
        alpha = H.correctionStep(p, pLower);
        ++rep.iterations;
    }
    throw std::runtime_error("MultigridSolver: not converged after " + std::to_string(maxIt) +
                             " iterations (residual " + messageNumber(rep.residual) +
                             " > tolerance " + messageNumber(control.tolerance) + ")");
}

}  // namespace flexehd::lube
