// StepSolver: one time step (docs/coupling.md §1) — the step's context (BDF2
// coefficients, crank state, gas force, liner offset), the predictor, and the Newton/coupling
// iteration with the run's coupling scheme (CoupledNewtonScheme, PartitionedScheme) until the
// motion and the coupling residual meet their tolerances.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "cosim/coupling/StepSolver.hpp"

#include "modal/HeldModalDynamics.hpp"
#include "cosim/coupling/CoupledNewtonScheme.hpp"
#include "cosim/coupling/PartitionedScheme.hpp"

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
    // The coupling scheme, chosen once: the coupled Newton method needs flexible bodies.
    if (c.coupling.method == CouplingMethod::Newton && mp_ + ml_ > 0)
        scheme_ = std::make_unique<CoupledNewtonScheme>(*this);
    else
        scheme_ = std::make_unique<PartitionedScheme>(*this);
    if (c.ringGas.model == RingGasModel::Lands) packGas_ = std::make_unique<RingPackGas>(c);
    const PistonLoadSpec& loads = c.pistonBody.loads;
    if (pistonBody_ && (loads.gasPressure || loads.inertia || loads.ringPack))
        pistonLoads_ = std::make_unique<PistonBodyLoads>(*pistonBody_, loads, c.pistonBody.file, c.rings, c.engine.bore);
    contactsChanged();
}

StepSolver::~StepSolver() = default;

void StepSolver::contactsChanged() {
    // Every new contact is told once what the scheme needs of it.
    const CouplingNeeds needs = scheme_->needs();
    for (; preparedContacts_ < contacts_.size(); ++preparedContacts_) contacts_[preparedContacts_]->prepare(needs);
    scheme_->contactsChanged();
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
    const double cylinderPressure = pressure_(crankAngle720(ctx.crankDeg));
    ctx.gas = dyn_.gasForce(cylinderPressure);
    st.cylinderPressure = cylinderPressure - case_.engine.crankcasePressure;
    if (packGas_) st.ringGas = &packGas_->trial(st.dt, cylinderPressure, ctx.crank.acceleration + dyn_.gravity(),
                                                ringFriction(s), ringOpenGaps(s));
    st.linerOffset = linerOffset_(ctx.crankDeg);
    st.oil = s.oil.layer ? &s.oil : nullptr;
    ctx.now = &s;
    ctx.before = &prev;
    if (pistonDynamics_ || linerDynamics_) {
        // Each body's step from its state (prev starts as a copy of the initial state; a2 = 0 on
        // the first step) and the modal force it was in.
        auto begin = [&](modal::ModalStepper& body, Eigen::Index first, Eigen::Index count) {
            modal::ModalStepStart start;
            start.dt = st.dt;
            start.a0 = st.a0, start.a1 = st.a1, start.a2 = st.a2;
            start.y = s.y.segment(first, count);
            start.yBefore = prev.y.segment(first, count);
            start.w = s.w.segment(first, count);
            start.wBefore = prev.w.segment(first, count);
            if (s.f.size() == s.y.size()) start.f = s.f.segment(first, count);
            body.beginStep(start);
        };
        if (pistonDynamics_) begin(*pistonDynamics_, 0, mp_);
        if (linerDynamics_) begin(*linerDynamics_, mp_, ml_);
    }
    return ctx;
}

std::vector<double> StepSolver::ringFriction(const StepState& s) const {
    std::vector<double> friction(case_.rings.size(), 0.0);
    for (std::size_t c = 0; c < contacts_.size() && c < s.films.size(); ++c) {
        const int ring = contacts_[c]->packRing();
        if (ring >= 0 && static_cast<std::size_t>(ring) < friction.size())
            friction[static_cast<std::size_t>(ring)] = s.films[c].axialForce;
    }
    return friction;
}

std::vector<RingOpenGap> StepSolver::ringOpenGaps(const StepState& s) const {
    std::vector<RingOpenGap> gaps(case_.rings.size());
    for (std::size_t c = 0; c < contacts_.size() && c < s.films.size(); ++c) {
        const int ring = contacts_[c]->packRing();
        if (ring >= 0 && static_cast<std::size_t>(ring) < gaps.size()) gaps[static_cast<std::size_t>(ring)] = s.films[c].openGap;
    }
    return gaps;
}

StepTolerances StepSolver::stepTolerances() const {
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

CouplingResidual StepSolver::couplingResidual(const StepContext& ctx, const StepEvaluation& ev,
                                              const Eigen::VectorXd& y) {
    // max |Δh(H(y)) − Δh(y)| over every contact's film; the bound from the contacts' shape maxima.
    Eigen::VectorXd d = ev.Hy - y;
    double bound = 0.0;
    for (const auto& contact : contacts_) {
        const double b = contact->filmChangeBound(d);
        if (!(b >= 0.0)) {  // not a number (the modal residual is not finite): no bound
            bound = std::numeric_limits<double>::infinity();
            break;
        }
        bound = std::max(bound, b);
    }
    return CouplingResidual(bound, [this, &ctx, d = std::move(d)] { return largestFilmChange(ctx, d); });
}

double StepSolver::largestFilmChange(const StepContext& ctx, const Eigen::VectorXd& d) {
    double res = 0.0;
    for (const auto& contact : contacts_) res = std::max(res, contact->filmChange(ctx.step, d, work_));
    return res;
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

void StepSolver::acceptStep(const StepContext& ctx, const StepState& s, const Eigen::Vector2d& x,
                                  const Eigen::VectorXd& y, const StepEvaluation& ev, StepState& out) const {
    out.crankDeg = ctx.crankDeg;
    out.time = s.time + ctx.step.dt;
    out.dt = ctx.step.dt;
    out.x = x;
    out.v = ev.vel;
    out.a = ev.acc;
    out.y = y;
    out.yFrom = s.y;
    if (pistonDynamics_ || linerDynamics_) {
        out.w = Eigen::VectorXd::Zero(mp_ + ml_);
        if (pistonDynamics_) out.w.head(mp_) = pistonDynamics_->velocity(y.head(mp_), ev.modalForce.head(mp_));
        if (linerDynamics_) out.w.tail(ml_) = linerDynamics_->velocity(y.tail(ml_), ev.modalForce.tail(ml_));
    }
    out.f = ev.modalForce;
    out.films.clear();
    for (std::size_t c = 0; c < contacts_.size(); ++c) out.films.push_back(contacts_[c]->accepted(ctx.step, s.films[c], ev.films[c]));
}

Eigen::Vector2d StepSolver::predictedMotion(const StepState& s, const StepState& prev, double dt,
                                            const Eigen::Vector2d& scale) {
    const Eigen::Vector2d firstOrder = s.x + dt * s.v;
    if (s.dt > 0.0 && prev.dt > 0.0) {
        // Where the acceleration reverses within a step (a slap on a starved film), the second-
        // order term sends the iteration's start the wrong way: the last step tells.
        const Eigen::Vector2d lastFirst = prev.x + s.dt * prev.v;
        const Eigen::Vector2d lastSecond = lastFirst + 0.5 * s.dt * s.dt * prev.a;
        if ((s.x - lastFirst).cwiseQuotient(scale).cwiseAbs().maxCoeff() <
            (s.x - lastSecond).cwiseQuotient(scale).cwiseAbs().maxCoeff())
            return firstOrder;
    }
    return firstOrder + 0.5 * dt * dt * s.a;
}

Eigen::VectorXd StepSolver::predictedModal(const StepState& s, const StepState& prev, double dt, bool quadratic) {
    if (!(s.dt > 0.0) || prev.y.size() != s.y.size()) return s.y;
    return extrapolatedModal(s, prev, dt, quadratic, s.y, prev.y, prev.yFrom);
}

Eigen::VectorXd StepSolver::extrapolatedModal(const StepState& s, const StepState& prev, double dt, bool quadratic,
                                              const Eigen::VectorXd& now, const Eigen::VectorXd& before,
                                              const Eigen::VectorXd& beforeThat) {
    if (!(s.dt > 0.0) || before.size() != now.size()) return {};
    if (!quadratic || !(prev.dt > 0.0) || beforeThat.size() != now.size()) return now + (dt / s.dt) * (now - before);
    // Lagrange weights at t = Δt of the times -(Δt_n + Δt_{n-1}), -Δt_n, 0.
    const double t0 = -(s.dt + prev.dt), t1 = -s.dt;
    const double w0 = (dt - t1) * dt / ((t0 - t1) * t0);
    const double w1 = (dt - t0) * dt / ((t1 - t0) * t1);
    const double w2 = (dt - t0) * (dt - t1) / (t0 * t1);
    return w0 * beforeThat + w1 * before + w2 * now;
}

Eigen::VectorXd StepSolver::givenLoadResponse(const StepContext& ctx) const {
    if (!pistonLoads_ || !pistonBody_ || pistonDynamics_) return {};
    Eigen::VectorXd f = Eigen::VectorXd::Zero(mp_), q;
    pistonLoads_->add(ctx.step.cylinderPressure, Eigen::Vector2d::Zero(), ctx.crank.acceleration + dyn_.gravity(),
                      ctx.step.ringGas, f);
    pistonBody_->quasiStatic(f, q);
    Eigen::VectorXd y = Eigen::VectorXd::Zero(mp_ + ml_);
    y.head(mp_) = q;
    return y;
}

bool StepSolver::advance(const StepState& s, const StepState& prev, double dtDeg, StepState& out, StepEvaluation& ev, int& iterations,
                               std::string& failure) {
    const StepContext ctx = stepContext(s, prev, dtDeg);
    const double dt = ctx.step.dt;
    const StepTolerances tol = stepTolerances();
    Eigen::Vector2d x = predictedMotion(s, prev, dt, tol.motion);
    // At high speed y moves by hundreds of coupling tolerances per step, and from y_n the first
    // Newton passes go through the strongly nonlinear film law. On a starved film the skirt's
    // deflection under its wetted patch changes its rate within a few steps: the linear start
    // of the costliest third of the starved flexible cycle's steps is a film change of 0.8 um
    // (median) off. Where the modal coordinates carry little curvature, the quadratic's larger
    // weights on the last states' convergence errors make the start worse: the last step tells.
    Eigen::VectorXd y = predictedModal(s, prev, dt, s.quadraticModalStart);
    const bool flexible = mp_ + ml_ > 0;
    // The given loads (a ring's flank force jumps as the ring lifts in its groove) change the
    // solution by what they change beyond their own extrapolation; the kept Jacobian says how
    // much, before the first film solve (docs/coupling.md §1).
    const Eigen::VectorXd given = givenLoadResponse(ctx);
    if (given.size()) {
        const Eigen::VectorXd expected =
            extrapolatedModal(s, prev, dt, s.quadraticModalStart, s.yGiven, prev.yGiven, prev.yGivenFrom);
        const Eigen::VectorXd dz =
            expected.size() == given.size() ? scheme_->givenLoadChange(given - expected) : Eigen::VectorXd();
        if (dz.size() == 2 + y.size()) {
            x += dz.head<2>();
            y += dz.tail(y.size());
        }
    }
    const int maxIt = case_.coupling.maxIterations;
    iterations = 0;
    failure.clear();
    // Why the iteration failed, for the diagnosis when the step size runs out.
    auto fail = [&](const std::string& why) {
        failure = fmt::format("{} (after {} film solves in this attempt)", why, iterations);
        return false;
    };
    scheme_->beginStep(x, y);
    for (int it = 0; it < maxIt; ++it) {
        try {
            ev = evaluate(ctx, x, y, true);
        } catch (const std::runtime_error& e) {
            return fail(std::string("a film solve failed: ") + e.what());  // the caller shortens the step
        }
        ++iterations;
        const CouplingResidual couplingRes = flexible ? couplingResidual(ctx, ev, y) : CouplingResidual();
        Eigen::Vector2d dx;     // the motion's update
        bool resolved = false;  // converged to the unknowns' resolution
        std::string why;
        const CouplingScheme::PassOutcome pass =
            scheme_->pass(ctx, tol, it, ev, couplingRes, x, y, iterations, dx, resolved, why);
        if (pass == CouplingScheme::PassOutcome::Retry) continue;
        if (pass == CouplingScheme::PassOutcome::Failed) return fail(why);
        if (!dx.allFinite()) return fail("the Newton update is not finite");
        const bool motionDone = std::abs(dx[0]) <= 1e-5 * tol.motion[0] && std::abs(dx[1]) <= 1e-5 * tol.motion[1] &&
                                std::abs(ev.residual[0]) <= 1e-4 * (ev.scale[0] + tol.forceFloor) &&
                                std::abs(ev.residual[1]) <= 1e-4 * (ev.scale[1] + tol.forceFloor * tol.reach);
        const bool converged = motionDone && couplingRes.atMost(tol.coupling);
        if (converged || resolved) {
            if (!converged) ++work_.resolvedSteps;
            acceptStep(ctx, s, x, y, ev, out);
            out.yGiven = given;
            out.yGivenFrom = s.yGiven;
            out.quadraticModalStart =
                flexible && largestFilmChange(ctx, y - predictedModal(s, prev, dt, true)) <
                                largestFilmChange(ctx, y - predictedModal(s, prev, dt, false));
            return true;
        }
        scheme_->update(ev, dx, x, y);
    }
    failure = fmt::format("the Newton/coupling iteration did not converge in coupling.max_iterations = {} passes "
                          "({} film solves, Jacobian included)", maxIt, iterations);
    return false;
}

}  // namespace flexehd::cosim
