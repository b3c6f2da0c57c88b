// CoupledNewtonScheme: a pass of the coupled Newton method (docs/coupling.md §1) — the line
// search, the Jacobian kept, re-formed or Broyden-updated, the damped update of (e, β, y) and the
// test of convergence to the resolution of the unknowns; the Jacobian is CoupledNewton.cpp's.
#include "cosim/coupling/CoupledNewtonScheme.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "cosim/coupling/StepSolver.hpp"

namespace flexehd::cosim {

CoupledNewtonScheme::CoupledNewtonScheme(StepSolver& step) : step_(step), mp_(step.mp_), ml_(step.ml_) {}

void CoupledNewtonScheme::beginStep(const Eigen::Vector2d& x, const Eigen::VectorXd& y) {
    iterate_ = NewtonIterate{};
    if (!step_.case_.coupling.keepJacobian) parts_.valid = false;  // a new linearisation every step
    iterate_.acceptedX = x;
    iterate_.acceptedY = y;
}

Eigen::VectorXd CoupledNewtonScheme::givenLoadChange(const Eigen::VectorXd& dH) const {
    const Eigen::Index m = mp_ + ml_;
    if (!parts_.valid || dH.size() != m || newtonInverse_.rows() != 2 + m || newtonInverse_.cols() != 2 + m) return {};
    return newtonInverse_.rightCols(m) * dH;
}

CouplingScheme::PassOutcome CoupledNewtonScheme::pass(const StepContext& ctx, const StepTolerances& tol, int /*pass*/,
                                                      const StepEvaluation& ev, const CouplingResidual& couplingRes,
                                                      Eigen::Vector2d& x, Eigen::VectorXd& y, int& iterations,
                                                      Eigen::Vector2d& dx, bool& resolved, std::string& why) {
    dz_.resize(0);
    resolved = false;
    const PassOutcome outcome =
        coupledNewtonPass(ctx, tol, ev, couplingRes, iterate_, x, y, iterations, dz_, resolved, why);
    if (outcome == PassOutcome::Update) dx = dz_.head<2>();
    return outcome;
}

void CoupledNewtonScheme::update(const StepEvaluation& /*ev*/, const Eigen::Vector2d& dx, Eigen::Vector2d& x,
                                 Eigen::VectorXd& y) {
    x += dx;
    y += dz_.tail(mp_ + ml_);
}

CouplingScheme::PassOutcome CoupledNewtonScheme::coupledNewtonPass(const StepContext& ctx, const StepTolerances& tol,
                                                                   const StepEvaluation& ev,
                                                                   const CouplingResidual& couplingRes,
                                                                   NewtonIterate& it, Eigen::Vector2d& x,
                                                                   Eigen::VectorXd& y, int& iterations,
                                                                   Eigen::VectorXd& dz, bool& resolved,
                                                                   std::string& why) {
    const double forceFloor = tol.forceFloor, reach = tol.reach, couplingTol = tol.coupling;
    Eigen::VectorXd F(2 + mp_ + ml_);
    F.head<2>() = ev.residual;
    F.tail(mp_ + ml_) = y - ev.Hy;
    // Line search: a pass whose merit (coupledMerit) is worse than the largest of the last three
    // accepted iterates' (a non-monotone line search: Grippo, Lampariello & Lucidi 1986; where
    // the cavitated or contact set changes, a Newton update that reaches the solution may first
    // raise the merit) goes back to the last accepted iterate — to linearise anew when the
    // Jacobian was a kept one, else to halve the update (at most 5 times; the film and contact
    // laws are strongly nonlinear there). The pass that revisits the accepted iterate is not
    // tested: its film solve differs from the first one there by the film solver's tolerance.
    Eigen::VectorXd rScale = residualScale(ev, forceFloor, reach, couplingTol);
    if (!it.revisit && it.accepted > 0 && coupledMerit(F, rScale) > it.meritReference()) {
        if (!it.freshJacobian) {
            // The kept Jacobian led astray: back to the accepted iterate, linearised anew.
            x = it.acceptedX;
            y = it.acceptedY;
            parts_.valid = false;
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
    // The residual in units of its tolerances (≤ 1: converged).
    const double measure = couplingRes.measure(couplingTol, tol.motionMeasure(ev));
    const double rate = ctx.step.a0 / ctx.step.dt;
    // A new linearisation when two passes in a row did not halve the measure (the first gets the
    // Broyden update of the kept Jacobian: near the solution a stale Jacobian's error dominates
    // the residual, and one secant update corrects it for less than a new linearisation costs),
    // or when the update had to backtrack; a step-size change alone re-forms the Jacobian from
    // the kept parts (affine in the rate); otherwise the kept inverse, Broyden-updated.
    if (it.backtracks > 0 && it.freshJacobian) {
        it.regularize = true;  // see below
        // A fresh Jacobian whose update had to backtrack: its (e, β) columns, forward differences
        // over 1e-5 of (c_r, c_r/reach), may be secants across a kink of the film's response (where
        // the skirt rides on its asperities with almost no side force, a squeeze-pressure region
        // that vanishes within half such a step as the skirt lifts off) and miss the slope at the
        // iterate severalfold, so that the update is no descent direction at all. The step's later
        // Jacobians difference over 1e-7 (docs/coupling.md §1).
        it.differenceStep = 1e-7;
    }
    const bool notHalved = measure > 0.5 * it.acceptedMeasure;
    const bool relinearize = !parts_.valid || it.backtracks > 0 || (notHalved && it.stalled);
    it.stalled = notHalved && !relinearize;
    if (!parts_.valid) it.acceptedMeasure = std::numeric_limits<double>::infinity();
    if (relinearize) {
        try {
            linearizeCoupled(ctx, x, ev);
        } catch (const std::runtime_error& e) {
            parts_.valid = false;
            why = std::string("the film's linearisation for the coupled Newton step failed: ") + e.what();
            return PassOutcome::Failed;
        }
        ++step_.work_.jacobians;
    }
    if (relinearize || rate != newtonRate_) {
        if (!formCoupledJacobian(ctx, x, y, ev, it.differenceStep * tol.motion, iterations)) {
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
    std::copy_backward(it.recentMerits.begin(), it.recentMerits.end() - 1, it.recentMerits.end());
    it.recentMerits.front() = coupledMerit(F, rScale);
    ++it.accepted;
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
    if (largest > 0.25 * step_.case_.piston.clearance) dz *= 0.25 * step_.case_.piston.clearance / largest;
    return PassOutcome::Update;
}

bool CoupledNewtonScheme::resolvedToTheUnknownsResolution(const StepTolerances& tol, const StepEvaluation& ev,
                                                          const CouplingResidual& couplingRes,
                                                          const Eigen::VectorXd& dz) const {
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
    return motionResolved && dz.cwiseAbs().dot(unknownScale_) <= 1e-5 * step_.case_.piston.clearance &&
           std::abs(dz[0]) <= resolution[0] && std::abs(dz[1]) <= resolution[1] && couplingRes.atMost(tol.coupling);
}

}  // namespace flexehd::cosim
