#pragma once
// JfoLinearization: the derivative of the mass-conserving film's pressure with respect to the
// film thickness h at a JFO solution (lube::JfoSolver), its partition held — full-film nodes
// (unknown p, φ = 1) and cavitated ones (unknown φ, p = p_cav): the generalized Jacobian a
// semismooth Newton method on a coupled problem needs (docs/coupling.md §6). The partition's
// balances F(y, h) = M(h) y − r(h) = 0 (docs/lube.md §3b) give
//
//   M δy = −(∂F/∂h) δh,   δp = δy on the full-film nodes, 0 on the cavitated and non-Film ones,
//
// so the change of the film fraction in a cavity carries the change of the Couette inflow it
// brings to the film downstream. ∂F/∂h at fixed (p, φ) — Poiseuille h_f³, Couette h_f and the
// content V φ h/Δt — is taken by finite differences on a distance-2 colouring of the grid
// (ColouredDifference: one network per colour); M is factorized once per linearisation (sparse
// LU, its ordering kept), over the rows δp depends on only: the full-film nodes and, transitively,
// the full-film and upstream cavitated neighbours their rows reach (no other unknown enters these
// rows; on a starved film the cavities downstream are most of the grid). Held: the previous step's content, and at each inlet (a Fixed node's
// Couette inflow) its film fraction or, where that is below 1, optionally its flux φ_in h_f — an
// inlet fed with a given oil volume per step, whose fraction falls as the gap opens.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "lube/FilmState.hpp"
#include "lube/GridColouring.hpp"
#include "lube/JfoSolver.hpp"
#include "lube/NodeColumns.hpp"

namespace flexehd::lube {

class SparseLuFactor;
class JfoNetwork;

/// What an inlet holds as the thickness changes.
enum class InletResponse {
    FractionHeld,          ///< its film fraction φ_in (a flooded or fixed-fraction inlet)
    FluxHeldWherePartial,  ///< where φ_in < 1 its Couette inflow φ_in h_f: a given oil supply
};

class JfoLinearization {
public:
    /// For the solver's grid, lubricant, cavitation pressure and inlet fractions (the solver is
    /// kept by reference and must outlive this).
    explicit JfoLinearization(const JfoSolver& solver, InletResponse inlets = InletResponse::FractionHeld);
    ~JfoLinearization();
    JfoLinearization(JfoLinearization&&) noexcept;

    /// Linearises at the solution of the solve (film, dt, previous) — the arguments that solve
    /// took, with the inlet fractions it had. Throws std::invalid_argument on sizes that do not
    /// fit the grid, std::runtime_error when the partition's system is singular.
    void linearize(const FilmState& film, double dt, const JfoState* previous, const JfoResult& solution);

    /// δp (N × k, Pa) for k columns of thickness changes δh (m, N × k).
    Eigen::MatrixXd pressureChange(const Eigen::Ref<const Eigen::MatrixXd>& dh) const;
    /// pressureChange on the full-film nodes, the only ones where it is not zero.
    NodeColumns pressureChangeOnNodes(const Eigen::Ref<const Eigen::MatrixXd>& dh) const;

    /// Film nodes cavitated (φ < 1) in the last linearisation.
    int cavitatedNodes() const { return cavitated_; }
    /// Rows of the last linearisation's system: the Film nodes the full film's δp depends on.
    int systemRows() const { return static_cast<int>(sys_.size()); }

private:
    const JfoSolver* solver_;
    InletResponse inlets_;
    GridColouring colouring_;
    std::unique_ptr<SparseLuFactor> lu_;
    /// Per grid node: cavitated in the solution's partition (counted in cavitated_).
    std::vector<char> partition(const JfoNetwork& net, const FilmGrid& g, const double* p, const double* phi);
    /// The rows δp depends on: the full-film nodes and the rows their system's entries reach.
    std::vector<int> dependentRows(const JfoNetwork& net, const FilmGrid& g, const std::vector<char>& cavitated) const;
    /// Keeps ∂F/∂h on the grid nodes it reaches (its non-zero columns).
    void keepReachedColumns(const Eigen::SparseMatrix<double>& dFdh);

    std::vector<int> rows_;        // the Film nodes
    std::vector<int> sys_;         // the rows of the linearisation's system, in order
    std::vector<char> sysCav_;     // per row of it: 1 cavitated
    Eigen::SparseMatrix<double> dFdh_;  // sys_ rows × the grid nodes in dFdhNodes_ (its non-zero columns)
    std::vector<int> dFdhNodes_;
    int cavitated_ = 0;
};

}  // namespace flexehd::lube
