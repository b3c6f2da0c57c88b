#pragma once
// CouplingScheme: how the step's iteration (StepSolver::advance, docs/coupling.md §1) turns an
// evaluated iterate (e, β, y) into the next one — chosen once per run from coupling.method and
// the bodies: CoupledNewtonScheme (coupling.method newton with flexible bodies: Newton on
// (e, β, y) with the coupled Jacobian) or PartitionedScheme (coupling.method partitioned, or
// rigid bodies: Newton on the motion, the modal fixed point accelerated). The step — its context,
// evaluation, convergence test and acceptance — is the solver's; a scheme gives each pass's
// motion update and then moves the iterate.

#include "cosim/contact/CouplingNeeds.hpp"
#include "cosim/coupling/CouplingResidual.hpp"
#include "cosim/coupling/StepState.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <string>

namespace flexehd::cosim {

/// The step's convergence tolerances (StepSolver::stepTolerances).
struct StepTolerances {
    Eigen::Vector2d motion;   ///< (m, rad): the clearance, and the clearance over the reach
    double reach = 0.0;       ///< m, the skirt's largest distance from the pin axis
    double forceFloor = 0.0;  ///< N, the reciprocating inertia force m r ω²
    double coupling = 0.0;    ///< m, coupling.tolerance × clearance

    /// The motion residual of ev in units of its tolerances 1e-4 (S₁ + F_inertia),
    /// 1e-4 (S₂ + F_inertia · reach) (≤ 1: met).
    double motionMeasure(const StepEvaluation& ev) const {
        return std::max(std::abs(ev.residual[0]) / (1e-4 * (ev.scale[0] + forceFloor)),
                        std::abs(ev.residual[1]) / (1e-4 * (ev.scale[1] + forceFloor * reach)));
    }
};

class CouplingScheme {
public:
    /// A pass's outcome: Retry — x, y were moved back (evaluate again); Failed — the reason is in
    /// `why`; Update — the motion's update is in dx.
    enum class PassOutcome { Retry, Failed, Update };

    virtual ~CouplingScheme() = default;

    /// What the scheme asks of the film contacts.
    virtual CouplingNeeds needs() const = 0;
    /// After a contact was added.
    virtual void contactsChanged() {}
    /// A new step from the iterate (x, y).
    virtual void beginStep(const Eigen::Vector2d& x, const Eigen::VectorXd& y) = 0;
    /// The change (δx, δy) of the solution that a change dH of the bodies' response to their
    /// given loads brings, to first order, before any film solve (empty: the scheme cannot say).
    virtual Eigen::VectorXd givenLoadChange(const Eigen::VectorXd& /*dH*/) const { return {}; }
    /// Pass `pass` of the step at the evaluated iterate ev of (x, y) with its coupling residual:
    /// the motion's update dx, and resolved when the iteration has converged to the resolution of
    /// its unknowns. Film solves it makes are counted in `iterations`.
    virtual PassOutcome pass(const StepContext& ctx, const StepTolerances& tol, int pass, const StepEvaluation& ev,
                             const CouplingResidual& couplingRes, Eigen::Vector2d& x, Eigen::VectorXd& y,
                             int& iterations, Eigen::Vector2d& dx, bool& resolved, std::string& why) = 0;
    /// Moves the iterate (x, y) by the last pass's update (dx: its motion part).
    virtual void update(const StepEvaluation& ev, const Eigen::Vector2d& dx, Eigen::Vector2d& x,
                        Eigen::VectorXd& y) = 0;
};

}  // namespace flexehd::cosim
