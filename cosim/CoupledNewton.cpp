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

    // δh per unknown: the rigid thickness is linear in (e, β); the modal columns are Ψ (zero on
    // Void nodes; the piston's are constant and written once). Kept between calls: n × k.
    Eigen::MatrixXd& Dh = jacobianDh_;
    if (Dh.rows() != n || Dh.cols() != k) {
        Dh.resize(n, k);
        if (piston_) Dh.middleCols(2, mp_) = psiPiston_;
    }
    {
        const double reach = std::max(case_.piston.skirtTop, -case_.piston.skirtBottom);
        const Eigen::Vector2d d(1e-3 * case_.piston.clearance, 1e-3 * case_.piston.clearance / reach);
        Eigen::VectorXd h0, h1;
        film_.rigidThickness(x[0], x[1], h0);
        for (int i = 0; i < 2; ++i) {
            Eigen::Vector2d xi = x;
            xi[i] += d[i];
            film_.rigidThickness(xi[0], xi[1], h1);
            for (int r = 0; r < n; ++r) Dh(r, i) = g.kind(r) == lube::NodeKind::Void ? 0.0 : (h1[r] - h0[r]) / d[i];
        }
    }
    if (liner_ && !(psiLinerOffset_ == ctx.offset)) {  // once per step (the offset is the step's)
        liner_->filmChangeShapes(ctx.offset, psiLiner_);
        Dh.rightCols(ml_) = psiLiner_;
        psiLinerOffset_ = ctx.offset;
    }
    const double rate = ctx.a0 / ctx.dt;  // δḣ = rate δh: the rate sees the unfloored thickness
    Eigen::MatrixXd floored;              // the film sees the floored one: no δh where the floor holds
    if (ev.floored > 0) {
        floored = Dh;
        for (int r = 0; r < n; ++r)
            if (ev.h[r] != ev.hTotal[r]) floored.row(r).setZero();
    }
    const Eigen::MatrixXd& DhFilm = ev.floored > 0 ? floored : Dh;

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
    Eigen::MatrixXd dP = linearization_->pressureChange(DhFilm, Dh, rate);
    // Asperity pressure p_c(max(h, −2σ)) of the unfloored h, as evaluate(): δp_c = p_c'(h) δh on
    // the nodes in contact, added into dP (the load is p + p_c); the rigid columns kept apart too.
    Eigen::Matrix<double, Eigen::Dynamic, 2> dPcRigid = Eigen::MatrixXd::Zero(n, 2);
    if (contact_) {
        const double sigma = case_.contact.sigma, d = 1e-4 * sigma;
        for (int r = 0; r < n; ++r) {
            const double h = ev.hTotal[r];
            if (g.kind(r) == lube::NodeKind::Void || h <= -2.0 * sigma) continue;
            const double lo = std::max(h - d, -2.0 * sigma);
            const double slope = (contact_->pressure(h + d) - contact_->pressure(lo)) / (h + d - lo);
            if (slope == 0.0) continue;
            dPcRigid.row(r) = slope * Dh.row(r).head<2>();
            dP.row(r) += slope * Dh.row(r);
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
        fj.dhdt = fs.dhdt + (s * rate) * Dh.col(j);
        pcj = ev.pc + s * dPcRigid.col(j);
        pj = ev.p + s * (dP.col(j) - dPcRigid.col(j));  // dP holds p_c's change too
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
        const Eigen::MatrixXd dAction = normalWeights_ * dP.rightCols(m);  // 2 × m
        for (int j = 0; j < m; ++j) {
            FilmAction a = ev.action;
            a.fx += dAction(0, j);
            a.my += dAction(1, j);
            J.block(0, 2 + j, 2, 1) = -(dyn_.force(ctx.crank, ctx.gas, a) - f0);
        }
    }
    J.topLeftCorner<2, 2>() += dyn_.mass(ctx.crank) * (rate * rate);

    // Modal rows: δ_ij − ∂H/∂z_j, H linear in the mapped pressure (history terms held).
    Eigen::MatrixXd F, Q;
    Eigen::VectorXd q;
    const Eigen::VectorXd zp = Eigen::VectorXd::Zero(mp_), zl = Eigen::VectorXd::Zero(ml_);
    if (piston_) {
        piston_->modalForces(dP, 0.0, F);
        if (pistonDynamics_) {
            for (int j = 0; j < k; ++j) {
                pistonDynamics_->respond(F.col(j), zp, zp, q);
                J.block(2, j, mp_, 1) = -q;
            }
        } else {
            piston_->quasiStatic(F, Q);
            J.middleRows(2, mp_) = -Q;
        }
    }
    if (liner_) {
        liner_->modalForces(dP, ctx.offset, F);
        if (linerDynamics_) {
            for (int j = 0; j < k; ++j) {
                linerDynamics_->respond(F.col(j), zl, zl, q);
                J.block(2 + mp_, j, ml_, 1) = -q;
            }
        } else {
            liner_->quasiStatic(F, Q);
            J.bottomRows(ml_) = -Q;
        }
    }
    J.bottomRightCorner(m, m).diagonal().array() += 1.0;
    const double dtStructure = seconds(t0);
    stats_.timings.structure += dtStructure;
    stats_.timings.modal += dtStructure;
    return J;
}

}  // namespace flexehd::cosim
