#pragma once
// PistonDynamics: the equations of the piston's secondary motion (docs/dynamics.md §2, derived
// there from the free-body diagrams of piston, pin and a massless connecting rod).
//
// Coordinates: e, the lateral shift of the pin axis (+x, major thrust side), and β, the tilt of
// the piston about the pin axis (+y; β > 0 moves the top of the piston towards +x). The primary
// (axial) motion Z(t) of the pin is prescribed by CrankKinematics. With A = Z̈ + g,
//   [m_p + m_pin        m_p (z_g + x_g tan ψ)] [ë]   [F_x + tan ψ ((m_p + m_pin) A + F_g − F_z)]
//   [m_p z_g            I_g + m_p (x_g² + z_g²)] [β̈] = [M_y − c F_g + m_p x_g A                  ]
// F_g = (p_cyl − p_crankcase) π D²/4 pushes the crown down along the piston axis (which lies at
// x = −c from the pin); F_x, F_z, M_y are the film's force on the piston (pressure, asperity
// contact, friction) in the cylinder frame and its moment about the pin axis; (x_g, z_g) the
// CG of the piston (without pin) relative to the pin axis; I_g its rotary inertia about the CG.
// The rod force follows from the axial balance: F_R cos ψ = (m_p + m_pin) A − m_p x_g β̈ + F_g − F_z,
// and its lateral component F_R sin ψ on the pin is the side force.

#include "cosim/engine/CrankKinematics.hpp"
#include "cosim/case/EngineCase.hpp"

#include <Eigen/Core>

namespace flexehd::cosim {

/// The film's action on the piston: force (N, cylinder frame) and moment about the pin axis
/// (N·m, about +y).
struct FilmAction {
    double fx = 0.0;
    double fz = 0.0;
    double my = 0.0;
};

class PistonDynamics {
public:
    /// Throws std::invalid_argument unless the piston mass and inertia are > 0 and the pin mass ≥ 0.
    PistonDynamics(const PistonSpec& piston, const EngineSpec& engine, double gravity = 9.81);

    /// M(ψ): the (non-symmetric) mass matrix of the equations above.
    Eigen::Matrix2d mass(const CrankState& crank) const;
    /// Right-hand side f for the net gas force F_g (N, > 0 pushing the piston down) and the film.
    Eigen::Vector2d force(const CrankState& crank, double gasForce, const FilmAction& film) const;
    /// Lateral force of the rod on the pin, F_R sin ψ (N), for the tilt acceleration β̈.
    double sideForce(const CrankState& crank, double gasForce, const FilmAction& film,
                     double tiltAcceleration) const;
    /// Kinetic energy of the secondary motion (J), v = (ė, β̇): ½ m_pin ė² + ½ m_p |v_G|² + ½ I_g β̇² with
    /// v_G = (ė + z_g β̇, −x_g β̇) the CG velocity relative to the primary motion, i.e.
    /// ½ (m_p + m_pin) ė² + m_p z_g ė β̇ + ½ [I_g + m_p (x_g² + z_g²)] β̇² = ½ vᵀ M(ψ = 0) v.
    double kineticEnergy(double lateralVelocity, double tiltRate) const;
    /// The gravity the equations carry (m/s², along −z): A = Z̈ + g.
    double gravity() const { return g_; }
    /// Net gas force (N) for the absolute cylinder pressure p (Pa).
    double gasForce(double cylinderPressure) const;

private:
    double mp_, mpin_, ig_, xg_, zg_, c_, area_, pcc_, g_;
};

}  // namespace flexehd::cosim
