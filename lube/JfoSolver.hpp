#pragma once
// JfoSolver: mass-conserving (JFO) cavitation by the Elrod–Adams film-fraction formulation,
// solved by the projected Gauss–Seidel algorithm of Ausas, Ragot, Leiva, Jai, Bayada & Buscaglia
// (J. Tribol. 129 (2007) 828; transient: J. Tribol. 131 (2009) 031702).
//
// Unknowns per Film node: pressure p ≥ p_cav and film fraction φ ∈ [0, 1] (oil volume fraction
// of the gap) with the complementarity (p − p_cav)(1 − φ) = 0: full film (φ = 1, p ≥ p_cav) or
// cavitated (p = p_cav, φ < 1). Mass balance of each control volume (constant ρ, η):
//
//   Σ_f c_f (p_k − p_nb) + Σ_f (U_n/2) h_f L_f φ_up(f) + V_k (φ_k h_k − φ_k⁰ h_k⁰)/Δt = 0,
//
// c_f, h_f, L_f as in ReynoldsSystem, the Couette flux carried by the UPWIND node's film
// fraction (Elrod–Adams transport; first order in φ, but identical to the Reynolds scheme in
// full film), backward Euler in time (Δt = 0: steady). Boundary (Fixed) nodes are flooded
// (φ = 1) unless given a smaller inlet fraction: a partially flooded (starved) inlet carrying
// the oil film h_oil = φ_in h upstream. Void nodes carry no film.
// Nodal update (exact solution of one node's complementarity problem, neighbours frozen):
//   φ* = (S + Σ_in q θ_nb − D p_cav + storage) / B;  φ* ≥ 1 → full film, p from the balance
//   (over-relaxed by ω); φ* < 1 → p = p_cav, φ = max(φ*, 0).
// Convergence criterion: max over Film nodes of the mass residual, scaled to pascals on full-film
// nodes (|F_k|/D_k relative to max|p − p_amb|) and to film fraction on cavitated nodes
// (|F_k|/B_k), ≤ tolerance; non-convergence or divergence throws.
//
// JfoMethod::ActiveSet solves the same discrete problem by a semismooth Newton (primal–dual
// active set) iteration: for a partition of the Film nodes into full film (unknown p, φ = 1) and
// cavitated (unknown φ, p = p_cav) the balances are one linear system — the Reynolds operator on
// the full-film nodes, the upwind film-fraction transport on the cavitated ones — solved by
// sparse LU (SuiteSparse KLU, its ordering kept between solves); nodes with p < p_cav become
// cavitated, nodes with φ > 1 full film, until the partition repeats (then the balances hold to round-off and the complementarity exactly). A
// cold start begins from the Reynolds-condition solution (multigrid), whose cavitated set a
// flooded film shares but for the reformation fronts: one factorization on the flooded cases
// measured; a warm start (time stepping) takes the previous partition, typically two or three.
// The same criterion decides acceptance; should the partition not settle within
// maxActiveSetIterations, Gauss–Seidel sweeps continue from the last iterate. See
// docs/lube.md §3b for measured speed (10–200× on long films and starved inlets, 1.5–3× on
// 2-D films, where the sparse LU dominates).
//
// JfoMethod::Multigrid solves it on the Reynolds multigrid: every full-film balance is the
// Reynolds-condition balance (φ = 1 throughout) plus the Couette inflow an upstream partial film
// does not bring and the content term, i.e. a squeeze-rate correction; and a node the Reynolds
// complementarity problem leaves at the bound has F(φ = 1) ≥ 0, i.e. φ* ≤ 1, the JFO rule. So
// passes of [the Reynolds problem with that corrected squeeze rate (multigrid, warm-started);
// one Gauss–Seidel pass of the nodal update along the Couette flow, which transports φ through
// the cavities and moves the fronts] have the JFO solution as their fixed point. The pass stops
// at the same criterion; should the residual not halve over three passes (a steady starved
// film's meniscus alternates between two nodes) or the passes run out, the active set finishes.
// From a warm start whose full film is a small pad (a starved film; with its rim of two nodes at
// most a quarter of the Film nodes) the active set on the pad and its rim, the nodes outside held,
// alternates with the nodal update along the flow of the nodes outside it, the pad taken anew
// each round, before the passes (docs/lube.md §3b).
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "lube/FilmGrid.hpp"
#include "lube/FilmState.hpp"
#include "lube/Lubricant.hpp"
#include "lube/SolverControl.hpp"

namespace flexehd::lube {

class SparseLuFactor;
class ReynoldsSolver;
struct JfoTopology;
struct JfoNetworkStorage;

/// How the discrete JFO problem is solved (the same problem and convergence criterion).
enum class JfoMethod {
    GaussSeidel,  ///< projected Gauss–Seidel of Ausas et al. (PSOR cost: sweeps grow with the grid)
    ActiveSet,    ///< semismooth Newton on the full-film/cavitated partition, sparse LU per step
    /// the Reynolds-condition problem on the multigrid with the film fraction's effect as a
    /// squeeze-rate correction, and the film fraction transported through the cavities, to their
    /// fixed point; the active set where that does not converge in maxMultigridPasses
    Multigrid
};

struct JfoOptions {
    double cavitationPressure = 0.0;  ///< p_cav (Pa), same datum as the grid pressures
    SolverControl control;            ///< tolerance on the scaled mass residual
    double omega = 0.0;               ///< over-relaxation of full-film updates; 0 = automatic
    JfoMethod method = JfoMethod::GaussSeidel;
    /// ActiveSet: partition updates (= LU factorizations) before falling back to Gauss–Seidel
    /// sweeps from the last iterate.
    int maxActiveSetIterations = 60;
    /// Multigrid: fixed-point passes (one multigrid solve each) before the active set takes over.
    int maxMultigridPasses = 40;
};

/// Film state carried between time steps.
struct JfoState {
    Eigen::VectorXd h;         ///< film thickness at the nodes (m)
    Eigen::VectorXd fraction;  ///< film fraction φ (1 on full-film nodes)
};

struct JfoResult {
    Eigen::VectorXd pressure;  ///< Pa
    Eigen::VectorXd fraction;  ///< φ per node (Void nodes 0, Fixed nodes their inlet fraction)
    int iterations = 0;        ///< Gauss–Seidel sweeps (Multigrid: fixed-point passes)
    double residual = 0.0;
    int factorizations = 0;    ///< ActiveSet: partition updates, one sparse LU each
    /// Multigrid: solved by the full-film pad stage (iterations then counts its rounds), and the
    /// nodes of the pad and its rim in its last round (0: no full film, the film fraction's
    /// transport alone solved it).
    bool padStage = false;
    int padNodes = 0;
    /// The net flow (m³/s) from each Fixed or Void node into the Film nodes (0 on Film nodes), as
    /// JfoSolver::boundaryFlows gives it.
    Eigen::VectorXd boundaryFlow;
};

class JfoSolver {
public:
    /// Constant-property lubricant only (throws otherwise): JFO with ρ(p), η(p) is not built.
    JfoSolver(FilmGrid grid, Lubricant lubricant, JfoOptions options = {});
    ~JfoSolver();
    JfoSolver(JfoSolver&&) noexcept;

    /// Film fraction φ_in ∈ [0, 1] carried by the Couette flow leaving a Fixed node (starved
    /// inlet; 0: a dry surface). Default 1 (flooded).
    void setInletFraction(int node, double fraction);

    /// Steady solve (dt = 0), or one backward-Euler step of length dt from `previous`.
    /// warmStart: a previous result on the same grid (or nullptr).
    JfoResult solve(const FilmState& film, double dt = 0.0, const JfoState* previous = nullptr,
                    const JfoResult* warmStart = nullptr) const;

    /// Oil volume in the film, Σ V_k φ_k h_k over Film nodes (m³).
    double oilVolume(const FilmState& film, const Eigen::VectorXd& fraction) const;
    /// Net volumetric flow (m³/s) from the Fixed nodes into the Film nodes (the boundary inflow),
    /// with the scheme's own face fluxes.
    double boundaryInflow(const FilmState& film, const JfoResult& result) const;
    /// The same flow per boundary node: the net flow (m³/s) from each Fixed or Void node into the
    /// Film nodes next to it (0 on Film nodes); its sum is boundaryInflow.
    Eigen::VectorXd boundaryFlows(const FilmState& film, const JfoResult& result) const;

    const FilmGrid& grid() const { return grid_; }
    const Lubricant& lubricant() const { return lubricant_; }
    const JfoOptions& options() const { return options_; }
    /// The inlet fraction of every node (used where the node is Fixed).
    const std::vector<double>& inletFractions() const { return inlet_; }
    /// The faces of the discrete problem (lube/JfoNetwork.hpp).
    const JfoTopology& topology() const { return *topology_; }

private:
    FilmGrid grid_;
    Lubricant lubricant_;
    JfoOptions options_;
    std::vector<double> inlet_;  // film fraction of each node when Fixed
    // ActiveSet: the sparse LU with its ordering kept between solves (one pattern per grid);
    // solve() is therefore not safe to call from two threads on one solver.
    std::unique_ptr<SparseLuFactor> lu_;
    mutable std::unique_ptr<ReynoldsSolver> multigrid_;  // Multigrid: built on the first solve
    mutable std::unique_ptr<SparseLuFactor> padLu_;     // Multigrid: the full-film pad's LU
    mutable std::vector<int> padRank_;  // Multigrid: each node's rank in the pad's elimination order
    std::unique_ptr<JfoTopology> topology_;              // the faces touching Film nodes, once
    // the per-solve arrays of the discrete problem, their memory reused (not thread-safe, as lu_)
    std::unique_ptr<JfoNetworkStorage> netStorage_;
};

}  // namespace flexehd::lube
