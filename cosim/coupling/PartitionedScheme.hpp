#pragma once
// PartitionedScheme: the partitioned coupling of a step (coupling.method partitioned, and every
// run with rigid bodies; docs/coupling.md §1, "Otherwise"): Newton on the motion (e, β) with a
// finite-difference Jacobian — with rigid bodies kept from step to step while the step size is the
// same (coupling.keep_jacobian), formed anew where a pass does not halve the residual, and
// Broyden-updated; with flexible ones formed at the step's first pass and held through the step
// (a chord iteration) — and, with flexible bodies, the
// joint fixed-point map of (e, β, y) accelerated by the CouplingAccelerator of
// coupling.acceleration, in units of clearances of film change.

#include "cosim/coupling/CouplingAccelerator.hpp"
#include "cosim/coupling/CouplingScheme.hpp"

#include <memory>

namespace flexehd::cosim {

class StepSolver;

class PartitionedScheme final : public CouplingScheme {
public:
    /// For the step solver's case, contacts and bodies (kept by reference).
    explicit PartitionedScheme(StepSolver& step);

    CouplingNeeds needs() const override { return {}; }
    void contactsChanged() override;
    void beginStep(const Eigen::Vector2d& x, const Eigen::VectorXd& y) override;
    PassOutcome pass(const StepContext& ctx, const StepTolerances& tol, int pass, const StepEvaluation& ev,
                     const CouplingResidual& couplingRes, Eigen::Vector2d& x, Eigen::VectorXd& y, int& iterations,
                     Eigen::Vector2d& dx, bool& resolved, std::string& why) override;
    void update(const StepEvaluation& ev, const Eigen::Vector2d& dx, Eigen::Vector2d& x, Eigen::VectorXd& y) override;

private:
    /// The finite-difference Jacobian of the motion residual (modal coordinates frozen).
    bool motionJacobian(const StepContext& ctx, const StepTolerances& tol, const Eigen::Vector2d& x,
                        const Eigen::VectorXd& y, const StepEvaluation& ev, int& iterations);
    /// The accelerated fixed-point map of (e, β, y).
    void partitionedUpdate(const StepEvaluation& ev, const Eigen::Vector2d& dx, Eigen::Vector2d& x,
                           Eigen::VectorXd& y);

    StepSolver& step_;
    bool flexible_;
    bool keepJacobian_;  // coupling.keep_jacobian (rigid bodies)
    // With flexible bodies: units of (e, β, y) in clearances of film change, for the quasi-Newton
    // acceleration of the joint fixed-point map (docs/coupling.md §1).
    Eigen::VectorXd partitionedScale_;
    std::unique_ptr<CouplingAccelerator> accelerator_;  // coupling.acceleration, reset every step
    Eigen::Matrix2d jacobian_ = Eigen::Matrix2d::Zero();  // the motion's
    // The Jacobian's state: formed at this step's iterate (else kept or Broyden-updated), formed
    // at all (kept_), and the step size and BDF2 rate a0/Δt of the step it was last used in.
    bool jacobianFresh_ = false, kept_ = false;
    double keptDt_ = 0.0, keptRate_ = 0.0;
    double lastMeasure_ = 0.0;  // the last pass's residual in units of its tolerances
    Eigen::Vector2d lastX_ = Eigen::Vector2d::Zero(), lastR_ = Eigen::Vector2d::Zero();  // the last pass's
};

}  // namespace flexehd::cosim
