#pragma once
// Modal superposition on a reduced body: displacements u = Φ q anywhere on the mesh,
// modal forces Φᵀ f, and the quasi-static and dynamic modal responses.
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "modal/ReducedBody.hpp"

namespace flexehd::modal {

/// Orthonormal basis N (modes × free coordinates) of the modal coordinates that leave the
/// reference nodes of the `held` interfaces at rest (their six motions A q = 0): q = N r.
/// Identity when nothing is held. Throws std::invalid_argument for an unknown interface index.
Eigen::MatrixXd heldBasis(const ReducedBody& body, const std::vector<int>& held);
/// The factorized stiffness Nᵀ K_r N on a held basis N (N.cols() > 0). Throws
/// std::runtime_error if the held body can still move rigidly (a zero-frequency free coordinate).
Eigen::LDLT<Eigen::MatrixXd> heldStiffness(const ReducedBody& body, const Eigen::MatrixXd& N);
/// The natural frequencies (Hz, ascending) of the body with the `held` interfaces' reference nodes
/// at rest: the eigenvalues of (Nᵀ K_r N, Nᵀ M_r N) — what the body vibrates at in a run that
/// holds them. Throws std::runtime_error if the held body can still move rigidly.
Eigen::VectorXd heldFrequenciesHz(const ReducedBody& body, const std::vector<int>& held);
/// The frequency (Hz) up to which the body's basis holds every fixed-interface normal mode: the
/// reduction's cut-off (`--cutoff`) where it had one, else the highest fixed-interface normal mode
/// it kept (`--modes N`): the N-th frequency with every interface held, as those modes are exact
/// eigenvectors of the held body and so its lowest Ritz values (docs/modal.md, "Command line"); without
/// interfaces the N-th of the body's own frequencies; 0 without normal modes. Above it the basis
/// misses modes, so a vibration record is refused beyond it.
double normalModesUpToHz(const ReducedBody& body);

class ModalSuperposition {
public:
    explicit ModalSuperposition(const ReducedBody& body);

    /// Full displacement vector (3·nodes), m.
    Eigen::VectorXd displacement(const Eigen::VectorXd& q) const;
    /// Displacements of selected nodes (3 x nodes.size()), m.
    Eigen::Matrix3Xd displacementAt(const std::vector<fem::Index>& nodes, const Eigen::VectorXd& q) const;
    /// Modal forces Φᵀ f from nodal forces f (3·nodes), N.
    Eigen::VectorXd modalForce(const Eigen::VectorXd& nodalForce) const;
    /// Quasi-static response K_r q = Φᵀ f with the reference nodes of `heldInterfaces` held
    /// (their six motions zero, enforced exactly by eliminating them from q). Throws if
    /// the body can still move rigidly.
    Eigen::VectorXd quasiStatic(const Eigen::VectorXd& modalForce, const std::vector<int>& heldInterfaces) const;
    /// The quasi-static compliance C = N (Nᵀ K_r N)⁻¹ Nᵀ (modes × modes): quasiStatic(f) = C f.
    Eigen::MatrixXd compliance(const std::vector<int>& heldInterfaces) const;

private:
    const ReducedBody& body_;
};

/// Dynamic modal response M_r q̈ + C_r q̇ + K_r q = Φᵀ f with M_r = I, K_r = diag(ω²),
/// C_r = diag(2ζω): each mode integrated by the implicit trapezoidal (Newmark average
/// acceleration) rule, unconditionally stable and energy-conserving without damping. Modal
/// damping only: throws std::invalid_argument for a body with damper supports
/// (ReducedBody::supportDamping), whose coupling a mode-by-mode rule cannot carry.
class ModalDynamics {
public:
    ModalDynamics(const ReducedBody& body, double timeStep);
    /// Advances one step to the force at the end of the step.
    void step(const Eigen::VectorXd& modalForce);
    const Eigen::VectorXd& q() const { return q_; }
    const Eigen::VectorXd& velocity() const { return v_; }
    const Eigen::VectorXd& acceleration() const { return a_; }
    void setState(const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& force);

private:
    double dt_;
    Eigen::VectorXd omega2_, c_, q_, v_, a_;
};

}  // namespace flexehd::modal
