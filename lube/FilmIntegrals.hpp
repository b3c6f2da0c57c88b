#pragma once
// FilmIntegrals: loads, friction and flows of a solved film, integrated over the grid's
// control volumes (trapezoidal rule on the unwrapped cylinder; Void nodes excluded).
//
// Frame: the film frame of FilmGrid, node position r = (R cos θ, R sin θ, z), outward normal of
// the inner body e_r = (cos θ, sin θ, 0), e_θ = (−sin θ, cos θ, 0), e_z.
// All forces are those acting ON THE INNER BODY (piston, journal):
//   pressure  F_p = −∫ (p − p_amb) e_r dA
//   contact   F_c = −∫ p_c e_r dA                       (asperity pressure from GreenwoodTripp)
//   shear     F_s = ∫ τ dA,  τ = φ η (V_out − V_in)/h − (h/2) ∇p     (tangential, e_z/e_θ)
//   boundary  F_b = ∫ μ_b p_c (V_out − V_in)/|V_out − V_in| dA
// with φ the film fraction (1 unless given: Couette shear scales with it in cavitated zones).
// The moment is that of all four about the given reference point.
// The outer body (liner, sleeve) feels the shear τ_out = −φ η (V_out − V_in)/h − (h/2) ∇p
// (the Couette part opposite, the Poiseuille part the same as on the inner body) and −F_b.
// Viscous dissipation Φ = ∫ [φ η |V_out − V_in|²/h + h³|∇p|²/(12η)] dA is frame-invariant and
// never negative; with the boundary friction power it is the power the contact loses
// (docs/results-format.md, "Friction").
#include <Eigen/Core>

#include "lube/FilmGrid.hpp"
#include "lube/FilmState.hpp"
#include "lube/Lubricant.hpp"

namespace flexehd::lube {

struct FilmIntegralOptions {
    Eigen::Vector3d referencePoint = Eigen::Vector3d::Zero();  ///< moment point (film frame, m)
    double cavitationPressure = 0.0;   ///< a Film node with p ≤ p_cav counts as cavitated
    double boundaryFriction = 0.0;     ///< μ_b of the asperity contact
    const Eigen::VectorXd* contactPressure = nullptr;  ///< p_c per node (Pa) or nullptr
    const Eigen::VectorXd* filmFraction = nullptr;     ///< φ per node in [0,1] or nullptr (= 1)
    /// m, composite rms roughness σ of the Couette shear's stress factor φ_f(h/σ)
    /// (ShearStressFactor, Patir & Cheng 1979); 0: smooth surfaces (φ_f = 1)
    double roughness = 0.0;
};

struct FilmLoads {
    Eigen::Vector3d pressureForce = Eigen::Vector3d::Zero();         ///< N
    Eigen::Vector3d contactForce = Eigen::Vector3d::Zero();          ///< N
    Eigen::Vector3d shearForce = Eigen::Vector3d::Zero();            ///< N
    Eigen::Vector3d boundaryFrictionForce = Eigen::Vector3d::Zero(); ///< N
    /// N, hydrodynamic shear on the OUTER body (the liner: what a floating-liner rig measures
    /// of the film); its boundary friction is −boundaryFrictionForce
    Eigen::Vector3d outerShearForce = Eigen::Vector3d::Zero();
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();  ///< N·m, all forces, about referencePoint
    double viscousDissipation = 0.0;      ///< W
    double boundaryFrictionPower = 0.0;   ///< W: ∫ μ_b p_c |V_out − V_in| dA
    double contactLoad = 0.0;             ///< N: ∫ p_c dA
    double minFilm = 0.0;                 ///< m, over non-Void nodes
    double maxPressure = 0.0;             ///< Pa, absolute
    double cavitatedArea = 0.0;           ///< m², Film nodes with p ≤ p_cav
    double filmArea = 0.0;                ///< m², all non-Void nodes

    Eigen::Vector3d frictionForce() const { return shearForce + boundaryFrictionForce; }
    /// W, ≥ 0: viscous dissipation + boundary friction power
    double dissipatedPower() const { return viscousDissipation + boundaryFrictionPower; }
    Eigen::Vector3d totalForce() const {
        return pressureForce + contactForce + shearForce + boundaryFrictionForce;
    }
};

FilmLoads integrateFilm(const FilmGrid& grid, const FilmState& film, const Lubricant& lubricant,
                        const Eigen::VectorXd& pressure, const FilmIntegralOptions& options = {});

/// Volumetric flow (m³/s) in +θ through the line between columns j and j+1 (periodic wrap),
/// summed over the axial extent: the same face fluxes as the finite-volume scheme.
double circumferentialFlow(const FilmGrid& grid, const FilmState& film,
                           const Lubricant& lubricant, const Eigen::VectorXd& pressure, int j,
                           const Eigen::VectorXd* filmFraction = nullptr);
/// Volumetric flow (m³/s) in +z through the line between rows i and i+1.
double axialFlow(const FilmGrid& grid, const FilmState& film, const Lubricant& lubricant,
                 const Eigen::VectorXd& pressure, int i,
                 const Eigen::VectorXd* filmFraction = nullptr);

/// Volumetric flow (m³/s) in +z through the grid's low (Edge::AxialLow) or high
/// (Edge::AxialHigh) end, summed over the columns: each column's face fluxes of its first two
/// faces inside the end, extrapolated linearly to the end (second order; the face flux half a
/// cell inside misses what the edge cells take in from the sides, e.g. from a supply groove).
/// Needs at least 3 rows.
double axialEdgeFlow(const FilmGrid& grid, const FilmState& film, const Lubricant& lubricant,
                     const Eigen::VectorXd& pressure, Edge edge, const Eigen::VectorXd* filmFraction = nullptr);

}  // namespace flexehd::lube
