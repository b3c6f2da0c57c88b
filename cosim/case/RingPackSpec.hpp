#pragma once
// The piston's ring pack as the case file gives it (case key `rings`, docs/case-file.md,
// "rings"): per ring its cross-section, running face, tension, end gap, mass, roughness and
// groove. SI units throughout; z in the piston frame (origin on the pin axis, up towards the crown).
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace flexehd::cosim {

enum class RingKind { Compression, Scraper, OilControl };

/// The running face across the ring's height: a barrel parabola (crown height over the face's
/// half-height, vertex offset towards the crown) or a table of (x from the face's centre, radial
/// drop) rows, x ascending (lube::RingFaceProfile).
struct RingFaceSpec {
    double crownHeight = 0.0;   ///< m
    double vertexOffset = 0.0;  ///< m, + towards the crown
    std::vector<std::pair<double, double>> table;  ///< (x m, drop m); empty: the barrel
};

/// The oil-control ring's two lands (rails), alike and placed symmetrically about the ring's
/// mid-height.
struct OilControlLandsSpec {
    double width = 0.0;        ///< m, axial width of each land
    double separation = 0.0;   ///< m, between the lands' centres
    double crownHeight = 0.0;  ///< m, each land's barrel crown
};

struct RingGrooveSpec {
    double lowerFlank = 0.0;     ///< m, piston-frame z of the groove's lower flank
    double sideClearance = 0.0;  ///< m, groove width − ring height
    double backClearance = 0.0;  ///< m, radial space behind the ring when its face is at the bore
};

struct RingSpec {
    std::string name;
    RingKind kind = RingKind::Compression;
    double height = 0.0;       ///< m, axial
    double radialWidth = 0.0;  ///< m
    RingFaceSpec face;         ///< compression and scraper rings
    std::optional<OilControlLandsSpec> lands;  ///< the oil-control ring
    /// The ring's elastic load on the bore per unit circumference (N/m): 2 F_t / D from the
    /// tangential force F_t at the closed gap, or p_e b from the elastic pressure p_e.
    double tensionPerLength = 0.0;
    double closedGap = 0.0;  ///< m
    double mass = 0.0;       ///< kg
    double roughness = 0.0;  ///< m, composite rms roughness of the face and the liner (contact.sigma by default)
    RingGrooveSpec groove;

    /// Piston-frame z of the ring's upper edge, sitting on the groove's lower flank (m).
    double top() const { return groove.lowerFlank + height; }
    /// Piston-frame z of the groove's upper flank (m).
    double grooveTop() const { return groove.lowerFlank + height + groove.sideClearance; }
};

/// The gas between the rings (case key `ring_gas`, docs/case-file.md; docs/ring-pack.md, "The
/// pack's gas in a run"): the lands between the rings as volumes, each ring's end gap an orifice.
enum class RingGasModel { None, Lands };

struct RingGasSpec {
    RingGasModel model = RingGasModel::None;  ///< None: the cylinder's gas above and behind the top ring, the crankcase's below it
    /// C_d of each ring's end gap on the area gap × land clearance (Furuhama & Tada 1961: 0.8–0.9)
    double dischargeCoefficient = 0.86;
    double landClearance = 0.3e-3;            ///< m, radial: the lands below the bore (piston.geo)
    /// K, per land (between ring i and ring i + 1, top first), the gas at the land's metal
    /// temperature; empty: kLandTemperature each (an assumed value, not a measured one)
    std::vector<double> landTemperatures;
    /// Each ring's axial motion in its groove (RingAxialMotion) and its groove as a volume of its
    /// own, open to the land above or below through the flank clearance the ring leaves; false:
    /// every ring rests on its lower flank, its groove part of the land above.
    bool ringLift = false;
    static constexpr double kLandTemperature = 450.0;
};

}  // namespace flexehd::cosim
