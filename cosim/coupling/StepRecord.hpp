#pragma once
// StepRecord: the per-step results of a co-simulation run, one row of history.csv
// (docs/results-format.md). Signs follow docs/dynamics.md: forces act ON THE PISTON, in the
// cylinder frame (x major thrust side, z towards the head); moments about the pin axis, +y.

#include "cosim/contact/FilmFigures.hpp"

#include <vector>

namespace flexehd::cosim {

/// The master's figures of the step, and the skirt film's (FilmFigures: film_force_n …
/// elastic_film_change_m, wetted_share; their columns sit between the master's, docs/results-format.md).
struct StepRecord : FilmFigures {
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
    double cylinderPressure = 0.0;  ///< Pa, absolute cylinder (gas) pressure, as the case's table gives it
    // The mass-conserving film only (lubricant.cavitation: mass_conserving; docs/coupling.md §6):
    // Flows and oil are summed over the contacts' films.
    double oilIn = 0.0;        ///< m³/s, oil flowing into the films through their axial edges
    double oilOut = 0.0;       ///< m³/s, ≥ 0, oil flowing out through them
    double sideLeakage = 0.0;  ///< m³/s, net oil leaving the films at their sides
    double filmOil = 0.0;      ///< m³, oil in the films, Σ V φ h
    double linerOil = 0.0;     ///< m³, oil on the liner outside the contacts' covers (0 with a flooded supply)
    double replenishedOil = 0.0;  ///< m³, added to the liner by the replenishment since the start (< 0: removed)
    int couplingIterations = 0;     ///< film solves in this step (coupling + Newton)
    double stepDeg = 0.0;           ///< °, crank-angle step that reached this point
    /// The values of the further contacts' own columns (FilmContact::columns, in contact order;
    /// PistonSimulation::contactColumns names them)
    std::vector<double> contactValues;
};

}  // namespace flexehd::cosim
