// PistonSimulation::evaluate: one iterate (e, β, y) of a step as stages (docs/coupling.md §1) —
// the film thickness (rigid motion + clearance terms + elastic change), contact pressure and the
// film floor, the film solve with its loads, the equations of motion's residual, and the bodies'
// response to the film load.
#include <algorithm>
#include <cmath>
#include <limits>

#include "cosim/clearance/ClearanceTerms.hpp"
#include "cosim/coupling/PistonSimulationState.hpp"
#include "fem/Stopwatch.hpp"
#include "lube/FilmIntegrals.hpp"

namespace flexehd::cosim {

PistonSimulation::Evaluation PistonSimulation::evaluate(const Context& ctx, const Eigen::Vector2d& x,
                                                        const Eigen::VectorXd& y, bool structure) {
    Evaluation ev;
    filmThickness(ctx, x, y, ev);
    const fem::Stopwatch t0;
    contactAndFloor(ev);
    solveFilm(ctx, ev);
    stats_.timings.film += t0.seconds();
    motionResidual(ctx, x, ev);
    if (structure && (piston_ || liner_)) structureResponse(ctx, ev);
    return ev;
}

void PistonSimulation::filmThickness(const Context& ctx, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                                     Evaluation& ev) {
    fem::Stopwatch t0;
    film_.rigidThickness(x[0], x[1], ev.hRigid);
    if (clearance_) clearance_->add(ctx.offset, ev.hRigid);  // distortion, thermal (seed eq. 2)
    ev.h = ev.hRigid;
    const double rigidSeconds = t0.seconds();
    if (piston_ || liner_) {
        // Elastic Δh of y at this offset; the Jacobian's evaluations reuse the pass's (y frozen).
        t0.restart();
        if (!(elasticOffset_ == ctx.offset && elasticY_.size() == y.size() && elasticY_ == y)) {
            if (piston_) piston_->filmChange(y.head(mp_), 0.0, pistonDh_);
            if (liner_) liner_->filmChange(y.tail(ml_), ctx.offset, linerDh_);
            elasticY_ = y;
            elasticOffset_ = ctx.offset;
        }
        if (piston_) ev.h += pistonDh_;
        if (liner_) ev.h += linerDh_;
        const double dt = t0.seconds();
        stats_.timings.mapping += dt;
        stats_.timings.structure += dt;
    }
    stats_.timings.film += rigidSeconds;
}

void PistonSimulation::contactAndFloor(Evaluation& ev) const {
    const lube::FilmGrid& g = film_.grid();
    // Where the surfaces touch or overlap, the contact pressure of the unfloored h (asperities,
    // and the coating's hard contact below h = 0) carries the load; the Reynolds equation sees h
    // floored at a fluid film of 0.05σ (0.01 c_r without contact). Counted in `floored`; the
    // outputs show the unfloored thickness (ev.hTotal, ev.minGap).
    const double floor = contact_ ? 0.05 * case_.contact.sigma : 0.01 * case_.piston.clearance;
    ev.hTotal = ev.h;
    ev.pc = Eigen::VectorXd::Zero(g.size());
    ev.pcHard = Eigen::VectorXd::Zero(g.size());
    ev.minGap = std::numeric_limits<double>::infinity();
    ev.hardForce = 0.0;
    for (int k = 0; k < g.size(); ++k) {
        if (g.kind(k) == lube::NodeKind::Void) continue;
        ev.minGap = std::min(ev.minGap, ev.h[k]);
        if (contact_) {
            double asperity = 0.0, hard = 0.0;
            contactPressure(ev.h[k], asperity, hard);
            ev.pc[k] = asperity + hard;
            if (hard > 0.0) {
                ev.pcHard[k] = hard;
                ev.hardForce -= hard * g.surfaceArea(k) * std::cos(g.theta(g.thetaIndex(k)));
            }
        }
        if (ev.h[k] < floor) {
            ev.h[k] = floor;
            ++ev.floored;
        }
    }
}

void PistonSimulation::solveFilm(const Context& ctx, Evaluation& ev) {
    const lube::FilmGrid& g = film_.grid();
    const State& n = *ctx.now;
    const State& b = *ctx.before;
    // Squeeze term: BDF2 of the whole (unfloored) film thickness with coupling.elastic_squeeze,
    // else of the rigid film thickness only (docs/coupling.md §3: with the elastic rate the
    // partitioned coupling has a gain ∝ 1/Δt and does not converge; it needs the Newton method).
    if (case_.coupling.elasticSqueeze)
        ev.dhdt = (ctx.a0 * ev.hTotal + ctx.a1 * n.hTotal + ctx.a2 * b.hTotal) / ctx.dt;
    else
        ev.dhdt = (ctx.a0 * ev.hRigid + ctx.a1 * n.hRigid + ctx.a2 * b.hRigid) / ctx.dt;
    lube::FilmState fs;
    fs.h = ev.h;
    fs.dhdt = ev.dhdt;
    fs.outer.axial = -ctx.crank.velocity;  // the liner slides past the piston-fixed grid
    const Eigen::VectorXd* warm = n.p.size() == g.size() ? &n.p : nullptr;
    lube::ReynoldsResult solved = solver_.solve(fs, warm);
    ev.p = std::move(solved.pressure);
    if (solved.fellBack) ++stats_.fallbackSolves;
    ++stats_.filmSolves;
    lube::FilmIntegralOptions io;
    io.referencePoint = Eigen::Vector3d(case_.engine.pinOffset, 0.0, 0.0);
    io.cavitationPressure = case_.lubricant.cavitationPressure;
    io.boundaryFriction = contact_ ? case_.contact.boundaryFriction : 0.0;
    io.contactPressure = contact_ ? &ev.pc : nullptr;
    ev.loads = lube::integrateFilm(g, fs, solver_.lubricant(), ev.p, io);
    const Eigen::Vector3d F = ev.loads.totalForce();
    ev.action = {F.x(), F.z(), ev.loads.moment.y()};
}

void PistonSimulation::motionResidual(const Context& ctx, const Eigen::Vector2d& x, Evaluation& ev) const {
    const State& n = *ctx.now;
    const State& b = *ctx.before;
    ev.vel = (ctx.a0 * x + ctx.a1 * n.x + ctx.a2 * b.x) / ctx.dt;
    ev.acc = (ctx.a0 * ev.vel + ctx.a1 * n.v + ctx.a2 * b.v) / ctx.dt;
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

void PistonSimulation::structureResponse(const Context& ctx, Evaluation& ev) {
    fem::Stopwatch t0;
    const Eigen::VectorXd ptot = ev.p + ev.pc;
    ev.Hy.resize(mp_ + ml_);
    Eigen::VectorXd fp, fl, q;
    if (piston_) piston_->modalForce(ptot, 0.0, fp);  // load mapping: Φᵀ A p
    if (liner_) liner_->modalForce(ptot, ctx.offset, fl);
    const double tMap = t0.seconds();
    t0.restart();
    if (piston_) {  // modal update: q = C f, or the BDF2 step of the modal dynamics
        if (pistonDynamics_)
            pistonDynamics_->respond(fp, ctx.hq.head(mp_), ctx.hv.head(mp_), q);
        else
            piston_->quasiStatic(fp, q);
        ev.Hy.head(mp_) = q;
    }
    if (liner_) {
        if (linerDynamics_)
            linerDynamics_->respond(fl, ctx.hq.tail(ml_), ctx.hv.tail(ml_), q);
        else
            liner_->quasiStatic(fl, q);
        ev.Hy.tail(ml_) = q;
    }
    const double tModal = t0.seconds();
    stats_.timings.mapping += tMap;
    stats_.timings.modal += tModal;
    stats_.timings.structure += tMap + tModal;
}

}  // namespace flexehd::cosim
