#pragma once
// EngineCase: everything a co-simulation run needs, as read from a case file (YAML, SI units;
// key-by-key reference in docs/case-file.md, reader in CaseFile.hpp). Plain data: the reader
// validates ranges and files, the simulation only uses it.
//
// Frames (docs/dynamics.md): cylinder frame with z along the cylinder axis towards the head,
// +x the major thrust side, y the pin axis. Piston frame: origin on the piston axis at the height
// of the pin axis, same orientation; the pin axis passes through (pinOffset, ·, 0).

#include <Eigen/Core>

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "cosim/case/RingPackSpec.hpp"

namespace flexehd::cosim {

struct EngineSpec {
    double bore = 0.086;               ///< m
    double stroke = 0.086;             ///< m (crank radius = stroke / 2)
    double rodLength = 0.1435;         ///< m, centre to centre
    /// m, pin axis offset from the piston axis, positive towards the major thrust side (+x).
    double pinOffset = 0.0;
    double speedRpm = 1000.0;          ///< crankshaft speed, rev/min (case key `speed_rpm`)
    double crankcasePressure = 1.0e5;  ///< Pa, absolute: the film's ambient pressure
    /// m, depth of the pin axis below the liner frame's origin (deck) at TDC (> 0): places the
    /// piston on the liner mesh (liner frame z of the pin = −pinTdcDepth − (s_TDC − s)).
    double pinTdcDepth = 0.0335;
};

struct ProfilePoint {
    double z = 0.0;     ///< m, piston frame (axial position on the skirt)
    double drop = 0.0;  ///< m, radial reduction of the skirt radius from bore/2 − clearance
};

struct PistonSpec {
    double mass = 0.0;           ///< kg, piston without pin
    double pinMass = 0.0;        ///< kg, pin (and the small-end share of the rod, if lumped)
    double inertia = 0.0;        ///< kg·m², piston about the pin-parallel axis through its CG
    double cgX = 0.0;            ///< m, CG lateral position relative to the pin axis (+x)
    double cgZ = 0.0;            ///< m, CG axial position relative to the pin axis (+z up)
    double skirtTop = 0.0;       ///< m, piston frame z of the skirt's upper edge
    double skirtBottom = 0.0;    ///< m, piston frame z of the skirt's lower edge (< skirtTop)
    double clearance = 50e-6;    ///< m, nominal radial clearance (bore/2 − skirt radius)
    /// Half-width of each skirt panel (thrust around θ = 0, anti-thrust around θ = 180°), rad;
    /// π/2 (or more) = a full-circumference skirt. Case key `skirt_half_angle_deg` (degrees).
    double skirtHalfAngle = 3.14159265358979323846 / 2;
    std::vector<ProfilePoint> profile;  ///< barrel profile, z ascending (empty = cylindrical)
    /// m, radial reduction at the pin sides (θ = ±90°): δ(θ) = ovality (1 − cos 2θ) / 2.
    double ovality = 0.0;
};

/// How the film cavitates (docs/lube.md §3, §3b): the Reynolds (Swift–Stieber) condition on the
/// pressure alone, or the mass-conserving JFO (Elrod–Adams) film with its film fraction.
enum class CavitationModel { Reynolds, MassConserving };

/// Where the skirt's oil comes from (docs/coupling.md §6): as much as the film draws (flooded), or
/// the oil layer the liner carries, transported over the cycle.
enum class OilSupplyModel { Flooded, LinerLayer };

struct OilLayerPoint {
    double depth = 0.0;      ///< m below the deck (liner frame z = −depth)
    double thickness = 0.0;  ///< m, oil layer on the liner
};

/// The oil-control ring as the liner's oil layer sees it (docs/coupling.md §6, "The oil-control
/// ring"): its band on the piston and the layer it leaves on the liner.
struct OilControlRingSpec {
    double bottom = 0.0, top = 0.0;  ///< m, piston-frame z of the ring's lower and upper edges
    double thickness = 0.0;          ///< m, the oil layer it leaves on the liner
};

struct OilSupplySpec {
    OilSupplyModel model = OilSupplyModel::Flooded;
    /// The liner's oil layer at the start, depth ascending: one point is a constant layer;
    /// linear between points, constant beyond the ends.
    std::vector<OilLayerPoint> layer;
    /// Replenishment: below this depth (m) the layer outside the skirt is restored to `layer` at
    /// every step (splash from the crankcase). NaN: the depth of the skirt's lower edge at
    /// mid-stroke (crank angle 90°). Off with `replenish` false.
    double replenishBelowDepth = std::numeric_limits<double>::quiet_NaN();
    bool replenish = true;
    /// The oil-control ring above the skirt, setting the layer where it passes (none: not modelled).
    std::optional<OilControlRingSpec> oilControlRing;
};

struct LubricantSpec {
    double viscosity = 0.01;          ///< Pa·s, at the film temperature
    double density = 850.0;           ///< kg/m³
    double barusAlpha = 0.0;          ///< 1/Pa, 0 = constant viscosity
    double cavitationPressure = 0.0;  ///< Pa, gauge (relative to the crankcase pressure)
    CavitationModel cavitation = CavitationModel::Reynolds;
    OilSupplySpec supply;             ///< liner_layer needs cavitation MassConserving
};

struct ContactSpec {
    double sigma = 0.8e-6;            ///< m, composite rms roughness
    double beta = 2e-6;               ///< m, asperity tip radius
    double asperityDensity = 1e10;    ///< 1/m², η_s (η_s β σ dimensionless, typically 0.03–0.05)
    double compositeModulus = 0.0;    ///< Pa, E* (Hertz: 1/E* = Σ (1−ν²)/E); 0 = contact off
    double boundaryFriction = 0.1;    ///< μ_b, friction coefficient of asperity contact
    /// Hard contact below h = 0 (lube::ElasticFoundation, docs/lube.md §5): the skirt coating as
    /// a bonded elastic layer, K = E (1 − ν)/[(1 + ν)(1 − 2ν) t]. Used with asperity contact on.
    double coatingThickness = 15e-6;      ///< m, skirt coating (resin-bonded solid lubricant)
    double coatingModulus = 8e9;          ///< Pa, Young's modulus of the coating
    double coatingPoisson = 0.3;          ///< Poisson's ratio of the coating
    double hardContactStiffness = 0.0;    ///< Pa/m, K given directly (> 0 overrides the coating)
    /// Coefficient of restitution of an impact on the hard contact (0 < e ≤ 1; 1: elastic, no
    /// damping; docs/lube.md §4).
    double restitution = 1.0;
    /// Archard wear coefficients k (m²/N) of the skirt and the liner: wear depth rate k p_c |u|
    /// (docs/coupling.md §7); 0 = no wear map of that surface.
    double pistonWearCoefficient = 0.0;
    double linerWearCoefficient = 0.0;
};

struct PressureSample {
    double crankDeg = 0.0;  ///< °, 0–720, 0 = gas-exchange TDC, 360 = firing TDC
    double pressure = 0.0;  ///< Pa, absolute cylinder pressure
};

enum class BodyModel { Rigid, Flexible };
enum class ElasticResponse { QuasiStatic, Dynamic };

/// Loads on a flexible piston besides its films' (case key bodies.piston.loads; docs/coupling.md §2).
struct PistonLoadSpec {
    bool gasPressure = false;           ///< the cylinder's gas pressure (gauge) on gasSurface
    std::string gasSurface = "crown";   ///< the surface group it acts on
    bool inertia = false;               ///< the inertia of the piston's rigid motion
    /// the ring pack's gas on the lands and grooves and the rings' forces on the groove flanks
    /// (needs `ring_gas` with `ring_lift`)
    bool ringPack = false;
};

struct BodySpec {
    BodyModel model = BodyModel::Rigid;
    PistonLoadSpec loads;     ///< the piston only
    std::string file;         ///< reduced-body HDF5 file (Flexible), resolved to an absolute path
    std::string surface;      ///< physical surface facing the film: `skirt` / `bore`
    std::string interface;    ///< interface held in the quasi-static response: `pin_bore` / seats
    /// Every interface held in the quasi-static response (case key `interface`: one name or a
    /// list, e.g. the liner's `[top_seat, bottom_seat]`); interface == interfaces.front().
    std::vector<std::string> interfaces;
};

struct GridSpec {
    int axialNodes = 48;           ///< nodes along the skirt
    int circumferentialNodes = 144;  ///< nodes around the full circumference (periodic)
};

struct TimeSpec {
    double startDeg = 0.0;         ///< °, crank angle where the first cycle starts (outputs give true angles)
    double maxStepDeg = 0.5;       ///< °, largest crank-angle step
    double minStepDeg = 1e-3;      ///< °, step control gives up (diagnosis) below this
    double lateralTolerance = 0.2e-6;  ///< m, local error tolerance on the lateral shift
    double tiltTolerance = 5e-6;       ///< rad, local error tolerance on the tilt
    /// The defaults of lateralTolerance and tiltTolerance on the liner's oil layer: a starved
    /// skirt crosses its clearance with little to damp the flight, and where it lands follows
    /// the crossing's integration (docs/coupling.md §1, "A starved skirt needs a tighter tolerance").
    static constexpr double kStarvedLateralTolerance = 0.02e-6;
    static constexpr double kStarvedTiltTolerance = 5e-7;
    int maxCycles = 5;             ///< cycles simulated at most
    /// m: the cycle is periodic when max over its steps of |Δe| + |Δβ|·reach ≤ this, with Δ the change
    /// from the previous cycle at the same crank angle and reach = max(skirtTop, −skirtBottom)
    double periodicityTolerance = 1e-6;
    /// Mass-conserving film: the cycle is periodic only when the oil on the liner and in the film
    /// at its end differs from its start by at most this share too (docs/coupling.md §6).
    double oilPeriodicityTolerance = 1e-3;
};

enum class CouplingAcceleration { IqnIls, Aitken };
/// How a step with flexible bodies is solved (docs/coupling.md §1): Newton on the motion and the
/// modal coordinates together with the film's exact linearisation, or the partitioned iteration
/// (Newton on the motion, IQN-ILS / Aitken on the modal coordinates).
enum class CouplingMethod { Newton, Partitioned };

struct CouplingSpec {
    /// Relative to the clearance: the film-structure coupling has converged when the largest film-
    /// thickness change of the modal residual H(y) − y, max over grid nodes and bodies of |Δh|, is
    /// ≤ tolerance × piston.clearance (docs/coupling.md §1).
    double tolerance = 1e-3;
    int maxIterations = 30;    ///< passes per step, one film solve each (+ 2 for the first pass's Jacobian)
    /// The default of maxIterations with a flexible body: on the mass-conserving film its partition
    /// changes within the step (docs/coupling.md §6), and where the skirt rides on its asperities
    /// with almost no side force to hold it a step takes up to about 150 passes on either film
    /// (docs/coupling.md §1, "Passes per step").
    static constexpr int kFlexiblePasses = 150;
    /// coupling.keep_jacobian: the step's Jacobian kept from step to step while it serves (rigid
    /// bodies: the motion's while the step size is the same; flexible bodies with method Newton:
    /// the coupled one, re-formed from its parts for a new step size) and formed anew where a pass
    /// does not halve the residual; false: formed at every step's first pass (docs/coupling.md §1).
    bool keepJacobian = true;
    CouplingAcceleration acceleration = CouplingAcceleration::IqnIls;  ///< of the partitioned method
    CouplingMethod method = CouplingMethod::Newton;
    ElasticResponse response = ElasticResponse::QuasiStatic;
    /// coupling.elastic_squeeze: the squeeze term ∂h/∂t includes the elastic deformation rate
    /// (the seed's eq. 1 in full, the default); the step is then solved by semismooth Newton on the motion and the
    /// modal coordinates together with the film's exact linearisation (docs/coupling.md §3);
    /// needs method Newton. Off: ∂h/∂t of the rigid film only (the quasi-static skirt may then lose
    /// its equilibrium in the film at high speed, docs/coupling.md §1).
    bool elasticSqueeze = true;
};

struct OutputSpec {
    std::string directory;     ///< results directory (created), resolved to an absolute path
    double vtkEveryDeg = 10.0; ///< °, spacing of the VTK snapshots in the last cycle; 0 = none
    bool modeShapes = true;    ///< also export the bodies' mode shapes for ParaView
};

/// One Fourier order of the bore distortion at one axial position (case key
/// `liner.bore_distortion`, format `fourier`): Δr(θ) = amplitude · cos(order · (θ − phase)).
struct FourierTerm {
    double z = 0.0;          ///< m, liner frame (0 at the liner top face, negative down the bore)
    int order = 0;           ///< n ≥ 0
    double amplitude = 0.0;  ///< m, radial, outward positive
    double phase = 0.0;      ///< rad, from +x towards +y
};

/// One node of an external FE result on the bore (format `nodal`), liner frame.
struct BoreNode {
    double x = 0.0, y = 0.0, z = 0.0;  ///< m, undeformed position
    double ur = 0.0;                   ///< m, radial displacement, outward positive
};

enum class BoreDistortionFormat { None, Fourier, Nodal };

/// Liner bore distortion from assembly (seed eq. 2: part of h_rigid; outward opens the gap).
struct BoreDistortionSpec {
    BoreDistortionFormat format = BoreDistortionFormat::None;  ///< None = no distortion
    std::string file;                  ///< absolute path of the table, empty for an inline table
    std::vector<FourierTerm> fourier;  ///< Fourier: the terms, sorted by z then order
    std::vector<BoreNode> nodes;       ///< Nodal: the bore nodes of the FE result
};

struct LinerSpec {
    BoreDistortionSpec boreDistortion;
};

/// Thermal displacements of piston and liner (case key `thermal`; file format: docs/coupling.md §5).
struct ThermalSpec {
    std::string file;  ///< absolute path of thermal.h5 (`flexehd thermal`); empty = no thermal
};

/// The liner's vibration for slap noise (case key `acoustics`, docs/acoustics.md): with a
/// flexible liner and the dynamic response, the run records the normal velocity of one of the
/// liner's surfaces over each cycle at a fixed sampling rate.
struct AcousticsSpec {
    bool enabled = false;
    std::string surface = "outer";  ///< the radiating surface: a surface group of the liner's mesh
    double upToHz = 5000.0;         ///< Hz, the frequency range the record resolves
    /// Samples per second per hertz of range (the analysers' 2.56: Nyquist with room for the
    /// anti-aliasing roll-off)
    static constexpr double kSamplesPerHz = 2.56;
    double sampleRateHz() const { return kSamplesPerHz * upToHz; }
};

struct EngineCase {
    std::string path;          ///< the case file (absolute), for messages and provenance
    std::string name;          ///< free text (case key `name`)
    EngineSpec engine;
    PistonSpec piston;
    LubricantSpec lubricant;
    ContactSpec contact;
    std::vector<PressureSample> cylinderPressure;  ///< from the CSV named by the case, sorted
    std::string cylinderPressureFile;              ///< absolute path of that CSV
    BodySpec pistonBody;
    BodySpec linerBody;
    GridSpec grid;
    TimeSpec time;
    CouplingSpec coupling;
    OutputSpec output;
    LinerSpec liner;      ///< liner geometry beyond the bore: assembly distortion
    ThermalSpec thermal;  ///< thermal displacements (none by default)
    std::vector<RingSpec> rings;  ///< the ring pack, top ring first (none by default)
    RingGasSpec ringGas;          ///< the gas between the rings (none by default)
    AcousticsSpec acoustics;      ///< the liner's recorded vibration (none by default)

    /// The piston or the liner is a flexible (reduced) body.
    bool hasFlexibleBody() const {
        return pistonBody.model == BodyModel::Flexible || linerBody.model == BodyModel::Flexible;
    }
};

}  // namespace flexehd::cosim
