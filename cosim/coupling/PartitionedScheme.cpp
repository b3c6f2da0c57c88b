#include "cosim/coupling/PartitionedScheme.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <array>

#include "cosim/coupling/StepSolver.hpp"
#include "fem/Stopwatch.hpp"

namespace flexehd::cosim {

PartitionedScheme::PartitionedScheme(StepSolver& step)
    : step_(step), flexible_(step.mp_ + step.ml_ > 0),
      keepJacobian_(step.case_.coupling.keepJacobian),
      accelerator_(makeCouplingAccelerator(step.case_.coupling.acceleration)) {}

void PartitionedScheme::contactsChanged() {
    if (!flexible_) return;
    const EngineCase& c = step_.case_;
    const auto& contacts = step_.contacts_;
    // A unit of e or β moves the film by up to 1 or the skirt reach; a modal coordinate by the
    // largest film change of a unit of it over the contacts.
    const double reach = std::max(c.piston.skirtTop, -c.piston.skirtBottom);
    const int m = step_.mp_ + step_.ml_;
    partitionedScale_.resize(2 + m);
    partitionedScale_.head<2>() << 1.0, reach;
    partitionedScale_.tail(m).setZero();
    for (const auto& contact : contacts)
        if (const Eigen::VectorXd s = contact->modalFilmChangeScale(); s.size() == m)  // empty: no modal action
            partitionedScale_.tail(m) = partitionedScale_.tail(m).cwiseMax(s);
    for (Eigen::Index j = 0; j < partitionedScale_.size(); ++j)
        partitionedScale_[j] = (partitionedScale_[j] > 0.0 ? partitionedScale_[j] : 1.0) / c.piston.clearance;
}

void PartitionedScheme::beginStep(const Eigen::Vector2d& x, const Eigen::VectorXd& /*y*/) {
    accelerator_->reset();  // a new history every step
    lastX_ = x;
    lastR_ = Eigen::Vector2d::Zero();
}

CouplingScheme::PassOutcome PartitionedScheme::pass(const StepContext& ctx, const StepTolerances& tol, int pass,
                                                    const StepEvaluation& ev, const CouplingResidual& /*couplingRes*/,
                                                    Eigen::Vector2d& x, Eigen::VectorXd& y, int& iterations,
                                                    Eigen::Vector2d& dx, bool& resolved, std::string& why) {
    resolved = false;
    const double measure = tol.motionMeasure(ev);
    const double rate = ctx.step.a0 / ctx.step.dt;
    bool fresh = false;
    if (pass == 0) {
        // With rigid bodies the last step's Jacobian is kept while the step size and the BDF2
        // rate are the same (its inertia and squeeze-damping parts depend on them); flexible
        // bodies form it at every step's first pass.
        fresh = flexible_ || !keepJacobian_ || !kept_ || ctx.step.dt != keptDt_ || rate != keptRate_;
    } else if (!jacobianFresh_ && measure > 0.5 * lastMeasure_) {
        fresh = true;  // the kept Jacobian did not halve the residual: a new one at this iterate
    }
    if (fresh) {
        if (!motionJacobian(ctx, tol, x, y, ev, iterations)) {
            kept_ = false;
            why = "a film solve of the finite-difference Jacobian failed";
            return PassOutcome::Failed;
        }
        jacobianFresh_ = true;
    } else if (pass == 0) {
        jacobianFresh_ = false;
    } else if (!flexible_) {
        // Broyden update of the rigid motion's Jacobian. With flexible bodies the Jacobian is
        // held through the step (a chord iteration): the joint quasi-Newton update below
        // models the fixed-point map from its past passes, which must be one and the same map.
        const Eigen::Vector2d ddx = x - lastX_, dr = ev.residual - lastR_;
        const double d2 = ddx.cwiseQuotient(tol.motion).squaredNorm();
        if (d2 > 0.0) {
            const Eigen::Vector2d w = ddx.cwiseQuotient(tol.motion).cwiseQuotient(tol.motion);
            jacobian_ += (dr - jacobian_ * ddx) * w.transpose() / d2;  // Broyden, scaled
        }
    }
    lastMeasure_ = measure;
    kept_ = true;
    keptDt_ = ctx.step.dt;
    keptRate_ = rate;
    dx = -jacobian_.partialPivLu().solve(ev.residual);
    return PassOutcome::Update;
}

void PartitionedScheme::update(const StepEvaluation& ev, const Eigen::Vector2d& dx, Eigen::Vector2d& x,
                               Eigen::VectorXd& y) {
    lastX_ = x;
    lastR_ = ev.residual;
    if (flexible_)
        partitionedUpdate(ev, dx, x, y);
    else
        x += dx;
}

bool PartitionedScheme::motionJacobian(const StepContext& ctx, const StepTolerances& tol, const Eigen::Vector2d& x,
                                       const Eigen::VectorXd& y, const StepEvaluation& ev, int& iterations) {
    // Finite differences of the motion residual (modal coordinates frozen).
    const Eigen::Vector2d delta = 1e-5 * tol.motion;
    std::array<StepEvaluation, 2> moved;
    if (!step_.perturbedMotion(ctx, x, y, delta, false, moved, iterations)) return false;
    for (int i = 0; i < 2; ++i) jacobian_.col(i) = (moved[i].residual - ev.residual) / delta[i];
    ++step_.work_.jacobians;
    return true;
}

void PartitionedScheme::partitionedUpdate(const StepEvaluation& ev, const Eigen::Vector2d& dx, Eigen::Vector2d& x,
                                          Eigen::VectorXd& y) {
    // One fixed-point map of the joint unknowns z = (e, β, y): the chord step of the motion
    // with y held and the modal response H with x held, accelerated together by IQN-ILS /
    // Aitken in units of clearances of film change (docs/coupling.md §1: accelerating y
    // alone leaves the motion lagging the modes, which diverges from 3000 rpm on).
    const fem::Stopwatch t0;
    const Eigen::Index m = step_.mp_ + step_.ml_;
    Eigen::VectorXd z(2 + m), Gz(2 + m);
    z << x, y;
    Gz << x + dx, ev.Hy;
    const Eigen::VectorXd zn = accelerator_->next(z.cwiseProduct(partitionedScale_), Gz.cwiseProduct(partitionedScale_))
                                   .cwiseQuotient(partitionedScale_);
    x = zn.head<2>();
    y = zn.tail(m);
    step_.work_.modal += t0.seconds();
}

}  // namespace flexehd::cosim
