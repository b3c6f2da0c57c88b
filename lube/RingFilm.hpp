#pragma once
// RingFilm: the oil film between a piston ring's running face and the liner, axisymmetric — the
// Reynolds equation across the face (axial x) with the Reynolds (Swift–Stieber) cavitation
// condition, the gas pressures below and above the ring at the face's edges (docs/lube.md §9):
//
//   d/dx (h³/(12η) dp/dx) = (U/2) dh/dx + ∂h/∂t,   h(x) = h_min + drop(x),   p ≥ p_cav,
//
// U the liner's axial speed relative to the ring (positive towards the crown) and ∂h/∂t the
// ring's radial squeeze rate (the whole face moves with h_min). Finite volumes on uniform nodes
// across the face (the conductances and Couette fluxes of ReynoldsSystem, in one dimension); the
// load and the friction are per unit length of the ring's circumference. Flooded: the Reynolds
// condition, the complementarity problem solved by a primal–dual active set on the tridiagonal
// system (a direct solve per partition). Fed by the liner's oil layer: mass-conserving (JFO, the
// scheme of lube::JfoSolver in one dimension: the Couette flux carried by the upwind node's film
// fraction), its full-film / cavitated partition solved the same way (a tridiagonal solve per
// partition); steady (the squeeze rate must be 0) or a backward-Euler step.
#include <Eigen/Core>

#include <limits>
#include <vector>

#include "lube/Lubricant.hpp"
#include "lube/RingFaceProfile.hpp"
#include "lube/ShearStressFactor.hpp"

namespace flexehd::lube {

struct RingFilmState {
    double minimumGap = 0.0;     ///< h_min (m, > 0)
    double slidingSpeed = 0.0;   ///< U: the liner's axial speed relative to the ring (m/s, + towards the crown)
    double squeezeRate = 0.0;    ///< ∂h_min/∂t (m/s, < 0 closing)
    double pressureBelow = 0.0;  ///< gauge pressure at the face's lower edge (Pa)
    double pressureAbove = 0.0;  ///< gauge pressure at the face's upper edge (Pa)
    /// The oil layer the liner carries into the face (m, ≥ 0; NaN: flooded, the Reynolds
    /// condition). Given, the film is mass-conserving (JFO): the leading edge takes in the
    /// layer's flux U t, the film fraction φ < 1 where the film is partial; steady (solve) or a
    /// backward-Euler step of its content from the last step's film fraction (step).
    double supplyFilm = std::numeric_limits<double>::quiet_NaN();
    /// The minimum gap the Couette shear sees (m; NaN: minimumGap): the separation of the rough
    /// surfaces' mean planes where the film is solved at a floor above it (≤ 0: they overlap).
    double nominalGap = std::numeric_limits<double>::quiet_NaN();
    /// Whether the solve computes the friction too (false: pressure, load and flows only, the
    /// friction left 0 for RingFilm::addFriction).
    bool withFriction = true;
};

struct RingFilmResult {
    Eigen::VectorXd x, h, p;  ///< across the face: position (m), film thickness (m), pressure (Pa)
    Eigen::VectorXd fraction; ///< film fraction φ across the face (1 with the Reynolds condition)
    double oil = 0.0;         ///< mass-conserving: the film's oil ∫ φ h dx per unit circumference (m²)
    double inflow = 0.0;      ///< mass-conserving: net flow into the film at its edges per unit circumference (m²/s)
    /// mass-conserving: the flow into the film per unit circumference (m²/s, + into the film)
    /// through the lower edge (x = profile.lower()) and the upper one; inflow is their sum
    double inflowLow = 0.0, inflowHigh = 0.0;
    /// mass-conserving step: the face is open to the gas (docs/lube.md §9) — its film partial from
    /// edge to edge between two different gases, or unable to hold the higher one within the step
    /// — and the gas passing it pushes the oil streaks
    bool openToGas = false;
    double load = 0.0;        ///< ∫ p dx: the film's radial force per unit circumference (N/m)
    double friction = 0.0;    ///< the film's axial shear force on the ring per unit circumference (N/m)
};

/// The gap a face's oil leaves open to the gas (docs/ring-pack.md, "Gas past a face on the oil
/// layer"): the open height h_o = (1 − φ) h at each node across the face (at the edges with the
/// fraction of the node next to them: the edges' own are the boundary's), its resistance
/// ∫ dx/h_o³ (m⁻², trapezoidal over the nodes; +∞ where the oil fills the gap at some node: no
/// path) and the narrowest h_o (m). A flooded film (φ = 1) has none.
struct OpenGap {
    double resistance = std::numeric_limits<double>::infinity();
    double narrowest = 0.0;
};
OpenGap openGap(const RingFilmResult& r);

class RingFilm {
public:
    /// nodes across the face (≥ 5); a constant-property lubricant (its reference viscosity);
    /// roughness: the composite rms σ of face and liner for the Couette shear's stress factor
    /// (lube::ShearStressFactor; 0: smooth surfaces).
    RingFilm(RingFaceProfile profile, Lubricant lubricant, int nodes = 201, double cavitationPressure = 0.0,
             double roughness = 0.0);

    /// Throws std::invalid_argument on a non-positive gap or non-finite input, std::runtime_error
    /// when the film solve fails. cavitated: the nodes held at the cavitation pressure (flooded
    /// film), or cavitated with a partial film (mass-conserving), the solve's start where it has
    /// one flag per node (e.g. the last solve's; else none) and its outcome on return — the
    /// solution is the same, found in fewer passes from a near one.
    RingFilmResult solve(const RingFilmState& s, std::vector<char>* cavitated = nullptr) const;
    /// Mass-conserving (s.supplyFilm given): one backward-Euler step of dt (s) of the film's
    /// content from the last step's film fraction across the face (its gap h_min − dt ḣ_min):
    /// the oil's change is dt × the edges' inflow. cavitated: as for solve.
    RingFilmResult step(const RingFilmState& s, double dt, const Eigen::VectorXd& previousFraction,
                        std::vector<char>* cavitated = nullptr) const;

    /// The film's friction (r.friction) for the state s it was solved for (a solve without it).
    void addFriction(const RingFilmState& s, RingFilmResult& r) const;

    const RingFaceProfile& profile() const { return profile_; }

private:
    /// The film's pressure and fraction for a given supply (JFO across the face), its oil and the
    /// edges' inflows.
    void solveStarved(const RingFilmState& s, double dt, const Eigen::VectorXd* previous, RingFilmResult& r,
                      std::vector<char>* cavitated) const;
    RingFilmResult solveWith(const RingFilmState& s, double dt, const Eigen::VectorXd* previous,
                             std::vector<char>* cavitated = nullptr) const;
    void solveFlooded(const RingFilmState& s, RingFilmResult& r, std::vector<char>* cavitated) const;

    RingFaceProfile profile_;
    Lubricant lubricant_;
    double pcav_;
    ShearStressFactor shear_;
    Eigen::VectorXd x_, drop_;  // per node
};

}  // namespace flexehd::lube
