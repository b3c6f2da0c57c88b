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
// The modal columns come from the contacts (FilmContact::linearize; the skirt's:
// SkirtContactLinearization.cpp): each gives the change of its load and of its modal load with y,
// the master maps the summed load change through the equations of motion and the summed modal load
// through the bodies' response. The (e, β) columns are differences of two full evaluations
// (formCoupledJacobian): a rigid motion moves the cavitation boundary, which the contacts'
// held-set linearisations miss.
//
// At a linearisation point the modal columns are affine in the rate r = a0/Δt, up to the dynamic
// response's step matrix S(r):
//   δp_j = δp_j^h + r δp_j^ḣ,   R_x rows = A_x + r B_x,   R_y rows = I − S(r)⁻¹ (F^h + r F^ḣ).
// The parts are kept (CoupledJacobianParts) and the Jacobian is re-formed for a new step size
// without a new linearisation — a step-size change alone costs a dense refactorization.
#include "cosim/coupling/CoupledNewtonScheme.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "cosim/coupling/StepSolver.hpp"
#include "fem/Stopwatch.hpp"

namespace flexehd::cosim {
namespace {

// A contact's part of the coupled Jacobian added to the sum; an empty part (a contact whose loads
// do not change with y) adds nothing.
void addPart(Eigen::MatrixXd& sum, const Eigen::MatrixXd& part) {
    if (part.size() == 0) return;
    if (sum.size() == 0)
        sum = part;
    else
        sum += part;
}

}  // namespace

Eigen::Matrix<double, 2, 6> CoupledNewtonScheme::actionGradient(const StepContext& ctx) const {
    // The equations of motion's right-hand side is affine in the film action (F_x, F_z, M_y).
    Eigen::Matrix<double, 2, 6> dForce = Eigen::Matrix<double, 2, 6>::Zero();
    const Eigen::Vector2d f0 = step_.dyn_.force(ctx.crank, ctx.gas, FilmAction{0.0, 0.0, 0.0});
    dForce.col(0) = step_.dyn_.force(ctx.crank, ctx.gas, FilmAction{1.0, 0.0, 0.0}) - f0;
    dForce.col(2) = step_.dyn_.force(ctx.crank, ctx.gas, FilmAction{0.0, 1.0, 0.0}) - f0;
    dForce.col(4) = step_.dyn_.force(ctx.crank, ctx.gas, FilmAction{0.0, 0.0, 1.0}) - f0;
    return dForce;
}

void CoupledNewtonScheme::linearizeCoupled(const StepContext& ctx, const Eigen::Vector2d& x, const StepEvaluation& ev) {
    // Each contact's load change with y; the motion rows through the film action (f is affine in
    // (F_x, F_z, M_y)), the modal rows as the contacts' modal loads (the bodies' response is applied
    // when the Jacobian is formed: it depends on the step size with bodies.response: dynamic).
    CoupledJacobianParts& P = parts_;
    Eigen::MatrixXd loadH, loadRate;
    P.modalH.resize(0, 0);
    P.modalRate.resize(0, 0);
    P.filmChangePerUnknown.resize(0);
    P.motionColumns = true;
    Eigen::MatrixXd loadX = Eigen::MatrixXd::Zero(6, 2);
    P.modalX = Eigen::MatrixXd::Zero(mp_ + ml_, 2);
    for (std::size_t c = 0; c < step_.contacts_.size(); ++c) {
        ContactJacobian J;
        step_.contacts_[c]->linearize(ctx.step, ctx.now->films[c], x, ev.films[c], J, step_.work_);
        addPart(loadH, J.loadH);
        addPart(loadRate, J.loadRate);
        addPart(P.modalH, J.modalH);
        addPart(P.modalRate, J.modalRate);
        P.motionColumns = P.motionColumns && J.motionColumns;
        addPart(loadX, J.loadX);
        addPart(P.modalX, J.modalX);
        if (J.filmChangePerUnknown.size() == 0) continue;
        P.filmChangePerUnknown = P.filmChangePerUnknown.size() == 0
                                     ? J.filmChangePerUnknown
                                     : Eigen::VectorXd(P.filmChangePerUnknown.cwiseMax(J.filmChangePerUnknown));
    }
    const fem::Stopwatch t0;
    const Eigen::Matrix<double, 2, 6> dForce = actionGradient(ctx);  // ∂f/∂(F, M)
    P.motionH = -dForce * loadH;
    P.motionRate = step_.case_.coupling.elasticSqueeze ? Eigen::MatrixXd(-dForce * loadRate) : Eigen::MatrixXd(2, 0);
    P.motionX = P.motionColumns ? Eigen::MatrixXd(-dForce * loadX) : Eigen::MatrixXd();
    P.valid = true;
    step_.work_.modal += t0.seconds();
}

Eigen::MatrixXd CoupledNewtonScheme::coupledJacobian(const StepContext& ctx) {
    const fem::Stopwatch t0;
    const CoupledJacobianParts& P = parts_;
    const int m = mp_ + ml_, k = 2 + m;
    const double rate = ctx.step.a0 / ctx.step.dt;
    const bool elasticRate = step_.case_.coupling.elasticSqueeze;
    // The modal columns, and the (e, β) columns where the contacts give them (else
    // formCoupledJacobian's differences).
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(k, k);
    J.topRightCorner(2, m) = elasticRate ? Eigen::MatrixXd(P.motionH + rate * P.motionRate) : P.motionH;
    // With the contacts' motion columns: the motion rows' (e, β) columns are the inertia's
    // (a0/Δt)² M and the film's part; the modal rows' the response to their modal load.
    const int first = P.motionColumns ? 0 : 2;
    if (P.motionColumns) J.topLeftCorner(2, 2) = rate * rate * step_.dyn_.mass(ctx.crank) + P.motionX;
    // Modal rows: δ_ij − ∂H/∂y_j, H linear in the mapped pressure (history terms held).
    auto respond = [&](const FlexibleBody& body, modal::ModalStepper* dynamics, int row, int rows) {
        Eigen::MatrixXd F(rows, k - first);
        if (P.motionColumns) F.leftCols(2) = P.modalX.middleRows(row - 2, rows);
        // The piston's inertia load at the iterate's (ë, β̈): ∂(ë, β̈)/∂(e, β) = (a0/Δt)² I.
        if (P.motionColumns && row == 2 && step_.pistonLoads_)
            F.leftCols(2) += rate * rate * step_.pistonLoads_->secondaryAccelerationColumns();
        F.rightCols(m) = P.modalH.middleRows(row - 2, rows);
        if (elasticRate) F.rightCols(m) += rate * P.modalRate.middleRows(row - 2, rows);
        if (dynamics) {
            Eigen::VectorXd q;
            for (int j = 0; j < k - first; ++j) {
                dynamics->loadResponse(F.col(j), q);
                J.block(row, first + j, rows, 1) = -q;
            }
        } else {
            Eigen::MatrixXd Q;
            body.quasiStatic(F, Q);
            J.block(row, first, rows, k - first) = -Q;
        }
    };
    if (step_.pistonBody_) respond(*step_.pistonBody_, step_.pistonDynamics_.get(), 2, mp_);
    if (step_.linerBody_) respond(*step_.linerBody_, step_.linerDynamics_.get(), 2 + mp_, ml_);
    J.bottomRightCorner(m, m).diagonal().array() += 1.0;
    step_.work_.modal += t0.seconds();
    return J;
}

bool CoupledNewtonScheme::formCoupledJacobian(const StepContext& ctx, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                                           const StepEvaluation& ev, const Eigen::Vector2d& delta, int& filmSolves) {
    Eigen::MatrixXd& J = newtonJacobian_;
    J = coupledJacobian(ctx);
    // Without the contacts' motion columns, the (e, β) columns by differences of full evaluations
    // (film solve and modal response): a rigid motion moves the Reynolds film's cavitation
    // boundary, whose effect its held-set linearisation misses — at high sliding and squeeze speeds
    // enough to stall Newton (docs/coupling.md §1).
    if (!parts_.motionColumns && !differenceColumns(ctx, x, y, ev, delta, J, filmSolves)) return false;
    newtonInverse_ = J.partialPivLu().inverse();
    // Unknowns in units of the film-thickness change they cause (Broyden norm, merit, damping).
    unknownScale_ = parts_.filmChangePerUnknown;
    for (Eigen::Index j = 0; j < unknownScale_.size(); ++j)
        unknownScale_[j] = unknownScale_[j] > 0.0 ? unknownScale_[j] : 1.0;
    // Without the elastic rate the quasi-static modal rows are algebraic: where the film's
    // stiffness on a combination of modes exceeds the structure's (det(I − ∂H/∂y) < 0), the skirt's
    // equilibrium in the film has folded away (docs/coupling.md §3); noted for the diagnosis.
    if (!step_.case_.coupling.elasticSqueeze && !step_.pistonDynamics_ && !step_.linerDynamics_ && mp_ + ml_ > 0) {
        const int m = mp_ + ml_;
        if (Eigen::MatrixXd(J.bottomRightCorner(m, m)).partialPivLu().determinant() < 0.0) ++step_.foldedJacobians_;
    }
    return true;
}

bool CoupledNewtonScheme::differenceColumns(const StepContext& ctx, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                                            const StepEvaluation& ev, const Eigen::Vector2d& delta, Eigen::MatrixXd& J,
                                            int& filmSolves) {
    std::array<StepEvaluation, 2> moved;
    if (!step_.perturbedMotion(ctx, x, y, delta, true, moved, filmSolves)) return false;
    for (int i = 0; i < 2; ++i) {
        J.block<2, 1>(0, i) = (moved[i].residual - ev.residual) / delta[i];
        J.col(i).tail(mp_ + ml_) = (ev.Hy - moved[i].Hy) / delta[i];
    }
    return true;
}

Eigen::VectorXd CoupledNewtonScheme::residualScale(const StepEvaluation& ev, double forceFloor, double reach,
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

double CoupledNewtonScheme::coupledMerit(const Eigen::VectorXd& F, const Eigen::VectorXd& residualScale) {
    if (!residualScale.allFinite()) return std::numeric_limits<double>::infinity();
    return 0.5 * F.cwiseQuotient(residualScale).squaredNorm();
}

Eigen::VectorXd CoupledNewtonScheme::levenbergMarquardtStep(const Eigen::VectorXd& F, const Eigen::VectorXd& rScale) const {
    const Eigen::VectorXd dzScale = step_.case_.piston.clearance * unknownScale_.cwiseInverse();
    const Eigen::MatrixXd Js = rScale.cwiseInverse().asDiagonal() * newtonJacobian_ * dzScale.asDiagonal();
    Eigen::MatrixXd N = Js.transpose() * Js;
    N.diagonal().array() += 1.0;
    return -(dzScale.asDiagonal() * N.llt().solve(Js.transpose() * F.cwiseQuotient(rScale)));
}

// Good Broyden update of the kept inverse Jacobian H for the update s and the residual change
// dF it caused, in the norm of the film-thickness change of s (Sherman–Morrison):
//   J₊ = J + (dF − J s) wᵀ/(wᵀ s),  w = D⁻² s  ⇔  H₊ = H + (s − H dF)(wᵀ H)/(wᵀ H dF).
void CoupledNewtonScheme::broydenUpdate(const Eigen::VectorXd& s, const Eigen::VectorXd& dF) {
    const Eigen::VectorXd w = s.cwiseProduct(unknownScale_).cwiseProduct(unknownScale_);
    const Eigen::VectorXd HdF = newtonInverse_ * dF;
    const double denom = w.dot(HdF);
    if (!(std::abs(denom) > 1e-12 * w.norm() * HdF.norm())) return;  // update undefined: keep H
    const Eigen::RowVectorXd wH = w.transpose() * newtonInverse_;
    newtonInverse_.noalias() += (s - HdF) * (wH / denom);
}

}  // namespace flexehd::cosim
