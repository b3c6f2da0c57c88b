#pragma once
// ModalPropagator: the dynamic response of a held reduced body by the exact solution of its modal
// equations over a step along which the modal force is linear in time (the piecewise-exact
// method of Nigam & Jennings 1969; Chopra, Dynamics of Structures, §5.2, for one mode).
//
//   M_r q̈ + C_r q̇ + K_r q = f(t),  q = N r (N = heldBasis),  f(t_n + s) = fₙ + (f₊ − fₙ) s/Δt.
//
// On the free coordinates, mass-normalised (r = Ψ u, Ψᵀ Mₙ Ψ = I, Ψᵀ Kₙ Ψ = Ω²) and scaled
// (x = [Ω u; u̇]), the equations are ẋ = A x + B f with A = [[0, Ω], [−Ω, −Ψᵀ Cₙ Ψ]], whose
// eigenvalues λ_j (the damped modes, modal damping need not be proportional) diagonalise it once:
// A = V Λ V⁻¹. Over a step of Δt, with z = V⁻¹ x,
//
//   z(τ) = e^{λτ} zₙ + τ φ₁(λτ) V⁻¹B fₙ + (τ²/Δt) φ₂(λτ) V⁻¹B (f₊ − fₙ),
//   φ₁(z) = (eᶻ − 1)/z,  φ₂(z) = (eᶻ − 1 − z)/z²,
//
// exact at every τ in [0, Δt], for every mode however high above 1/Δt: a mode rings with its own
// frequency and damping at any step size, where BDF2 damps the modes its step does not resolve
// numerically and shifts their phase. What the step size still limits is how well the linear
// force follows the real one. Each step costs products of the 2n_f × m maps; a new step size
// costs one (m × 2n_f)(2n_f × m) product for the compliance G.
#include <complex>
#include <vector>

#include <Eigen/Core>

#include "modal/ModalStepper.hpp"
#include "modal/ReducedBody.hpp"

namespace flexehd::modal {

class ModalPropagator final : public ModalStepper {
public:
    /// held: interface indices whose reference nodes are at rest. Throws std::runtime_error if the
    /// held body can still move rigidly, or if its damped modes are not independent (a mode
    /// damped exactly critically).
    ModalPropagator(const ReducedBody& body, const std::vector<int>& held);

    int modes() const override { return int(outQ_.rows()); }
    /// The step from (yₙ, ẏₙ) under the force fₙ at its start (start.f); the BDF2 coefficients
    /// are not used.
    void beginStep(const ModalStepStart& start) override;
    void respond(const Eigen::VectorXd& f, Eigen::VectorXd& q) const override;
    void loadResponse(const Eigen::VectorXd& f, Eigen::VectorXd& q) const override;
    Eigen::VectorXd velocity(const Eigen::VectorXd& q, const Eigen::VectorXd& f) const override;

    /// The modal coordinates q(t_n + τ) and velocities q̇(t_n + τ) at each τ of `taus` (s, in
    /// [0, Δt]) within the step from (q, q̇) = (y, w) under the force going linearly from fStart to
    /// fEnd over dt; one column per τ (modes × taus). Independent of beginStep.
    void responseWithin(const Eigen::VectorXd& y, const Eigen::VectorXd& w, const Eigen::VectorXd& fStart,
                        const Eigen::VectorXd& fEnd, double dt, const std::vector<double>& taus,
                        Eigen::MatrixXd& displacement, Eigen::MatrixXd& velocity) const;
    /// The work ∫ fᵀ q̇ dt (J) the force, linear from fStart to fEnd over dt, does on the body over
    /// the step from (y, w), exactly: f₊ᵀq₊ − fₙᵀqₙ − ((f₊ − fₙ)/Δt)ᵀ ∫ q dt by parts, with ∫ z dt =
    /// Δt φ₁ zₙ + Δt² φ₂ V⁻¹B fₙ + Δt³ φ₃ V⁻¹B (f₊ − fₙ)/Δt, φ₃(z) = (eᶻ − 1 − z − z²/2)/z³.
    /// yEnd: q at the step's end (from responseWithin).
    double workOver(const Eigen::VectorXd& y, const Eigen::VectorXd& w, const Eigen::VectorXd& fStart,
                    const Eigen::VectorXd& fEnd, double dt, const Eigen::VectorXd& yEnd) const;
    /// The damped modes' eigenvalues λ (1/s; ω_d = Im λ, ζω = −Re λ).
    const Eigen::VectorXcd& eigenvalues() const { return lambda_; }
    /// The modal dashpots c_k = 2 ζ_k √K_kk (N·s/m per unit modal coordinate), the diagonal part
    /// diag(c) of the damping the equations carry.
    const Eigen::VectorXd& damping() const { return damping_; }
    /// The damping the equations carry in the body's modal coordinates q, C = diag(c) + D_s with
    /// D_s the damper supports' projected dashpots (ReducedBody::supportDamping; none: C = diag(c));
    /// the damping block of A is Ψᵀ Nᵀ C N Ψ, and the rate at which it takes energy is q̇ᵀ C q̇ (W).
    const Eigen::MatrixXd& dampingMatrix() const { return dampingMatrix_; }
    /// Whether C has the damper supports' coupling (is not diagonal).
    bool coupledDamping() const { return coupled_; }

private:
    Eigen::VectorXcd startModes(const Eigen::VectorXd& y, const Eigen::VectorXd& w) const;

    Eigen::VectorXd damping_;                 // c (m)
    Eigen::MatrixXd dampingMatrix_;           // C = diag(c) + D_s (m × m)
    bool coupled_ = false;                    // D_s present
    Eigen::VectorXcd lambda_;                 // 2n_f eigenvalues of A
    Eigen::MatrixXcd inQ_, inV_, inF_;        // z = inQ q + inV q̇;  V⁻¹B (2n_f × m)
    Eigen::MatrixXcd outQ_, outV_;            // q = Re(outQ z), q̇ = Re(outV z)  (m × 2n_f)
    // The current step: its size, compliance (q and q̇ rows) and free response.
    double dt_ = -1.0;
    Eigen::MatrixXd G_, Gv_;
    Eigen::VectorXd qFree_, vFree_;
};

}  // namespace flexehd::modal
