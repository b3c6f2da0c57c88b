#pragma once
// JournalBearing: a plain 360° journal bearing — stationary sleeve, journal spinning at N rev/s,
// film h = c(1 + ε cos θ) with θ from the maximum film (docs/lube.md §1) — solved by the
// lubrication library, with the dimensionless numbers of the design charts (Raimondi & Boyd,
// ASLE Trans. 1 (1958) 159): Sommerfeld number, attitude angle, friction and flow variables,
// pressure ratio. The oil enters through a full-length axial groove at ambient pressure 0, by
// default at the maximum film (Raimondi & Boyd's boundary condition; also the datum where the
// infinitely long Sommerfeld solutions vanish), or anywhere round the sleeve (where the groove
// lies in the diverging film, the mass-conserving film ruptures downstream of the minimum film
// and re-forms inside the bearing, ahead of the groove); with the mass-conserving film the groove
// may supply a starved film (the Couette flow leaving it carries a film fraction below 1). The
// ends are open at ambient pressure, or, for the infinitely long bearing, one axial cell with
// zero-flux ends (docs/lube.md §8).
#include <string>

#include "lube/ReynoldsSolver.hpp"

namespace flexehd::lube {

/// Cavitation model of the bearing film: the linear Reynolds equation (full Sommerfeld), its
/// negative pressures dropped afterwards (half Sommerfeld), the Reynolds (Swift–Stieber)
/// condition, or the mass-conserving Elrod–Adams (JFO) film.
enum class BearingCavitation { FullSommerfeld, HalfSommerfeld, Reynolds, MassConserving };

struct JournalBearingSpec {
    double radius = 0.05;        ///< journal radius R (m)
    double length = 0.1;         ///< bearing length L (m)
    double clearance = 50e-6;    ///< radial clearance c (m)
    double eccentricity = 0.5;   ///< ε = e/c in (0, 1)
    double speed = 50.0;         ///< journal speed N (rev/s)
    double viscosity = 0.01;     ///< dynamic viscosity μ (Pa s)
    bool infinitelyLong = false; ///< no side leakage; loads for the length L
    bool supplyGroove = true;    ///< the axial supply groove (needed by MassConserving)
    /// °, where the groove is, from the maximum film in the direction of rotation, in [0, 360):
    /// the grid column nearest to it (JournalBearingResult::grooveAngleDeg)
    double grooveAngleDeg = 0.0;
    /// The film fraction of the oil the groove supplies, in (0, 1]: 1 flooded, < 1 a starved
    /// supply (MassConserving only)
    double supplyFraction = 1.0;
    BearingCavitation cavitation = BearingCavitation::Reynolds;
    /// Reynolds models: the complementarity solver. MassConserving: Psor = the projected
    /// Gauss–Seidel sweeps of Ausas et al., otherwise the active-set method on sparse LU.
    SolverKind solver = SolverKind::Multigrid;
    int circumferentialNodes = 128;
    int axialNodes = 33;         ///< ignored when infinitelyLong (2 nodes, one cell)
    double tolerance = 1e-8;     ///< relative natural residual
    double omega = 0.0;          ///< over-relaxation of PSOR and JFO sweeps; 0 = automatic
};

/// How well `circumferentialNodes` grid nodes round the sleeve resolve the film's minimum
/// region (docs/lube.md §8, "Grid resolution of the minimum film"). Near the minimum film
/// h ≈ h_min + c ε (θ−π)²/2, so h < 2 h_min over a half-width Δθ = √(2 h_min/(c ε)) = √(2(1−ε)/ε);
/// the pressure peak lies in that region, and the load is grid-converged (measured: within 2 %)
/// once kMinFilmRegionNodes grid spacings 2π/Nθ span its width 2Δθ.
struct FilmResolution {
    double regionWidthDeg = 0.0;          ///< 2Δθ in degrees
    double nodesAcross = 0.0;             ///< K = 2Δθ/(2π/Nθ): grid nodes across the region
    /// The fraction (0..1) by which the load was measured to be low at this K (the largest of the
    /// measured set-ups, L/D = 1 with the Reynolds condition; docs/lube.md §8); 0 when resolved
    double expectedLoadDeficit = 0.0;
    /// The least Nθ with K ≥ kMinFilmRegionNodes, rounded up to a multiple of 16 (multigrid
    /// coarsens by halving); may exceed any grid that fits in memory (ε → 1)
    double neededCircumferentialNodes = 0.0;
    bool resolved = false;                ///< K ≥ kMinFilmRegionNodes
};

/// Grid nodes across the minimum region h < 2 h_min that make the load grid-converged to 2 %
/// (docs/lube.md §8: 1.7 % at K = 7.3, 0.7–1.0 % at K ≈ 9.5, 3.4 % at K ≈ 5.8).
inline constexpr double kMinFilmRegionNodes = 8.0;

struct JournalBearingResult {
    std::string solverName;           ///< the method that solved the film
    int axialNodes = 0;               ///< of the grid solved
    double grooveAngleDeg = 0.0;      ///< °, the groove's grid column (the spec's angle, snapped)
    double load = 0.0;                ///< W (N)
    double loadAlongLineOfCentres = 0.0, loadPerpendicular = 0.0;  ///< components of W (N)
    double specificLoad = 0.0;        ///< P = W/(LD) (Pa)
    double attitudeDeg = 0.0;         ///< angle of W from the line of centres (deg)
    double sommerfeld = 0.0;          ///< S = (R/c)² μN/P
    double frictionTorque = 0.0;      ///< on the journal, opposing its rotation (N m)
    double frictionPower = 0.0;       ///< torque × ω (W)
    double frictionCoefficient = 0.0; ///< f = T/(RW)
    double frictionVariable = 0.0;    ///< (R/c) f
    double inletFlow = 0.0;           ///< Q through the groove's downstream edge (m³/s)
    double returnFlow = 0.0;          ///< flow reaching the groove from upstream (m³/s)
    double sideFlow = 0.0;            ///< Qs out of both ends (m³/s)
    double flowVariable = 0.0;        ///< Q/(R c N L)
    double maxPressure = 0.0;         ///< Pa
    double maxPressureRatio = 0.0;    ///< P/p_max
    double minFilm = 0.0;             ///< m
    double cavitatedArea = 0.0;       ///< m²
    double cavitatedFraction = 0.0;   ///< of the film area
    int iterations = 0;               ///< solver iterations (JFO: sweeps or LU factorizations)
    int coarseIterations = 0;         ///< of them on coarse grids (nested start)
    double residual = 0.0;
    double solveSeconds = 0.0;
    FilmResolution resolution;        ///< of the minimum film by the grid (filmResolution)
};


/// The resolution of the film h = c(1 + ε cos θ) on `circumferentialNodes` nodes round the
/// sleeve; std::invalid_argument for ε outside (0, 1) or fewer than one node.
FilmResolution filmResolution(double eccentricity, int circumferentialNodes);

/// The largest ε whose minimum region `circumferentialNodes` nodes resolve (K ≥ kMinFilmRegionNodes):
/// 2/(2 + (kMinFilmRegionNodes π/Nθ)²).
double largestResolvedEccentricity(int circumferentialNodes);

class JournalBearing {
public:
    /// Checks the specification (std::invalid_argument naming the quantity).
    explicit JournalBearing(const JournalBearingSpec& spec);
    JournalBearingResult solve() const;
    const JournalBearingSpec& spec() const { return spec_; }
    /// The method that solves the film: the Reynolds solver's name, or jfo-gauss-seidel,
    /// jfo-active-set.
    const char* methodName() const;

private:
    JournalBearingSpec spec_;
};

const char* name(BearingCavitation m);  ///< full-sommerfeld, half-sommerfeld, reynolds, jfo
const char* name(SolverKind s);         ///< psor, active-set, multigrid

}  // namespace flexehd::lube
