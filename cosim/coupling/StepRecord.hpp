#pragma once
// StepRecord: the per-step results of a co-simulation run, one row of history.csv
// (docs/results-format.md). Signs follow docs/dynamics.md: forces act ON THE PISTON, in the
// cylinder frame (x major thrust side, z towards the head); moments about the pin axis, +y.

#include <vector>

namespace flexehd::cosim {

struct StepRecord {
    int cycle = 0;                  ///< 1-based cycle number
    /// °, the crank angle 0–720 (0 = gas-exchange TDC, 360 = firing TDC), whatever time.start_deg:
    /// a cycle runs from start_deg to 720 and on from 0 to start_deg
    double crankDeg = 0.0;
    double time = 0.0;              ///< s since the start of the run
    double lateral = 0.0;           ///< m, lateral shift e of the pin axis (+x thrust)
    double tilt = 0.0;              ///< rad, tilt β about +y (top of the piston towards +x > 0)
    double lateralVelocity = 0.0;   ///< m/s
    double tiltRate = 0.0;          ///< rad/s
    double sideForce = 0.0;         ///< N, lateral force of the connecting rod on the pin
    double filmForce = 0.0;         ///< N, lateral force of the film without asperity contact (pressure + friction)
    double filmMoment = 0.0;        ///< N·m, moment of film pressure, contact and friction about the pin
    double contactForce = 0.0;      ///< N, lateral contact force (asperities + hard contact)
    double hardContactForce = 0.0;  ///< N, its hard-contact part (coating, film thickness < 0)
    double frictionForce = 0.0;     ///< N, axial friction force on the piston (hydrodynamic shear + boundary)
    /// N, axial friction force ON THE LINER (what a floating-liner rig measures): the film's
    /// shear on the liner wall and the boundary friction of the asperity contact
    double linerHydrodynamicFriction = 0.0;
    double linerBoundaryFriction = 0.0;
    /// W, ≥ 0: the power the skirt contact loses, viscous dissipation + boundary friction power
    double dissipatedPower = 0.0;
    double boundaryFrictionPower = 0.0;  ///< W, ≥ 0: its boundary-friction part μ_b ∫ p_c |ΔV| dA
    double cylinderPressure = 0.0;  ///< Pa, absolute cylinder (gas) pressure, as the case's table gives it
    double minFilm = 0.0;           ///< m, smallest film thickness (gap); < 0 where the surfaces overlap
    double maxPressure = 0.0;       ///< Pa, gauge
    /// m, largest |elastic change of the film thickness| over the film nodes (piston and liner
    /// deformation together; 0 with rigid bodies)
    double elasticFilmChange = 0.0;
    // The mass-conserving film only (lubricant.cavitation: mass_conserving; docs/coupling.md §6):
    // Flows and oil are summed over the contacts' films.
    double oilIn = 0.0;        ///< m³/s, oil flowing into the films through their axial edges
    double oilOut = 0.0;       ///< m³/s, ≥ 0, oil flowing out through them
    double sideLeakage = 0.0;  ///< m³/s, net oil leaving the films at their sides
    double filmOil = 0.0;      ///< m³, oil in the films, Σ V φ h
    double wettedShare = 0.0;  ///< the share of the skirt's area in full film (φ = 1)
    double linerOil = 0.0;     ///< m³, oil on the liner outside the contacts' covers (0 with a flooded supply)
    double replenishedOil = 0.0;  ///< m³, added to the liner by the replenishment since the start (< 0: removed)
    int couplingIterations = 0;     ///< film solves in this step (coupling + Newton)
    double stepDeg = 0.0;           ///< °, crank-angle step that reached this point
    /// The values of the further contacts' own columns (FilmContact::columns, in contact order;
    /// PistonSimulation::contactColumns names them)
    std::vector<double> contactValues;
};

}  // namespace flexehd::cosim
