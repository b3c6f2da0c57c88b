#pragma once
// SkirtFilm: the lubrication grid on the piston skirt and the rigid part of the film thickness
// (seed eq. 2; docs/dynamics.md §3).
//
// The grid is fixed to the piston: FilmGrid full circumference of radius bore/2, z from the
// skirt bottom to the skirt top in the piston frame (increasing towards the head), θ from +x
// about +z. Nodes farther than the panel half-angle from θ = 0 (thrust panel) and θ = π
// (anti-thrust panel) are Void: no skirt there, ambient pressure.
//     h_rigid(z, θ) = c + δ_profile(z) + δ_ovality(θ) − (e + z β) cos θ
// with c the nominal radial clearance, δ_profile the barrel profile (piecewise linear in the
// table, constant beyond its ends), δ_ovality = ovality (1 − cos 2θ)/2, e the lateral shift of
// the pin axis and β the tilt about it (a skirt point at height z moves by e + z β along x).

#include "cosim/case/EngineCase.hpp"
#include "lube/FilmGrid.hpp"

#include <Eigen/Core>

namespace flexehd::cosim {

class SkirtFilm {
public:
    /// Throws std::invalid_argument for a grid below 3 × 8 nodes or an empty skirt.
    SkirtFilm(const EngineSpec& engine, const PistonSpec& piston, const GridSpec& grid);

    const lube::FilmGrid& grid() const { return grid_; }
    /// h_rigid at every node (m) for the secondary motion (e, β): the same formula at every node,
    /// Void nodes included (their value is never used).
    void rigidThickness(double lateral, double tilt, Eigen::VectorXd& h) const;
    /// The motion-independent part c + δ_profile + δ_ovality (m).
    const Eigen::VectorXd& staticThickness() const { return h0_; }
    /// Piston-frame z and cos θ of every node.
    const Eigen::VectorXd& nodeZ() const { return z_; }
    const Eigen::VectorXd& nodeCos() const { return cos_; }

private:
    lube::FilmGrid grid_;
    Eigen::VectorXd h0_, z_, cos_;
};

/// Piecewise-linear interpolation of the profile table, constant beyond its ends (0 if empty).
double profileDrop(const std::vector<ProfilePoint>& profile, double z);

}  // namespace flexehd::cosim
