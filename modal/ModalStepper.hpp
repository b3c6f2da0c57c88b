#pragma once
// ModalStepper: the dynamic response of a held reduced body over one time step, as the
// co-simulation's step iteration uses it (bodies.response: dynamic). Every integrator of the
// modal equations M_r q̈ + C_r q̇ + K_r q = f is, over one step, affine in the modal force at the
// step's end:
//
//   q₊ = G f₊ + q_free,   q̇₊ = G_v f₊ + q̇_free,
//
// with G (the step's dynamic compliance) fixed by the step size and q_free by the state the
// step starts from. beginStep prepares both once per step; respond applies them to each
// iterate's force; loadResponse applies G alone (the coupled Newton's Jacobian columns).
// Implementations: HeldModalDynamics (BDF2) and ModalPropagator (exact for a force linear
// over the step); docs/modal.md, "Superposition and response".
#include <Eigen/Core>

namespace flexehd::modal {

/// The state a step starts from and the step's size and BDF2 coefficients (docs/coupling.md §2).
struct ModalStepStart {
    double dt = 0.0;                      ///< s
    double a0 = 1.0, a1 = -1.0, a2 = 0.0;  ///< BDF2: ẏ₊ = (a0 y₊ + a1 yₙ + a2 yₙ₋₁)/Δt
    Eigen::VectorXd y, yBefore;           ///< m: yₙ, yₙ₋₁
    Eigen::VectorXd w, wBefore;           ///< m/s: ẏₙ, ẏₙ₋₁
    Eigen::VectorXd f;                    ///< N: the modal force at yₙ (empty: zero)
};

class ModalStepper {
public:
    virtual ~ModalStepper() = default;
    virtual int modes() const = 0;
    /// Prepares the step (its compliance, refactored only when the step size changes, and the
    /// free response of its start state).
    virtual void beginStep(const ModalStepStart& start) = 0;
    /// q₊ for the modal force f₊ at the step's end.
    virtual void respond(const Eigen::VectorXd& f, Eigen::VectorXd& q) const = 0;
    /// G f: the part of q₊ the end force makes (the start state's part left out).
    virtual void loadResponse(const Eigen::VectorXd& f, Eigen::VectorXd& q) const = 0;
    /// q̇₊ of the step that ends at q₊ = respond(f): BDF2 takes it from q (the accepted iterate),
    /// the exact propagator from f alone (the response respond(f) gives, which the accepted
    /// iterate matches to the coupling tolerance).
    virtual Eigen::VectorXd velocity(const Eigen::VectorXd& q, const Eigen::VectorXd& f) const = 0;
};

}  // namespace flexehd::modal
