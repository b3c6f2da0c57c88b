#pragma once
// CoupledNewtonScheme: the coupled Newton method of a step (coupling.method newton with flexible
// bodies; docs/coupling.md §1, §3): Newton on (e, β, y) with the coupled Jacobian of the motion
// residual and y − H(y), a line search on the merit ½‖F / tolerance‖², the Jacobian kept and
// Broyden-updated within the step, re-formed from its parts for a new step size, and a
// Levenberg–Marquardt step where it is nearly singular.
//
// Translation units: CoupledNewtonScheme.cpp (the pass), CoupledNewton.cpp (the Jacobian).

#include "cosim/coupling/CouplingScheme.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace flexehd::cosim {

class StepSolver;

class CoupledNewtonScheme final : public CouplingScheme {
public:
    /// For the step solver's case, contacts and bodies (kept by reference).
    explicit CoupledNewtonScheme(StepSolver& step);

    CouplingNeeds needs() const override { return CouplingNeeds{true}; }
    void beginStep(const Eigen::Vector2d& x, const Eigen::VectorXd& y) override;
    /// J⁻¹ (0, dH) with the kept inverse Jacobian (the residual's modal rows are y − H(y)).
    Eigen::VectorXd givenLoadChange(const Eigen::VectorXd& dH) const override;
    PassOutcome pass(const StepContext& ctx, const StepTolerances& tol, int pass, const StepEvaluation& ev,
                     const CouplingResidual& couplingRes, Eigen::Vector2d& x, Eigen::VectorXd& y, int& iterations,
                     Eigen::Vector2d& dx, bool& resolved, std::string& why) override;
    void update(const StepEvaluation& ev, const Eigen::Vector2d& dx, Eigen::Vector2d& x, Eigen::VectorXd& y) override;

private:
    // The modal columns of the Jacobian at one linearisation, affine in the rate r = a0/Δt
    // (CoupledNewton.cpp): motion rows motionH + r motionRate, modal rows
    // I − response(modalH + r modalRate) per body; the rate parts are empty without
    // coupling.elastic_squeeze.
    struct CoupledJacobianParts {
        bool valid = false;
        Eigen::MatrixXd motionH, motionRate;    // 2 × modes
        Eigen::MatrixXd modalH, modalRate;      // modes × modes: the contacts' modal loads (piston rows, liner rows)
        Eigen::VectorXd filmChangePerUnknown;   // 2 + modes: the contacts' largest film change per unit
        // The (e, β) columns' film part where every contact gives it (ContactJacobian::motionColumns):
        // the motion rows' (2 × 2, through the action) and the modal load's (modes × 2); else the
        // columns are formed by differences.
        bool motionColumns = false;
        Eigen::MatrixXd motionX, modalX;
    };

    // The last accepted iterate of the step (its measure, merit, unknowns and residual) and the
    // line search's state.
    struct NewtonIterate {
        double acceptedMeasure = std::numeric_limits<double>::infinity();
        Eigen::Vector2d acceptedX = Eigen::Vector2d::Zero();
        Eigen::VectorXd acceptedY, acceptedF;
        /// The merits of the last accepted iterates, newest first (the line search's reference).
        std::array<double, 3> recentMerits{};
        int accepted = 0;
        /// The largest merit of the last (up to three) accepted iterates.
        double meritReference() const {
            return *std::max_element(recentMerits.begin(), recentMerits.begin() + std::min<int>(accepted, 3));
        }
        int backtracks = 0;
        bool freshJacobian = false, regularize = false, revisit = false;
        bool stalled = false;  ///< the last pass did not halve the measure (and was Broyden-updated)
        /// The (e, β) columns' difference steps in units of (c_r, c_r/reach): 1e-5, finer after a
        /// fresh Jacobian's update had to backtrack.
        double differenceStep = 1e-5;
    };

    /// The line search, the Jacobian kept, re-formed or Broyden-updated, and the damped update dz
    /// of (e, β, y); Retry: x, y were moved back (evaluate again).
    PassOutcome coupledNewtonPass(const StepContext& ctx, const StepTolerances& tol, const StepEvaluation& ev,
                                  const CouplingResidual& couplingRes, NewtonIterate& it, Eigen::Vector2d& x,
                                  Eigen::VectorXd& y, int& iterations, Eigen::VectorXd& dz, bool& resolved,
                                  std::string& why);
    /// The iteration has converged to the resolution of its unknowns.
    bool resolvedToTheUnknownsResolution(const StepTolerances& tol, const StepEvaluation& ev,
                                         const CouplingResidual& couplingRes, const Eigen::VectorXd& dz) const;
    // The coupled Jacobian (CoupledNewton.cpp).
    /// Linearises (motion residual, y − H(y)) in (e, β, y) at the evaluation into the parts of
    /// CoupledJacobianParts (docs/coupling.md §1, §3)
    void linearizeCoupled(const StepContext& ctx, const Eigen::Vector2d& x, const StepEvaluation& ev);
    /// ∂(equations of motion's right-hand side)/∂(F_x, ·, F_z, ·, M_y, ·): 2 × 6, from the dynamics.
    Eigen::Matrix<double, 2, 6> actionGradient(const StepContext& ctx) const;
    /// The (e, β) columns of J by forward differences of two full evaluations with steps delta (m,
    /// rad); false: a film solve failed.
    bool differenceColumns(const StepContext& ctx, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                           const StepEvaluation& ev, const Eigen::Vector2d& delta, Eigen::MatrixXd& J, int& filmSolves);
    /// Good Broyden update of the kept inverse Jacobian for the update s and the residual change dF.
    void broydenUpdate(const Eigen::VectorXd& s, const Eigen::VectorXd& dF);
    /// Forms the coupled Jacobian at the context's step size (its (e, β) columns by differences of
    /// two full evaluations with steps delta, counted in filmSolves) and its inverse; false if a
    /// film solve failed.
    bool formCoupledJacobian(const StepContext& ctx, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                             const StepEvaluation& ev, const Eigen::Vector2d& delta, int& filmSolves);
    /// The tolerance of each residual row: motion rows 1e-4 (scale + force floor), modal rows the
    /// coupling tolerance over the largest film change of a unit of the mode.
    Eigen::VectorXd residualScale(const StepEvaluation& ev, double forceFloor, double reach, double couplingTol) const;
    /// The line search's merit ½‖F / residualScale‖² (∞ before the first Jacobian).
    static double coupledMerit(const Eigen::VectorXd& F, const Eigen::VectorXd& residualScale);
    /// −D (JsᵀJs + I)⁻¹ Jsᵀ Fs, residual in tolerance units, unknowns in clearances of film change.
    Eigen::VectorXd levenbergMarquardtStep(const Eigen::VectorXd& F, const Eigen::VectorXd& residualScale) const;
    /// The Jacobian at the context's step size from the last linearisation's parts.
    Eigen::MatrixXd coupledJacobian(const StepContext& ctx);

    StepSolver& step_;
    const int mp_, ml_;  // modal coordinates of piston and liner
    CoupledJacobianParts parts_;     // the last linearisation
    NewtonIterate iterate_;          // the step's last accepted iterate
    Eigen::VectorXd dz_;             // the last pass's update of (e, β, y)
    Eigen::MatrixXd newtonJacobian_; // the coupled Jacobian as formed (before Broyden updates)
    Eigen::MatrixXd newtonInverse_;  // inverse of the coupled Jacobian (Broyden-updated within a step)
    Eigen::VectorXd unknownScale_;   // m of film-thickness change per unit of each unknown
    double newtonRate_ = -1.0;       // the a0/Δt it was formed for
};

}  // namespace flexehd::cosim
