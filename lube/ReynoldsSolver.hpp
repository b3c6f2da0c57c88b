#pragma once
// ReynoldsSolver: one film solve — assemble the finite-volume Reynolds system (ReynoldsSystem)
// for the caller's film state and solve it with the chosen cavitation condition and solver.
//
// Cavitation conditions:
//   None            full-Sommerfeld: the linear system, sub-ambient pressures allowed;
//   HalfSommerfeld  the full-Sommerfeld solution with p < p_cav clipped to p_cav afterwards
//                   (not mass conserving; for comparison with classical charts);
//   Reynolds        Swift–Stieber: p ≥ p_cav as a complementarity problem.
// Solvers: Psor (baseline, PsorSolver), ActiveSet (exact, ActiveSetSolver) or Multigrid (fast,
// cost-linear, MultigridSolver). A pressure-
// dependent Lubricant makes the problem nonlinear; it is solved by Picard iteration on ρ(p),
// η(p), each step a full solve warm-started from the previous one.
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "lube/ActiveSetSolver.hpp"
#include "lube/FilmGrid.hpp"
#include "lube/FilmState.hpp"
#include "lube/Lubricant.hpp"
#include "lube/MultigridSolver.hpp"
#include "lube/PsorSolver.hpp"
#include "lube/ReynoldsSystem.hpp"
#include "lube/SolverControl.hpp"

namespace flexehd::lube {

enum class Cavitation { None, HalfSommerfeld, Reynolds };
enum class SolverKind { Psor, ActiveSet, Multigrid };

struct ReynoldsOptions {
    Cavitation cavitation = Cavitation::Reynolds;
    SolverKind solver = SolverKind::ActiveSet;
    double cavitationPressure = 0.0;  ///< p_cav (Pa), same datum as the grid pressures
    SolverControl control;            ///< tolerance on ReynoldsSystem::residual
    double omega = 0.0;               ///< PSOR relaxation, 0 = automatic
    double picardTolerance = 1e-8;    ///< pressure-dependent lubricant: max|Δp| / max|p|
    int maxPicardIterations = 200;
    double picardRelaxation = 1.0;    ///< under-relaxation of p between Picard steps
    /// Active-set and multigrid solvers, cold start: solve first on grids coarsened 2×, 4×, …
    /// (down to ~2000 nodes) and prolong bilinearly, so that the fine active set starts within a
    /// cell or two of the answer (the active set moves one cell per iteration otherwise); for
    /// multigrid this is nested iteration (full multigrid start).
    bool gridSequencing = true;
    /// The solver that redoes a solve the primary one stops without converging (a stalled
    /// multigrid iteration, seen near the dead centres in pure squeeze): the active-set method
    /// gives the same complementarity solution on a sparse factorization. The fallback has the
    /// same options but its own (default) iteration limit. Unset: the stall is thrown
    /// (std::runtime_error).
    std::optional<SolverKind> fallback;
};

struct ReynoldsResult {
    Eigen::VectorXd pressure;  ///< nodal pressure (Pa)
    int iterations = 0;        ///< solver iterations, summed over Picard steps
    int picardIterations = 0;  ///< 1 for a constant-property lubricant
    int coarseIterations = 0;  ///< solver iterations on the coarse grids (grid sequencing)
    double residual = 0.0;     ///< final relative natural residual (before half-Sommerfeld clip)
    bool fellBack = false;     ///< solved by options.fallback after the primary solver stalled
};

class ReynoldsSolver {
public:
    ReynoldsSolver(FilmGrid grid, Lubricant lubricant, ReynoldsOptions options = {});

    /// warmStart: a previous pressure field on the same grid (or nullptr).
    ReynoldsResult solve(const FilmState& film, const Eigen::VectorXd* warmStart = nullptr);

    /// The film of the last solve() with the squeeze rate replaced by dhdt (m/s, one value per
    /// node), from the warm start p (the grid's size): the assembled system and, for the
    /// multigrid solver, its coarse operators are reused (ReynoldsSystem::setSqueezeRate,
    /// MultigridSolver::resolve). For a fixed point that changes only the right-hand side between
    /// solves (JfoSolver's passes). When the last solve() fell back, the fallback solver re-solves
    /// its own system (and the result says so). Constant-property lubricant; std::logic_error
    /// before a solve().
    ReynoldsResult resolve(const Eigen::VectorXd& dhdt, const Eigen::VectorXd& warmStart);

    const FilmGrid& grid() const { return grid_; }
    const Lubricant& lubricant() const { return lubricant_; }
    const ReynoldsOptions& options() const { return options_; }

private:
    ReynoldsResult solveWithPrimary(const FilmState& film, const Eigen::VectorXd* warmStart);
    SolveReport solveOnce(const ReynoldsSystem& sys, Eigen::VectorXd& p);
    double lowerBound() const;  // p_cav under the Reynolds condition, else −∞
    /// Grid-sequenced starting pressure on the fine grid (empty if unavailable).
    Eigen::VectorXd sequencedStart(const FilmState& film, int& coarseIterations);

    struct Level {
        FilmGrid grid;
        std::vector<int> axialMap;  // row of the next finer grid for each row of this one
        ActiveSetSolver solver;
        MultigridSolver multigrid;
    };

    FilmGrid grid_;
    Lubricant lubricant_;
    ReynoldsOptions options_;
    PsorSolver psor_;
    ActiveSetSolver fast_;
    MultigridSolver multigrid_;
    std::vector<Level> coarse_;  // coarse_[0] is 2× coarser than grid_, coarse_[1] 4×, ...
    std::unique_ptr<ReynoldsSystem> last_;  // the last solve's system (constant properties)
    std::unique_ptr<ReynoldsSolver> fallback_;  // options_.fallback's solver
    bool lastFellBack_ = false;                 // the last solve() was the fallback's
};

}  // namespace flexehd::lube
