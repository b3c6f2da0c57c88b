#pragma once
// ClearanceTerms: the film-thickness terms of seed eq. 2 that do not depend on the secondary
// motion or the elastic deformation, beyond SkirtFilm's c + profile + ovality (docs/coupling.md §5):
//
//   h_rigid += Δr_bore(z + s, θ)            liner bore distortion from assembly (BoreDistortion)
//   h       += u_r,liner,th(z + s, θ)        liner thermal growth (outward opens the gap)
//   h       −= u_r,piston,th(z, θ)           piston thermal growth (outward closes the gap)
//
// (z, θ) a film-grid node in the piston frame (= the piston mesh frame: the piston's reduced body
// is mapped with no offset), s the liner offset (PistonSimulation::linerOffset: liner-frame z =
// grid z + s, the liner mesh frame). The piston term is interpolated once onto the grid; the liner
// terms are tabulated once on liner-fixed rows (LinerFieldTable) and sampled at s every step.
// Void nodes are left alone. Nothing is added when the case has neither thermal nor distortion.

#include "cosim/case/EngineCase.hpp"
#include "cosim/clearance/LinerFieldTable.hpp"
#include "lube/FilmGrid.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>

namespace flexehd::cosim {

class ClearanceTerms {
public:
    /// [offsetMin, offsetMax]: the liner offsets the run visits (TDC … BDC). Reads the thermal
    /// file (case key `thermal`) and tabulates the bore distortion (`liner.bore_distortion`).
    /// Throws std::runtime_error naming the file and dataset if a thermal table does not cover
    /// the skirt (piston) or its sweep (liner), or the FE bore nodes do not cover the sweep.
    ClearanceTerms(const EngineCase& c, const lube::FilmGrid& grid, double offsetMin, double offsetMax);

    /// True if the case gives any of the terms.
    static bool wanted(const EngineCase& c) {
        return !c.thermal.file.empty() || c.liner.boreDistortion.format != BoreDistortionFormat::None;
    }
    bool empty() const { return !hasPiston_ && !distortion_ && !linerThermal_; }

    /// h += all terms at the liner offset s (non-Void nodes).
    void add(double offset, Eigen::VectorXd& h) const;
    /// The piston term −u_r,piston,th on the grid (zero if none; 0 on Void nodes).
    const Eigen::VectorXd& pistonTerm() const { return piston_; }
    const std::optional<LinerFieldTable>& distortion() const { return distortion_; }
    const std::optional<LinerFieldTable>& linerThermal() const { return linerThermal_; }
    /// One line for the run's progress output: which terms are on and their ranges.
    std::string summary() const;

private:
    const lube::FilmGrid* grid_;
    bool hasPiston_ = false;
    Eigen::VectorXd piston_;
    std::optional<LinerFieldTable> distortion_, linerThermal_;
};

}  // namespace flexehd::cosim
