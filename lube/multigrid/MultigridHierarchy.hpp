#pragma once
// MultigridSolver::Hierarchy: the levels of one film grid and the operations on them — geometry
// and prolongation (MultigridHierarchy.cpp), Galerkin coarsening and the coarsest solve
// (GalerkinCoarsening.cpp), line smoothers (LineSmoothers.cpp), V-cycles (VCycle.cpp); the outer
// projected-Newton iteration is MultigridSolver::solve (docs/lube.md §3).
#include <Eigen/Dense>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "lube/MultigridSolver.hpp"
#include "lube/multigrid/MultigridLevel.hpp"

namespace flexehd::lube {

struct MultigridSolver::Hierarchy {
    std::vector<multigrid::Level> levels;
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
    multigrid::Vec dir;                            // line-search direction
    multigrid::Vec invDiag;                        // 1/A_kk on the fine Film nodes (0 elsewhere)
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
    /// The levels' arrays: arena slices (x, f, q, zm, zw, the Galerkin stencils, dir, invDiag)
    /// and the per-level bookkeeping, sized and reset.
    void allocateArena();
    void extractFine(const ReynoldsSystem& sys);
    // The outer iteration's stages (MultigridSolver.cpp): the starting point (returns the
    // pressure scale of the columns without Film nodes), the fused nonlinear pass (returns the
    // scaled residual), the truncated V-cycle correction with its line search (returns α).
    double startingPoint(const FilmGrid& g, Eigen::VectorXd& p, double pLower);
    double nonlinearPass(const ReynoldsSystem& sys, Eigen::VectorXd& p, double pLower, double alpha, double deadScale);
    double correctionStep(Eigen::VectorXd& p, double pLower);
    // Coarse nodes whose Galerkin rows must be rebuilt: flags, list, and flags per coarse row.
    struct Dirty {
        std::vector<char> flag, rows;
        std::vector<int> list;
    };
    void galerkin(std::size_t l, const Dirty* dirty);  // levels[l+1] from levels[l]
    template <bool Five, bool Partial>
    static void galerkinT(const multigrid::Level& F, multigrid::Level& C, const Dirty* dirty);
    template <bool Five, bool Partial>
    static void galerkinHalvedT(const multigrid::Level& F, multigrid::Level& C, const Dirty* dirty);
    void dirtyParents(std::size_t l, const std::vector<int>& changed, Dirty& dirty) const;
    void updateCoarse();
    void factorCoarsest();
    void factorZ(multigrid::Level& L);
    template <bool Five> bool factorZT(multigrid::Level& L, bool mayDefer = false);
    void factorTheta(multigrid::Level& L, int i);
    static void thomasSolve(const multigrid::Level& L, int i, double* r);
    void lineSweepZ(multigrid::Level& L, bool forward);
    template <bool Five> void lineSweepZT(multigrid::Level& L, bool forward);
    template <bool Five> void lineSweepThetaT(multigrid::Level& L, bool forward);
    void lineSweepTheta(multigrid::Level& L, bool forward);
    void smooth(multigrid::Level& L, bool pre);
    void residual(multigrid::Level& L);
    template <bool Five> void residualT(multigrid::Level& L);
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
        void direction(const multigrid::Level& F, int i);
        void curvature(const multigrid::Level& F, int i);
    };
    template <bool Five> void vcycleZT(std::size_t l, LineSearch* ls);
};

}  // namespace flexehd::lube
