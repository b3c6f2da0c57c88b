// The Jacobian of one time step's equations in the unknowns z = (e, β, y) for the coupled
// Newton method (coupling.method: newton, the default with flexible bodies; docs/coupling.md §1, §3):
//
//   R_x(z) = M(ψ) ẍ(x) − f(ψ, F_g, film action(p, h))      (motion, docs/dynamics.md)
//   R_y(z) = y − H(p, p_c)                                   (modal response, quasi-static or BDF2)
//   p = p(h, ḣ): the film's complementarity solution, h = h_rigid(x) + Ψ y,
//   ḣ = (a0 h_s + a1 h_s,n + a2 h_s,n−1)/Δt                  (BDF2 of the squeeze thickness h_s:
//                                                            the rigid one, or the whole one with
//                                                            coupling.elastic_squeeze)
//
// The modal column j follows from the film-change shape Ψ_j and, with the elastic rate,
// δḣ_j = (a0/Δt) Ψ_j: δp_j from the film's linearisation with its cavitated set held
// (lube::FilmLinearization — a generalized Jacobian of the semismooth equation),
// δp_c,j = p_c'(h) Ψ_j, then the film action by a small difference of the (affine in p, smooth in
// h) film integrals, and the modal response of the mapped δp_j + δp_c,j. The (e, β) columns are
// differences of two full evaluations (formCoupledJacobian): a rigid motion moves the cavitation
// boundary, which the held set misses.
//
// At a linearisation point the modal columns are affine in the rate r = a0/Δt, up to the dynamic
// response's step matrix S(r):
//   δp_j = δp_j^h + r δp_j^ḣ,   R_x rows = A_x + r B_x,   R_y rows = I − S(r)⁻¹ (F^h + r F^ḣ).
// The parts are kept (CoupledJacobianParts) and the Jacobian is re-formed for a new step size
// without a new linearisation — a step-size change alone costs a dense refactorization.
#include "cosim/coupling/PistonSimulationState.hpp"

#include "lube/FilmIntegrals.hpp"
#include "lube/FilmLoadGradient.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "fem/Stopwatch.hpp"

namespace flexehd::cosim {

void PistonSimulation::filmChangeColumns(const Context& ctx, const Eigen::Vector2d& x) {
    const lube::FilmGrid& g = film_.grid();
    const int n = g.size(), k = 2 + mp_ + ml_;
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
}

Eigen::Matrix<double, 2, 6> PistonSimulation::actionGradient(const Context& ctx) const {
    // The equations of motion's right-hand side is affine in the film action (F_x, F_z, M_y).
    Eigen::Matrix<double, 2, 6> dForce = Eigen::Matrix<double, 2, 6>::Zero();
    const Eigen::Vector2d f0 = dyn_.force(ctx.crank, ctx.gas, FilmAction{0.0, 0.0, 0.0});
    dForce.col(0) = dyn_.force(ctx.crank, ctx.gas, FilmAction{1.0, 0.0, 0.0}) - f0;
    dForce.col(2) = dyn_.force(ctx.crank, ctx.gas, FilmAction{0.0, 1.0, 0.0}) - f0;
    dForce.col(4) = dyn_.force(ctx.crank, ctx.gas, FilmAction{0.0, 0.0, 1.0}) - f0;
    return dForce;
}

void PistonSimulation::linearizeCoupled(const Context& ctx, const Eigen::Vector2d& x, const Evaluation& ev) {
    const lube::FilmGrid& g = film_.grid();
    const int n = g.size(), m = mp_ + ml_;
    const bool elasticRate = case_.coupling.elasticSqueeze;
    fem::Stopwatch t0;

    filmChangeColumns(ctx, x);
    const Eigen::MatrixXd& Dh = jacobianDh_;
    // The parts hold the modal columns only: formCoupledJacobian takes the (e, β) columns by
    // differences of full evaluations. The film sees the floored thickness (no δh where the floor
    // holds); the rate sees the unfloored one, and the modes only with coupling.elastic_squeeze.
    const Eigen::MatrixXd Psi = Dh.rightCols(m);
    Eigen::MatrixXd flooredPsi;
    if (ev.floored > 0) {
        flooredPsi = Psi;
        for (int r = 0; r < n; ++r)
            if (ev.h[r] != ev.hTotal[r]) flooredPsi.row(r).setZero();
    }
    const Eigen::MatrixXd& PsiFilm = ev.floored > 0 ? flooredPsi : Psi;

    // δp from the film's linearisation at the evaluation's solution: the thickness part and the
    // rate part (per unit rate) apart.
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
    CoupledJacobianParts& P = *newtonParts_;
    const Eigen::MatrixXd dPh = linearization_->pressureChange(PsiFilm, Eigen::MatrixXd());
    const Eigen::MatrixXd dPrate =
        elasticRate ? linearization_->pressureChange(Eigen::MatrixXd(), Psi, 1.0) : Eigen::MatrixXd(n, 0);
    // Contact pressure of the unfloored h, as evaluate(): δp_c = p_c'(h) δh on the nodes in contact
    // (the load is p + p_c); its slope once per node.
    Eigen::VectorXd slope = Eigen::VectorXd::Zero(n);
    if (contact_)
        for (int r = 0; r < n; ++r)
            if (g.kind(r) != lube::NodeKind::Void) slope[r] = contactSlope(ev.hTotal[r]);
    const Eigen::MatrixXd dPc = slope.asDiagonal() * Psi;
    stats_.timings.film += t0.seconds();
    t0.restart();

    // Motion rows: −∂f/∂y through the film action — the load's gradient in (p, h, p_c) applied to
    // all modal columns at once (lube::FilmLoadGradient), the friction's change included (at high
    // sliding speed its moment about the pin is a large part of the motion's dependence on the
    // deformation); f is affine in the action (F_x, F_z, M_y).
    lube::FilmIntegralOptions io;
    io.referencePoint = Eigen::Vector3d(case_.engine.pinOffset, 0.0, 0.0);
    io.cavitationPressure = case_.lubricant.cavitationPressure;
    io.boundaryFriction = contact_ ? case_.contact.boundaryFriction : 0.0;
    const lube::FilmLoadGradient G = lube::filmLoadGradient(g, fs, lub, ev.p, io);
    const Eigen::Matrix<double, 2, 6> dForce = actionGradient(ctx);  // ∂f/∂(F, M)
    P.motionH = -dForce * G.change(dPh, PsiFilm, contact_ ? dPc : Eigen::MatrixXd());
    P.motionRate = elasticRate ? Eigen::MatrixXd(-dForce * G.change(dPrate, Eigen::MatrixXd(), Eigen::MatrixXd()))
                               : Eigen::MatrixXd(2, 0);

    // Modal rows: the modal forces of the mapped δp + δp_c (the response is applied when the
    // Jacobian is formed: it depends on the step size with bodies.response: dynamic).
    const Eigen::MatrixXd dLoad = dPh + dPc;
    if (piston_) {
        piston_->modalForces(dLoad, 0.0, P.pistonH);
        if (elasticRate) piston_->modalForces(dPrate, 0.0, P.pistonRate);
    }
    if (liner_) {
        liner_->modalForces(dLoad, ctx.offset, P.linerH);
        if (elasticRate) liner_->modalForces(dPrate, ctx.offset, P.linerRate);
    }
    P.valid = true;
    const double dtStructure = t0.seconds();
    stats_.timings.structure += dtStructure;
    stats_.timings.modal += dtStructure;
}

Eigen::MatrixXd PistonSimulation::coupledJacobian(const Context& ctx) {
    const fem::Stopwatch t0;
    const CoupledJacobianParts& P = *newtonParts_;
    const int m = mp_ + ml_, k = 2 + m;
    const double rate = ctx.a0 / ctx.dt;
    const bool elasticRate = case_.coupling.elasticSqueeze;
    // The modal columns; the (e, β) columns are formCoupledJacobian's.
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(k, k);
    J.topRightCorner(2, m) = elasticRate ? Eigen::MatrixXd(P.motionH + rate * P.motionRate) : P.motionH;
    // Modal rows: δ_ij − ∂H/∂y_j, H linear in the mapped pressure (history terms held).
    auto respond = [&](const Eigen::MatrixXd& Fh, const Eigen::MatrixXd& Fr, const FlexibleSurface& body,
                       modal::HeldModalDynamics* dynamics, int row, int rows) {
        Eigen::MatrixXd F = Fh;
        if (elasticRate) F += rate * Fr;
        if (dynamics) {
            const Eigen::VectorXd zero = Eigen::VectorXd::Zero(rows);
            Eigen::VectorXd q;
            for (int j = 0; j < m; ++j) {
                dynamics->respond(F.col(j), zero, zero, q);
                J.block(row, 2 + j, rows, 1) = -q;
            }
        } else {
            Eigen::MatrixXd Q;
            body.quasiStatic(F, Q);
            J.block(row, 2, rows, m) = -Q;
        }
    };
    if (piston_) respond(P.pistonH, P.pistonRate, *piston_, pistonDynamics_.get(), 2, mp_);
    if (liner_) respond(P.linerH, P.linerRate, *liner_, linerDynamics_.get(), 2 + mp_, ml_);
    J.bottomRightCorner(m, m).diagonal().array() += 1.0;
    const double dtStructure = t0.seconds();
    stats_.timings.structure += dtStructure;
    stats_.timings.modal += dtStructure;
    return J;
}

bool PistonSimulation::formCoupledJacobian(const Context& ctx, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                                           const Evaluation& ev, const Eigen::Vector2d& tol, int& filmSolves) {
    Eigen::MatrixXd& J = newtonJacobian_;
    J = coupledJacobian(ctx);
    // The (e, β) columns by differences of full evaluations (film solve and modal response): a
    // rigid motion moves the cavitation boundary, whose effect the held-set linearisation misses —
    // at high sliding and squeeze speeds enough to stall Newton (docs/coupling.md §1).
    const double fdScale = 1e-5;  // of the clearance (tilt: of the clearance over the reach)
    for (int i = 0; i < 2; ++i) {
        Eigen::Vector2d xp = x;
        xp[i] += fdScale * tol[i];
        Evaluation e2;
        try {
            e2 = evaluate(ctx, xp, y, true);
        } catch (const std::runtime_error&) {
            return false;
        }
        ++filmSolves;
        J.block<2, 1>(0, i) = (e2.residual - ev.residual) / (fdScale * tol[i]);
        J.col(i).tail(mp_ + ml_) = (ev.Hy - e2.Hy) / (fdScale * tol[i]);
    }
    newtonInverse_ = J.partialPivLu().inverse();
    // Unknowns in units of the film-thickness change they cause (Broyden norm, merit, damping).
    unknownScale_ = jacobianDh_.colwise().lpNorm<Eigen::Infinity>().transpose();
    for (Eigen::Index j = 0; j < unknownScale_.size(); ++j)
        unknownScale_[j] = unknownScale_[j] > 0.0 ? unknownScale_[j] : 1.0;
    // Without the elastic rate the quasi-static modal rows are algebraic: where the film's
    // stiffness on a combination of modes exceeds the structure's (det(I − ∂H/∂y) < 0), the skirt's
    // equilibrium in the film has folded away (docs/coupling.md §3); noted for the diagnosis.
    if (!case_.coupling.elasticSqueeze && !pistonDynamics_ && !linerDynamics_ && mp_ + ml_ > 0) {
        const int m = mp_ + ml_;
        if (Eigen::MatrixXd(J.bottomRightCorner(m, m)).partialPivLu().determinant() < 0.0) ++foldedJacobians_;
    }
    return true;
}

Eigen::VectorXd PistonSimulation::residualScale(const Evaluation& ev, double forceFloor, double reach,
                                                double couplingTol) const {
    const int k = 2 + mp_ + ml_;
    Eigen::VectorXd r = Eigen::VectorXd::Ones(k);
    r[0] = 1e-4 * (ev.scale[0] + forceFloor);
    r[1] = 1e-4 * (ev.scale[1] + forceFloor * reach);
    if (unknownScale_.size() == k)
        for (int j = 2; j < k; ++j) r[j] = couplingTol / unknownScale_[j];
    else
        r.tail(k - 2).setConstant(std::numeric_limits<double>::quiet_NaN());  // no Jacobian yet
    return r;
}

double PistonSimulation::coupledMerit(const Eigen::VectorXd& F, const Eigen::VectorXd& residualScale) {
    if (!residualScale.allFinite()) return std::numeric_limits<double>::infinity();
    return 0.5 * F.cwiseQuotient(residualScale).squaredNorm();
}

Eigen::VectorXd PistonSimulation::levenbergMarquardtStep(const Eigen::VectorXd& F, const Eigen::VectorXd& rScale) const {
    const Eigen::VectorXd dzScale = case_.piston.clearance * unknownScale_.cwiseInverse();
    const Eigen::MatrixXd Js = rScale.cwiseInverse().asDiagonal() * newtonJacobian_ * dzScale.asDiagonal();
    Eigen::MatrixXd N = Js.transpose() * Js;
    N.diagonal().array() += 1.0;
    return -(dzScale.asDiagonal() * N.llt().solve(Js.transpose() * F.cwiseQuotient(rScale)));
}

}  // namespace flexehd::cosim
