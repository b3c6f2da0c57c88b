// StepSolver: one time step (docs/coupling.md §1) — the step's context (BDF2
// coefficients, crank state, gas force, liner offset), the predictor, and the Newton/coupling
// iteration — coupled Newton on (e, β, y) with coupling.method newton, else Newton on the motion
// with the partitioned, accelerated modal fixed point — until the motion and the coupling
// residual meet their tolerances.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/LU>
#include <fmt/format.h>

#include "cosim/coupling/StepSolver.hpp"
#include "fem/Stopwatch.hpp"

namespace flexehd::cosim {

StepSolver::StepSolver(const EngineCase& c, const CrankKinematics& kin, const PistonDynamics& dyn,
                       const CylinderPressure& pressure, const std::vector<std::unique_ptr<FilmContact>>& contacts,
                       std::shared_ptr<const FlexibleBody> piston, std::shared_ptr<const FlexibleBody> liner,
                       std::function<double(double)> linerOffset, WorkTally& work)
    : case_(c), kin_(kin), dyn_(dyn), pressure_(pressure), contacts_(contacts), pistonBody_(std::move(piston)),
      linerBody_(std::move(liner)), linerOffset_(std::move(linerOffset)), work_(work),
      mp_(pistonBody_ ? pistonBody_->modes() : 0), ml_(linerBody_ ? linerBody_->modes() : 0) {
    if (c.coupling.response == ElasticResponse::Dynamic) {
        if (pistonBody_)
            pistonDynamics_ = std::make_unique<modal::HeldModalDynamics>(pistonBody_->body(), pistonBody_->heldInterfaces());
        if (linerBody_)
            linerDynamics_ = std::make_unique<modal::HeldModalDynamics>(linerBody_->body(), linerBody_->heldInterfaces());
    }
    if (c.coupling.method == CouplingMethod::Newton && mp_ + ml_ > 0) newtonParts_ = std::make_unique<CoupledJacobianParts>();
    accelerator_ = makeCouplingAccelerator(c.coupling.acceleration);
    contactsChanged();
}

StepSolver::~StepSolver() = default;

void StepSolver::contactsChanged() {
    if (case_.coupling.method != CouplingMethod::Partitioned || mp_ + ml_ == 0) return;
    // A unit of e or β moves the film by up to 1 or the skirt reach; a modal coordinate by the
    // largest film change of a unit of it over the contacts.
    const double reach = std::max(case_.piston.skirtTop, -case_.piston.skirtBottom);
    const int m = mp_ + ml_;
    partitionedScale_.resize(2 + m);
    partitionedScale_.head<2>() << 1.0, reach;
    partitionedScale_.tail(m) = contacts_.front()->modalFilmChangeScale();
    for (std::size_t k = 1; k < contacts_.size(); ++k)
        partitionedScale_.tail(m) = partitionedScale_.tail(m).cwiseMax(contacts_[k]->modalFilmChangeScale());
    for (Eigen::Index j = 0; j < partitionedScale_.size(); ++j)
        partitionedScale_[j] = (partitionedScale_[j] > 0.0 ? partitionedScale_[j] : 1.0) / case_.piston.clearance;
}

StepContext StepSolver::stepContext(const StepState& s, const StepState& prev, double dtDeg) {
    StepContext ctx;
    ContactStep& st = ctx.step;
    ctx.crankDeg = s.crankDeg + dtDeg;
    st.dt = dtDeg * kin_.secondsPerDegree();
    if (s.dt > 0.0) {  // BDF2 with variable step ratio ω
        const double w = st.dt / s.dt;
        st.a0 = (1.0 + 2.0 * w) / (1.0 + w);
        st.a1 = -(1.0 + w);
        st.a2 = w * w / (1.0 + w);
    }
    ctx.crank = kin_.at(ctx.crankDeg);
    st.pistonVelocity = ctx.crank.velocity;
    ctx.gas = dyn_.gasForce(pressure_(crankAngle720(ctx.crankDeg)));
    st.linerOffset = linerOffset_(ctx.crankDeg);
    ctx.now = &s;
    ctx.before = &prev;
    if (pistonDynamics_ || linerDynamics_) {
        // BDF2 histories of the modal coordinates (prev starts as a copy of the initial state;
        // a2 = 0 on the first step).
        ctx.hq = st.a1 * s.y + st.a2 * prev.y;
        ctx.hv = st.a1 * s.w + st.a2 * prev.w;
        if (pistonDynamics_) pistonDynamics_->setStep(st.a0, st.dt);
        if (linerDynamics_) linerDynamics_->setStep(st.a0, st.dt);
    }
    return ctx;
}

StepSolver::StepTolerances StepSolver::stepTolerances() const {
    StepTolerances t;
    // Newton tolerances and finite-difference steps from the clearance c: 1e-5 c on the
    // lateral shift and on the tilt times the skirt reach (not from the local error tolerances,
    // which may be loose when the step size is fixed by time.max_step_deg).
    t.reach = std::max(case_.piston.skirtTop, -case_.piston.skirtBottom);
    t.motion = Eigen::Vector2d(case_.piston.clearance, case_.piston.clearance / t.reach);
    // Force floor of the residual test: the reciprocating inertia force m r ω² of the engine.
    t.forceFloor = (case_.piston.mass + case_.piston.pinMass) * kin_.crankRadius() * kin_.omega() * kin_.omega();
    t.coupling = case_.coupling.tolerance * case_.piston.clearance;
    return t;
}

double StepSolver::couplingResidual(const StepContext& ctx, const StepEvaluation& ev, const Eigen::VectorXd& y) {
    // max |Δh(H(y)) − Δh(y)| over every contact's film.
    const Eigen::VectorXd d = ev.Hy - y;
    double res = 0.0;
    for (const auto& contact : contacts_) res = std::max(res, contact->filmChange(ctx.step, d, work_));
    return res;
}

StepSolver::PassOutcome StepSolver::coupledNewtonPass(const StepContext& ctx, const StepTolerances& tol,
                                                                 const StepEvaluation& ev, double couplingRes,
                                                                 NewtonIterate& it, Eigen::Vector2d& x,
                                                                 Eigen::VectorXd& y, int& iterations,
                                                                 Eigen::VectorXd& dz, bool& resolved,
                                                                 std::string& why) {
    const double forceFloor = tol.forceFloor, reach = tol.reach, couplingTol = tol.coupling;
    // The residual in units of its tolerances (≤ 1: converged).
    const double measure = std::max({couplingRes / couplingTol,
                                     std::abs(ev.residual[0]) / (1e-4 * (ev.scale[0] + forceFloor)),
                                     std::abs(ev.residual[1]) / (1e-4 * (ev.scale[1] + forceFloor * reach))});
    Eigen::VectorXd F(2 + mp_ + ml_);
    F.head<2>() = ev.residual;
    F.tail(mp_ + ml_) = y - ev.Hy;
    // Line search: a pass whose merit (coupledMerit) is worse than at the last accepted
    // iterate goes back there — to linearise anew when the Jacobian was a kept one, else to
    // halve the update (at most 5 times; the film and contact laws are strongly nonlinear
    // where the cavitated or contact set changes).
    Eigen::VectorXd rScale = residualScale(ev, forceFloor, reach, couplingTol);
    if (it.acceptedMerit < std::numeric_limits<double>::infinity() && coupledMerit(F, rScale) > it.acceptedMerit) {
        if (!it.freshJacobian && !it.revisit) {
            // The kept Jacobian led astray: back to the accepted iterate, linearised anew.
            x = it.acceptedX;
            y = it.acceptedY;
            newtonParts_->valid = false;
            it.revisit = true;
            return PassOutcome::Retry;
        }
        if (it.backtracks < 5) {
            ++it.backtracks;
            x = it.acceptedX + 0.5 * (x - it.acceptedX);
            y = it.acceptedY + 0.5 * (y - it.acceptedY);
            return PassOutcome::Retry;
        }
    }
    it.revisit = false;
    const double rate = ctx.step.a0 / ctx.step.dt;
    // A new linearisation when a pass did not halve the measure (or had to backtrack with a
    // kept Jacobian); a step-size change alone re-forms the Jacobian from the kept parts
    // (affine in the rate); otherwise the kept inverse, Broyden-updated within the step.
    if (it.backtracks > 0 && it.freshJacobian) it.regularize = true;  // see below
    const bool relinearize = !newtonParts_->valid || measure > 0.5 * it.acceptedMeasure || it.backtracks > 0;
    if (!newtonParts_->valid) it.acceptedMeasure = std::numeric_limits<double>::infinity();
    if (relinearize) {
        try {
            linearizeCoupled(ctx, x, ev);
        } catch (const std::runtime_error& e) {
            newtonParts_->valid = false;
            why = std::string("the film's linearisation for the coupled Newton step failed: ") + e.what();
            return PassOutcome::Failed;
        }
        ++work_.jacobians;
    }
    if (relinearize || rate != newtonRate_) {
        if (!formCoupledJacobian(ctx, x, y, ev, tol.motion, iterations)) {
            why = "a film solve of the Jacobian's difference columns failed";
            return PassOutcome::Failed;
        }
        newtonRate_ = rate;
    } else if (it.acceptedF.size()) {
        Eigen::VectorXd step(2 + mp_ + ml_);
        step.head<2>() = x - it.acceptedX;
        step.tail(mp_ + ml_) = y - it.acceptedY;
        broydenUpdate(step, F - it.acceptedF);
    }
    it.freshJacobian = relinearize;
    it.backtracks = 0;
    rScale = residualScale(ev, forceFloor, reach, couplingTol);  // the Jacobian's unknown scales
    it.acceptedMeasure = measure;
    it.acceptedMerit = coupledMerit(F, rScale);
    it.acceptedX = x;
    it.acceptedY = y;
    it.acceptedF = F;
    // After a failed line search with a fresh Jacobian the step is nearly singular: some
    // combination of motion and modes changes the residual by less than its tolerance per
    // clearance of film change (a soft elastic mode against a film of nearly equal and
    // opposite stiffness, quasi-static). Then the Levenberg–Marquardt step in units of the
    // tolerances (residual) and of the clearance (film-thickness change of each unknown),
    // dz = −D (JsᵀJs + I)⁻¹ Jsᵀ Fs, leaves such directions alone.
    dz = -newtonInverse_ * F;
    resolved = relinearize && resolvedToTheUnknownsResolution(tol, ev, couplingRes, dz);
    if (it.regularize) dz = levenbergMarquardtStep(F, rScale);
    if (!dz.allFinite()) {
        why = "the Newton update of the coupled step is not finite";
        return PassOutcome::Failed;
    }
    // Damped step: no update moves the film thickness anywhere by more than a quarter of the
    // clearance (the film and contact laws are far from linear over such a distance).
    const double largest = dz.cwiseAbs().dot(unknownScale_);  // ≥ max |Δh|
    if (largest > 0.25 * case_.piston.clearance) dz *= 0.25 * case_.piston.clearance / largest;
    return PassOutcome::Update;
}

bool StepSolver::resolvedToTheUnknownsResolution(const StepTolerances& tol, const StepEvaluation& ev,
                                                       double couplingRes, const Eigen::VectorXd& dz) const {
    // Where the film is thin and the step short, the squeeze film makes the motion so stiff that
    // a change of e, β by 1e-5 c_r (the resolution the motion test asks of them) changes its
    // residual by more than the tolerance; then, with the modal equations met, a fresh
    // Jacobian's full Newton update below that resolution and each motion residual within 10× its
    // tolerance, or within the change a step of e, β by their resolution makes of it (the fresh
    // Jacobian's motion rows), end the iteration (docs/coupling.md §1).
    const Eigen::Vector2d tolerance(1e-4 * (ev.scale[0] + tol.forceFloor),
                                    1e-4 * (ev.scale[1] + tol.forceFloor * tol.reach));
    const Eigen::Vector2d resolution = 1e-5 * tol.motion;
    bool motionResolved = true;
    for (int i = 0; i < 2; ++i) {
        const double resolvable =
            std::abs(newtonJacobian_(i, 0)) * resolution[0] + std::abs(newtonJacobian_(i, 1)) * resolution[1];
        motionResolved = motionResolved && std::abs(ev.residual[i]) <= std::max(10.0 * tolerance[i], resolvable);
    }
    return couplingRes <= tol.coupling && motionResolved &&
           dz.cwiseAbs().dot(unknownScale_) <= 1e-5 * case_.piston.clearance &&
           std::abs(dz[0]) <= resolution[0] && std::abs(dz[1]) <= resolution[1];
}

bool StepSolver::motionJacobian(const StepContext& ctx, const StepTolerances& tol, const Eigen::Vector2d& x,
                                      const Eigen::VectorXd& y, const StepEvaluation& ev, int& iterations) {
    // Finite differences of the motion residual (modal coordinates frozen).
    const Eigen::Vector2d delta = 1e-5 * tol.motion;
    std::array<StepEvaluation, 2> moved;
    if (!perturbedMotion(ctx, x, y, delta, false, moved, iterations)) return false;
    for (int i = 0; i < 2; ++i) jacobian_.col(i) = (moved[i].residual - ev.residual) / delta[i];
    ++work_.jacobians;
    return true;
}

bool StepSolver::perturbedMotion(const StepContext& ctx, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                                 const Eigen::Vector2d& delta, bool structure, std::array<StepEvaluation, 2>& moved,
                                 int& solves) {
    for (int i = 0; i < 2; ++i) {
        Eigen::Vector2d xp = x;
        xp[i] += delta[i];
        try {
            moved[i] = evaluate(ctx, xp, y, structure);
        } catch (const std::runtime_error&) {
            return false;
        }
        ++solves;
    }
    return true;
}

void StepSolver::partitionedUpdate(const StepEvaluation& ev, const Eigen::Vector2d& dx, Eigen::Vector2d& x,
                                   Eigen::VectorXd& y) {
    // One fixed-point map of the joint unknowns z = (e, β, y): the chord step of the motion
    // with y held and the modal response H with x held, accelerated together by IQN-ILS /
    // Aitken in units of clearances of film change (docs/coupling.md §1: accelerating y
    // alone leaves the motion lagging the modes, which diverges from 3000 rpm on).
    const fem::Stopwatch t0;
    const Eigen::Index m = mp_ + ml_;
    Eigen::VectorXd z(2 + m), Gz(2 + m);
    z << x, y;
    Gz << x + dx, ev.Hy;
    const Eigen::VectorXd zn =
        accelerator_->next(z.cwiseProduct(partitionedScale_), Gz.cwiseProduct(partitionedScale_)).cwiseQuotient(partitionedScale_);
    x = zn.head<2>();
    y = zn.tail(m);
    work_.modal += t0.seconds();
}

void StepSolver::acceptStep(const StepContext& ctx, const StepState& s, const Eigen::Vector2d& x,
                                  const Eigen::VectorXd& y, const StepEvaluation& ev, StepState& out) const {
    out.crankDeg = ctx.crankDeg;
    out.time = s.time + ctx.step.dt;
    out.dt = ctx.step.dt;
    out.x = x;
    out.v = ev.vel;
    out.a = ev.acc;
    out.y = y;
    if (pistonDynamics_ || linerDynamics_) out.w = (ctx.step.a0 * y + ctx.hq) / ctx.step.dt;  // ẏ of BDF2
    out.films.clear();
    for (std::size_t c = 0; c < contacts_.size(); ++c) out.films.push_back(contacts_[c]->accepted(ctx.step, s.films[c], ev.films[c]));
}

bool StepSolver::advance(const StepState& s, const StepState& prev, double dtDeg, StepState& out, StepEvaluation& ev, int& iterations,
                               std::string& failure) {
    const StepContext ctx = stepContext(s, prev, dtDeg);
    const double dt = ctx.step.dt;
    Eigen::Vector2d x = s.x + dt * s.v + 0.5 * dt * dt * s.a;  // predictor
    // The modal coordinates start from their linear extrapolation over the last step (at high
    // speed y moves by hundreds of coupling tolerances per step; from y_n the first Newton passes
    // go through the strongly nonlinear film law).
    Eigen::VectorXd y = s.y;
    if (s.dt > 0.0 && prev.y.size() == s.y.size()) y += (ctx.step.dt / s.dt) * (s.y - prev.y);
    const bool flexible = mp_ + ml_ > 0;
    accelerator_->reset();  // a new history every step
    const StepTolerances tol = stepTolerances();
    const int maxIt = case_.coupling.maxIterations;
    Eigen::Vector2d lastX = x, lastR = Eigen::Vector2d::Zero();
    iterations = 0;
    failure.clear();
    // Why the iteration failed, for the diagnosis when the step size runs out.
    auto fail = [&](const std::string& why) {
        failure = fmt::format("{} (after {} film solves in this attempt)", why, iterations);
        return false;
    };
    NewtonIterate newton;  // coupling.method newton: the last accepted iterate
    newton.acceptedX = x;
    newton.acceptedY = y;
    for (int it = 0; it < maxIt; ++it) {
        try {
            ev = evaluate(ctx, x, y, true);
        } catch (const std::runtime_error&) {
            return fail("a film solve failed");  // the caller shortens the step
        }
        ++iterations;
        const double couplingRes = flexible ? couplingResidual(ctx, ev, y) : 0.0;
        Eigen::VectorXd dz;     // coupling.method newton: the update of (e, β, y)
        bool resolved = false;  // coupling.method newton: converged to the unknowns' resolution
        if (newtonParts_) {
            std::string why;
            const PassOutcome pass =
                coupledNewtonPass(ctx, tol, ev, couplingRes, newton, x, y, iterations, dz, resolved, why);
            if (pass == PassOutcome::Retry) continue;
            if (pass == PassOutcome::Failed) return fail(why);
        } else if (it == 0) {
            if (!motionJacobian(ctx, tol, x, y, ev, iterations))
                return fail("a film solve of the finite-difference Jacobian failed");
        } else if (!flexible) {
            // Broyden update of the rigid motion's Jacobian. With flexible bodies the Jacobian is
            // held through the step (a chord iteration): the joint quasi-Newton update below
            // models the fixed-point map from its past passes, which must be one and the same map.
            const Eigen::Vector2d dx = x - lastX, dr = ev.residual - lastR;
            const double d2 = dx.cwiseQuotient(tol.motion).squaredNorm();
            if (d2 > 0.0) {
                const Eigen::Vector2d w = dx.cwiseQuotient(tol.motion).cwiseQuotient(tol.motion);
                jacobian_ += (dr - jacobian_ * dx) * w.transpose() / d2;  // Broyden, scaled
            }
        }
        const Eigen::Vector2d dx = dz.size() ? Eigen::Vector2d(dz.head<2>()) : Eigen::Vector2d(-jacobian_.partialPivLu().solve(ev.residual));
        if (!dx.allFinite()) return fail("the Newton update is not finite");
        const bool motionDone = std::abs(dx[0]) <= 1e-5 * tol.motion[0] && std::abs(dx[1]) <= 1e-5 * tol.motion[1] &&
                                std::abs(ev.residual[0]) <= 1e-4 * (ev.scale[0] + tol.forceFloor) &&
                                std::abs(ev.residual[1]) <= 1e-4 * (ev.scale[1] + tol.forceFloor * tol.reach);
        if ((motionDone && couplingRes <= tol.coupling) || resolved) {
            if (resolved && !(motionDone && couplingRes <= tol.coupling)) ++work_.resolvedSteps;
            acceptStep(ctx, s, x, y, ev, out);
            return true;
        }
        lastX = x;
        lastR = ev.residual;
        if (dz.size()) {
            x += dx;
            y += dz.tail(mp_ + ml_);
        } else if (flexible) {
            partitionedUpdate(ev, dx, x, y);
        } else {
            x += dx;
        }
    }
    failure = fmt::format("the Newton/coupling iteration did not converge in coupling.max_iterations = {} passes "
                          "({} film solves, Jacobian included)", maxIt, iterations);
    return false;
}

}  // namespace flexehd::cosim
