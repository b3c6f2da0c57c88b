#pragma once
// MultigridSolver: the fast, cost-linear solver for the cavitation complementarity problem of
// ReynoldsSystem — a truncated nonsmooth Newton multigrid method (TNNMG; Gräser & Kornhuber,
// J. Comput. Math. 27 (2009) 1; Gräser, Sack & Sander 2009), i.e. projected multigrid in the
// Brandt–Cryer / Venner–Lubrecht family made globally convergent by a line search.
//
// The LCP  p ≥ p_cav, w = Ap − b ≥ 0, (p − p_cav)·w = 0  is the minimisation of the convex
// energy J(p) = ½pᵀAp − bᵀp over p ≥ p_cav (A SPD on the Film nodes). One iteration:
//  1. one projected Gauss–Seidel sweep on the fine grid (a descent step; it is what lets nodes
//     leave or enter the cavitated set), plus a second one on the nodes next to the free
//     boundary only (local relaxation at fronts, mask edges and open ends);
//  2. truncation: nodes at the bound p = p_cav are frozen; on the remaining (inactive) nodes the
//     linear defect equation A e = b − Ap is solved approximately by ONE linear multigrid
//     V-cycle whose coarse operators are Galerkin products Pᵀ A P with the prolongation P
//     truncated (zero rows) at frozen and prescribed nodes — the coarse grids never see the
//     cavitated region, so they need no obstacle of their own;
//  3. the correction is projected onto the feasible set, d = max(p_cav, p + e) − p, and applied
//     with the exact line search α = dᵀ(b − Ap)/dᵀAd (clipped to keep p feasible): J decreases
//     monotonically, which gives convergence for any start.
// Grids: the structured FilmGrid hierarchy, coarsened by 2 in each direction where it halves
// (semicoarsening otherwise): bilinear P with the true axial coordinates (non-uniform spacing),
// periodic wrap in θ; masks, supply nodes and open edges enter only through the truncation.
// Smoother: line Gauss–Seidel along the strongly coupled direction of each level (zebra
// tridiagonal solves along z for skirts, Δz ≪ RΔθ; cyclic ones along θ for long bearings;
// alternating when neither dominates), factorizations cached per line; on z-line levels the
// smoothing, residual, restriction, prolongation and (fine level) line search are fused into
// three passes per smoothing step (docs/lube.md §3). When the frozen set changes, only the
// coarse Galerkin rows it reaches are rebuilt. Coarsest grid (≤ 64 nodes, or up to 400 when it
// cannot coarsen): dense LDLT. Unbounded problems (pLower = −∞) use the same loop without
// projection: a linear multigrid iteration with exact line search.
// Convergence criterion: ReynoldsSystem::residual ≤ tolerance (docs/lube.md §3); iterations =
// outer (V-cycle) iterations. Cost per iteration is O(N).
// The work vectors of all levels are slices of one LargeArrayAllocator block per hierarchy (huge
// pages, no zero fill: every array is written before it is read). A cold solve's nested coarse
// problems run on the levels of the fine grid's hierarchy (prepare()).
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "lube/ReynoldsSystem.hpp"
#include "lube/SolverControl.hpp"

namespace flexehd::lube {

class MultigridSolver {
public:
    MultigridSolver();
    ~MultigridSolver();
    MultigridSolver(MultigridSolver&&) noexcept;
    MultigridSolver& operator=(MultigridSolver&&) noexcept;

    /// Solves in place; p holds the warm start on entry (empty: cold start, p = max(p_cav, p_amb)).
    SolveReport solve(const ReynoldsSystem& system, Eigen::VectorXd& p, double pLower,
                      const SolverControl& control);

    /// The same as solve() for the system of the last solve() whose right-hand side alone has
    /// changed (ReynoldsSystem::setSqueezeRate): the coarse operators, smoother directions and
    /// line factorizations of the last solve are kept and updated only where the truncation
    /// changes. Another system (or none solved yet) is solved with solve().
    SolveReport resolve(const ReynoldsSystem& system, Eigen::VectorXd& p, double pLower,
                        const SolverControl& control);

    /// Number of grid levels of the last solve (1 = no coarse grid could be built).
    int levels() const;

    /// Builds the grid hierarchy of `fine` (kept if it exists). solve() on a grid of that
    /// hierarchy — `fine` or one of its coarse levels, which are FilmGrid::coarsened's grids —
    /// then uses it and its memory instead of building one (nested iteration of a cold start).
    void prepare(const FilmGrid& fine);
    /// True if g's geometry is a level of the current hierarchy.
    bool hasLevel(const FilmGrid& g) const;

private:
    SolveReport iterate(const ReynoldsSystem& system, Eigen::VectorXd& p, double pLower, const SolverControl& control);
    struct Hierarchy;
    std::unique_ptr<Hierarchy> h_;
};

}  // namespace flexehd::lube
