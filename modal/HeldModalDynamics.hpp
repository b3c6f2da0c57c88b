#pragma once
// HeldModalDynamics: the dynamic response of a reduced body whose held interfaces' reference
// nodes are at rest (the piston's pin bore, the liner's seats; the bodies' rigid motion is the
// secondary motion's, not the modes'), integrated by BDF2 with the caller's step coefficients.
//
//   M_r q̈ + C_r q̇ + K_r q = f,   q = N r   (N = heldBasis: the held reference motions vanish),
//   M_r = I, K_r = diag(ω²), C_r = diag(2 ζ ω) + D_s   (the reduced body's orthonormal basis, modal
//   damping and the damper supports' projected dashpots, modal::bodyDampingMatrix)
//
// BDF2 (variable step): q̇₊ = (a0 q₊ + hq)/Δt, q̈₊ = (a0 q̇₊ + hv)/Δt with the histories
// hq = a1 qₙ + a2 qₙ₋₁, hv = a1 q̇ₙ + a2 q̇ₙ₋₁ — the same coefficients as the piston's secondary
// motion (docs/dynamics.md), so the whole system is one BDF2 scheme. Substituted, each step is the
// linear system
//   Nᵀ S N r = Nᵀ [f − M (a0 hq/Δt² + hv/Δt) − C hq/Δt],   S = (a0/Δt)² M + (a0/Δt) C + K,
// whose matrix is factored once per distinct a0/Δt (the step size control keeps it constant
// over most steps). BDF2 is L-stable: modes far above 1/Δt are damped numerically and answer
// quasi-statically, the low ones with their inertia and damping. As Δt → ∞ (slow loading) the
// response tends to the quasi-static one, N (Nᵀ K N)⁻¹ Nᵀ f.
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "modal/ModalStepper.hpp"
#include "modal/ReducedBody.hpp"

namespace flexehd::modal {

class HeldModalDynamics final : public ModalStepper {
public:
    /// held: interface indices whose reference nodes are at rest. Throws std::runtime_error if
    /// the held body can still move rigidly (a zero-frequency free coordinate).
    HeldModalDynamics(const ReducedBody& body, const std::vector<int>& held);

    int modes() const override { return int(N_.rows()); }
    /// BDF coefficient a0 and step Δt (s) of the coming step; refactors when a0/Δt changes.
    void setStep(double a0, double dt);
    /// q₊ for the modal force f (N) and the histories hq = a1 qₙ + a2 qₙ₋₁ (m), hv = a1 q̇ₙ + a2 q̇ₙ₋₁ (m/s).
    void respond(const Eigen::VectorXd& f, const Eigen::VectorXd& hq, const Eigen::VectorXd& hv,
                 Eigen::VectorXd& q) const;
    /// q̇₊ = (a0 q₊ + hq)/Δt of the current step.
    Eigen::VectorXd bdf2Velocity(const Eigen::VectorXd& q, const Eigen::VectorXd& hq) const { return (a0_ * q + hq) / dt_; }

    /// ModalStepper: the BDF2 step with the histories hq = a1 yₙ + a2 yₙ₋₁, hv = a1 ẏₙ + a2 ẏₙ₋₁.
    void beginStep(const ModalStepStart& start) override;
    void respond(const Eigen::VectorXd& f, Eigen::VectorXd& q) const override { respond(f, hq_, hv_, q); }
    void loadResponse(const Eigen::VectorXd& f, Eigen::VectorXd& q) const override;
    Eigen::VectorXd velocity(const Eigen::VectorXd& q, const Eigen::VectorXd& /*f*/) const override {
        return bdf2Velocity(q, hq_);
    }

private:
    Eigen::MatrixXd N_, Mn_, Cn_, Kn_;  // free basis; M, C, K projected on it
    Eigen::MatrixXd M_, C_;            // in modal coordinates (history terms)
    double a0_ = 0.0, dt_ = 0.0, rate_ = -1.0;  // rate_ = a0/Δt of the factorization
    Eigen::LLT<Eigen::MatrixXd> llt_;
    Eigen::VectorXd hq_, hv_;  // the current step's histories (beginStep)
};

}  // namespace flexehd::modal
