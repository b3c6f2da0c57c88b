#pragma once
// CycleMetrics: the figures engineers compare designs by, integrated over one engine cycle of
// StepRecords (docs/results-format.md, summary.json).

#include "cosim/engine/PistonDynamics.hpp"
#include "cosim/coupling/StepRecord.hpp"

#include <vector>

namespace flexehd::cosim {

struct CycleMetrics {
    double duration = 0.0;            ///< s, time spanned by the records
    double frictionEnergy = 0.0;      ///< J, ∫ dissipated power dt (trapezoidal over the steps)
    double frictionPowerMean = 0.0;   ///< W, frictionEnergy / duration
    double boundaryFrictionEnergy = 0.0;     ///< J, its boundary-friction part
    double boundaryFrictionPowerMean = 0.0;  ///< W, boundaryFrictionEnergy / duration
    double fmep = 0.0;                ///< Pa, frictionEnergy / displaced volume (skirt's FMEP share)
    /// J, peak kinetic energy of the secondary motion, PistonDynamics::kineticEnergy:
    /// ½ (m_p + m_pin) ė² + m_p z_g ė β̇ + ½ [I_g + m_p (x_g² + z_g²)] β̇² (docs/dynamics.md §2)
    double slapEnergyMax = 0.0;
    double slapEnergyDeg = 0.0;       ///< °, crank angle (StepRecord::crankDeg, 0–720) where it peaks
    double lateralMin = 0.0, lateralMax = 0.0;  ///< m
    double tiltMin = 0.0, tiltMax = 0.0;        ///< rad
    double minFilm = 0.0, minFilmDeg = 0.0;     ///< m (< 0: the surfaces overlap); ° (crank angle 0–720)
    double maxPressure = 0.0;         ///< Pa, gauge
    double contactForceMax = 0.0;     ///< N, largest |lateral contact force| (asperities + hard contact)
    double hardContactForceMax = 0.0; ///< N, largest |lateral hard-contact force|
    double sideForceMax = 0.0;        ///< N, largest |rod side force|
    /// The fewest grid nodes across the thinnest film's region over the cycle, along the grid row
    /// and along the column (FilmFigures::minFilmNodes*; 0: the contact does not say), the crank
    /// angles (°) where they occur; the axial count over the steps whose thinnest film lies
    /// inside the film, not on its axial edge (an edge in contact cuts the region)
    int minFilmNodesCircumferential = 0, minFilmNodesAxial = 0;
    double minFilmNodesCircumferentialDeg = 0.0, minFilmNodesAxialDeg = 0.0;
    double meanIterations = 0.0;      ///< film solves per step
    int maxIterations = 0;
};

/// Throws std::invalid_argument for fewer than two records. displacedVolume = π B² S / 4 (m³).
CycleMetrics cycleMetrics(const std::vector<StepRecord>& cycle, const PistonDynamics& dynamics, double displacedVolume);
/// The cylinder's swept volume π/4 D² s (m³): friction energy over it is the FMEP.
double sweptVolume(const EngineSpec& engine);

}  // namespace flexehd::cosim
