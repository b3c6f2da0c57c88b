#pragma once
// FilmFigures, FilmFields: the run's own film results (docs/results-format.md) — the figures of
// history.csv from film_force_n to elastic_film_change_m and its wetted_share, and the film fields
// of film.pvd. One contact of a run reports them, the skirt's (FilmContact::filmFigures,
// filmFields); every further contact reports through its own columns (ContactColumns.hpp). Signs
// follow docs/dynamics.md: forces act ON THE PISTON, in the cylinder frame (x major thrust side,
// z towards the head); moments about the pin axis, +y.

#include <Eigen/Core>

namespace flexehd::cosim {

/// The film's figures at an accepted step (a part of StepRecord, one row of history.csv).
struct FilmFigures {
    double filmForce = 0.0;         ///< N, lateral force of the film without asperity contact (pressure + friction)
    double filmMoment = 0.0;        ///< N·m, moment of film pressure, contact and friction about the pin
    double contactForce = 0.0;      ///< N, lateral contact force (asperities + hard contact)
    double hardContactForce = 0.0;  ///< N, its hard-contact part (coating, film thickness < 0)
    double frictionForce = 0.0;     ///< N, axial friction force on the piston (hydrodynamic shear + boundary)
    /// N, axial friction force ON THE LINER (what a floating-liner rig measures): the film's
    /// shear on the liner wall and the boundary friction of the asperity contact
    double linerHydrodynamicFriction = 0.0;
    double linerBoundaryFriction = 0.0;
    /// W, ≥ 0: the power the contact loses, viscous dissipation + boundary friction power
    double dissipatedPower = 0.0;
    double boundaryFrictionPower = 0.0;  ///< W, ≥ 0: its boundary-friction part μ_b ∫ p_c |ΔV| dA
    double minFilm = 0.0;           ///< m, smallest film thickness (gap); < 0 where the surfaces overlap
    double maxPressure = 0.0;       ///< Pa, gauge
    /// m, largest |elastic change of the film thickness| over the film nodes (piston and liner
    /// deformation together; 0 with rigid bodies)
    double elasticFilmChange = 0.0;
    /// the share of the film's area in full film (φ = 1); the mass-conserving film only
    double wettedShare = 0.0;
    /// Not history columns: the grid nodes across the region of the thinnest film
    /// (lube::minimumFilmSpan, band max(h_min, σ)), along the grid row and column through it;
    /// 0 for a contact that does not say (docs/lube.md §8)
    int minFilmNodesCircumferential = 0;
    int minFilmNodesAxial = 0;
    bool minFilmAtAxialEdge = false;  ///< the thinnest film on the film's axial edge (a skirt edge)
};

/// The film's fields at a written crank angle (a part of Snapshot), per node of its grid.
struct FilmFields {
    /// Pa gauge; m (unfloored: < 0 where the surfaces overlap); Pa; Pa (τ_z on the piston);
    /// cavitated share of the node
    Eigen::VectorXd pressure, filmThickness, contactPressure, shearStress, cavitation;
    Eigen::VectorXd filmFraction;  ///< mass-conserving film: φ per node (empty with the Reynolds condition)
};

}  // namespace flexehd::cosim
