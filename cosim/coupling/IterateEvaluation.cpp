// StepSolver::evaluate: one iterate (e, β, y) of a step as stages (docs/coupling.md §1) —
// every film contact's film and action (FilmContact::evaluate), the equations of motion's
// residual, and the bodies' response to the contacts' modal loads.
#include <cmath>

#include "cosim/coupling/StepSolver.hpp"
#include "fem/Stopwatch.hpp"

namespace flexehd::cosim {

StepEvaluation StepSolver::evaluate(const StepContext& ctx, const Eigen::Vector2d& x,
                                                        const Eigen::VectorXd& y, bool structure) {
    StepEvaluation ev;
    ev.films.resize(contacts_.size());
    for (std::size_t c = 0; c < contacts_.size(); ++c) {
        contacts_[c]->evaluate(ctx.step, ctx.now->films[c], ctx.before->films[c], x, y, ev.films[c], work_);
        const FilmAction& a = ev.films[c].action;
        if (c == 0) {
            ev.action = a;
        } else {
            ev.action.fx += a.fx;
            ev.action.fz += a.fz;
            ev.action.my += a.my;
        }
    }
    motionResidual(ctx, x, ev);
    if (structure && mp_ + ml_ > 0) structureResponse(ctx, ev);
    return ev;
}

void StepSolver::motionResidual(const StepContext& ctx, const Eigen::Vector2d& x, StepEvaluation& ev) const {
    const StepState& n = *ctx.now;
    const StepState& b = *ctx.before;
    const ContactStep& st = ctx.step;
    ev.vel = (st.a0 * x + st.a1 * n.x + st.a2 * b.x) / st.dt;
    ev.acc = (st.a0 * ev.vel + st.a1 * n.v + st.a2 * b.v) / st.dt;
    const Eigen::Vector2d Ma = dyn_.mass(ctx.crank) * ev.acc;
    ev.residual = Ma - dyn_.force(ctx.crank, ctx.gas, ev.action);
    // Scale of each equation: the sum of its terms' magnitudes (rod, film, gas, inertia).
    const double A = std::abs(ctx.crank.acceleration) + 9.81;
    const double mTot = case_.piston.mass + case_.piston.pinMass;
    ev.scale[0] = std::abs(Ma[0]) + std::abs(ev.action.fx) +
                  std::abs(ctx.crank.tanRod) * (mTot * A + std::abs(ctx.gas) + std::abs(ev.action.fz));
    ev.scale[1] = std::abs(Ma[1]) + std::abs(ev.action.my) + std::abs(case_.engine.pinOffset * ctx.gas) +
                  case_.piston.mass * std::abs(case_.piston.cgX) * A;
}

void StepSolver::structureResponse(const StepContext& ctx, StepEvaluation& ev) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(mp_ + ml_), q;
    for (std::size_t c = 0; c < contacts_.size(); ++c) contacts_[c]->addModalLoad(ctx.step, ev.films[c], f, work_);
    if (pistonLoads_)  // the crown's gas pressure, the rigid motion's inertia at this iterate, the ring pack's
        pistonLoads_->add(ctx.step.cylinderPressure, ev.acc, ctx.crank.acceleration + dyn_.gravity(), ctx.step.ringGas,
                          f.head(mp_));
    const fem::Stopwatch t0;
    ev.Hy.resize(mp_ + ml_);
    if (pistonBody_) {  // modal update: q = C f, or the BDF2 step of the modal dynamics
        if (pistonDynamics_)
            pistonDynamics_->respond(f.head(mp_), q);
        else
            pistonBody_->quasiStatic(f.head(mp_), q);
        ev.Hy.head(mp_) = q;
    }
    if (linerBody_) {
        if (linerDynamics_)
            linerDynamics_->respond(f.tail(ml_), q);
        else
            linerBody_->quasiStatic(f.tail(ml_), q);
        ev.Hy.tail(ml_) = q;
    }
    ev.modalForce = f;  // the dynamic response's next step and the liner's acoustic record start from it
    work_.modal += t0.seconds();
}

}  // namespace flexehd::cosim
