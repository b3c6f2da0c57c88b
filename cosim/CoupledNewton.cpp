// The Jacobian of one time step's equations in the unknowns z = (e, β, y) when the squeeze term
// carries the elastic deformation rate (coupling.elastic_squeeze; docs/coupling.md §3):
//
//   R_x(z) = M(ψ) ẍ(x) − f(ψ, F_g, film action(p, h))      (motion, docs/dynamics.md)
//   R_y(z) = y − H(p, p_c)                                   (modal response, quasi-static or BDF2)
//   p = p(h, ḣ): the film's complementarity solution, h = h_rigid(x) + Ψ y,
//   ḣ = (a0 h + a1 hₙ + a2 hₙ₋₁)/Δt                          (BDF2 of the whole film thickness)
//
// Column j of the Jacobian follows from δh_j (∂h/∂z_j: the rigid thickness's derivative, or the
// film-change shape Ψ_j) and δḣ_j = a0/Δt δh_j: δp_j from the film's linearisation with its
// cavitated set held (lube::FilmLinearization — a generalized Jacobian of the semismooth
// equation), δp_c,j = p_c'(h) δh_j, then the film action by a small difference of the (affine in p,
// smooth in h) film integrals, and the modal response of the mapped δp_j + δp_c,j. The a0/Δt
// squeeze part, whose gain ∝ 1/Δt defeats the partitioned iteration, is thereby exact.
#include "cosim/PistonSimulationState.hpp"

#include "lube/FilmIntegrals.hpp"

#include <chrono>
#include <cmath>

namespace flexehd::cosim {

namespace {
using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }
}  // namespace

Eigen::MatrixXd PistonSimulation::coupledJacobian(const Context& ctx, const Eigen::Vector2d& x, const Evaluation& ev) {
    const lube::FilmGrid& g = film_.grid();
    const int n = g.size(), m = mp_ + ml_, k = 2 + m;
    auto t0 = Clock::now();

    // δh per unknown: the rigid thickness is linear in (e, β); the modal columns are Ψ.
    Eigen::MatrixXd Dh(n, k);
    {
        const double reach = std::max(case_.piston.skirtTop, -case_.piston.skirtBottom);
        const Eigen::Vector2d d(1e-3 * case_.piston.clearance, 1e-3 * case_.piston.clearance / reach);
        Eigen::VectorXd h0, h1;
        film_.rigidThickness(x[0], x[1], h0);
        for (int i = 0; i < 2; ++i) {
            Eigen::Vector2d xi = x;
            xi[i] += d[i];
            film_.rigidThickness(xi[0], xi[1], h1);
            Dh.col(i) = (h1 - h0) / d[i];
        }
    }
    if (piston_) Dh.middleCols(2, mp_) = psiPiston_;
    if (liner_) {
        if (!(psiLinerOffset_ == ctx.offset)) {  // once per step (the offset is the step's)
            liner_->filmChangeShapes(ctx.offset, psiLiner_);
            psiLinerOffset_ = ctx.offset;
        }
        Dh.rightCols(ml_) = psiLiner_;
    }
    for (int r = 0; r < n; ++r)
        if (g.kind(r) == lube::NodeKind::Void) Dh.row(r).setZero();
    const Eigen::MatrixXd Dhdt = (ctx.a0 / ctx.dt) * Dh;  // the rate sees the unfloored thickness
    Eigen::MatrixXd DhFilm = Dh;                            // the film sees the floored one
    for (int r = 0; r < n; ++r)
        if (ev.h[r] != ev.hTotal[r]) DhFilm.row(r).setZero();

    // δp from the film's linearisation at the evaluation's solution.
    lube::FilmState fs;
    fs.h = ev.h;
    fs.dhdt = ev.dhdt;
    fs.outer.axial = -ctx.crank.velocity;
    const lube::Lubricant& lub = solver_.lubricant();
    Eigen::VectorXd rho(n), eta(n);
    for (int r = 0; r < n; ++r) {
        rho[r] = lub.density(ev.p[r]);
        eta[r] = lub.viscosity(ev.p[r]);
    }
    linearization_->linearize(fs, rho, eta, ev.p, case_.lubricant.cavitationPressure);
    const Eigen::MatrixXd dP = linearization_->pressureChange(DhFilm, Dhdt);
    Eigen::MatrixXd dPc = Eigen::MatrixXd::Zero(n, k);
    if (contact_) {  // p_c(max(h, −2σ)) of the unfloored h, as evaluate()
        const double sigma = case_.contact.sigma, d = 1e-4 * sigma;
        for (int r = 0; r < n; ++r) {
            const double h = ev.hTotal[r];
            if (g.kind(r) == lube::NodeKind::Void || h <= -2.0 * sigma) continue;
            const double slope = (contact_->pressure(h + d) - contact_->pressure(std::max(h - d, -2.0 * sigma))) /
                                 (h + d - std::max(h - d, -2.0 * sigma));
            if (slope != 0.0) dPc.row(r) = slope * Dh.row(r);
        }
    }
    stats_.timings.film += seconds(t0);
    t0 = Clock::now();

    // Motion rows: −∂f/∂z through the film action, plus M (a0/Δt)² on (e, β). The rigid columns
    // by a difference of the film integrals (affine in p, smooth in h); the modal columns through
    // the normal force and its moment only (weights of integrateFilm's pressure term), leaving
    // out the small change of the shear friction — an inexact Newton step, not a different solution.
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(k, k);
    lube::FilmIntegralOptions io;
    io.referencePoint = Eigen::Vector3d(case_.engine.pinOffset, 0.0, 0.0);
    io.cavitationPressure = case_.lubricant.cavitationPressure;
    io.boundaryFriction = contact_ ? case_.contact.boundaryFriction : 0.0;
    const Eigen::Vector2d f0 = dyn_.force(ctx.crank, ctx.gas, ev.action);
    lube::FilmState fj = fs;
    Eigen::VectorXd pj, pcj;
    for (int j = 0; j < 2; ++j) {
        const double size = Dh.col(j).cwiseAbs().maxCoeff();
        // A step of 1e-6 clearance in h: the integrals' curvature (friction ∝ 1/h) stays below it.
        const double s = 1e-6 * case_.piston.clearance / size;
        fj.h = fs.h + s * DhFilm.col(j);
        fj.dhdt = fs.dhdt + s * Dhdt.col(j);
        pj = ev.p + s * dP.col(j);
        pcj = ev.pc + s * dPc.col(j);
        io.contactPressure = contact_ ? &pcj : nullptr;
        const lube::FilmLoads loads = lube::integrateFilm(g, fj, lub, pj, io);
        const Eigen::Vector3d F = loads.totalForce();
        const Eigen::Vector2d fjv = dyn_.force(ctx.crank, ctx.gas, FilmAction{F.x(), F.z(), loads.moment.y()});
        J.block(0, j, 2, 1) = -(fjv - f0) / s;
    }
    if (m > 0) {
        if (normalWeights_.cols() != n) {  // fx = Σ −p A cos θ, my = Σ z (−p A cos θ) (pin axis at z = 0)
            normalWeights_.setZero(2, n);
            for (int r = 0; r < n; ++r) {
                if (g.kind(r) == lube::NodeKind::Void) continue;
                const double fx = -g.area(r) * std::cos(g.theta(g.thetaIndex(r)));
                normalWeights_(0, r) = fx;
                normalWeights_(1, r) = (g.z(g.axialIndex(r)) - io.referencePoint.z()) * fx;
            }
        }
        const Eigen::MatrixXd dAction = normalWeights_ * (dP.rightCols(m) + dPc.rightCols(m));  // 2 × m
        for (int j = 0; j < m; ++j) {
            FilmAction a = ev.action;
            a.fx += dAction(0, j);
            a.my += dAction(1, j);
            J.block(0, 2 + j, 2, 1) = -(dyn_.force(ctx.crank, ctx.gas, a) - f0);
        }
    }
    const double rate = ctx.a0 / ctx.dt;
    J.topLeftCorner<2, 2>() += dyn_.mass(ctx.crank) * (rate * rate);

    // Modal rows: δ_ij − ∂H/∂z_j, H linear in the mapped pressure (history terms held).
    const Eigen::MatrixXd dPt = dP + dPc;
    Eigen::MatrixXd F;
    Eigen::VectorXd q;
    const Eigen::VectorXd zp = Eigen::VectorXd::Zero(mp_), zl = Eigen::VectorXd::Zero(ml_);
    if (piston_) {
        piston_->modalForces(dPt, 0.0, F);
        for (int j = 0; j < k; ++j) {
            if (pistonDynamics_) pistonDynamics_->respond(F.col(j), zp, zp, q);
            else piston_->quasiStatic(F.col(j), q);
            J.block(2, j, mp_, 1) = -q;
        }
    }
    if (liner_) {
        liner_->modalForces(dPt, ctx.offset, F);
        for (int j = 0; j < k; ++j) {
            if (linerDynamics_) linerDynamics_->respond(F.col(j), zl, zl, q);
            else liner_->quasiStatic(F.col(j), q);
            J.block(2 + mp_, j, ml_, 1) = -q;
        }
    }
    J.bottomRightCorner(m, m).diagonal().array() += 1.0;
    const double dtStructure = seconds(t0);
    stats_.timings.structure += dtStructure;
    stats_.timings.modal += dtStructure;
    return J;
}

}  // namespace flexehd::cosim
