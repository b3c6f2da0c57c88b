#include "cosim/case/CaseFile.hpp"
#include "cosim/io/YamlKeys.hpp"
#include "cosim/io/YamlSection.hpp"
#include "cosim/case/CaseValues.hpp"

#include <algorithm>
#include <cstdint>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "cosim/clearance/BoreDistortion.hpp"
#include "cosim/engine/CylinderPressure.hpp"
#include "cosim/clearance/ThermalDisplacementFile.hpp"

namespace flexehd::cosim {
namespace {

using namespace casefile;
namespace fs = std::filesystem;
const auto& closest = closestKey;
const auto& joined = joinedKeys;
const auto& describe = describeNode;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// ---- sections -------------------------------------------------------------------------------

const Quantity kLength{"length", "m"};
const Quantity kMass{"mass", "kg"};
const Quantity kPressure{"pressure", "Pa"};

void readEngine(const YamlSection& s, EngineSpec& e) {
    e.bore = number(s, "bore", kLength, Sign::Positive, e.bore, true);
    e.stroke = number(s, "stroke", kLength, Sign::Positive, e.stroke, true);
    e.rodLength =
        number(s, "rod_length", {"length (connecting rod, centre to centre)", "m"}, Sign::Positive, e.rodLength, true);
    e.pinOffset = number(s, "pin_offset", {"length (towards +x, the major thrust side)", "m"}, Sign::Any, e.pinOffset);
    e.speedRpm = number(s, "speed_rpm", {"crankshaft speed", "rev/min"}, Sign::Positive, e.speedRpm, true);
    e.crankcasePressure =
        number(s, "crankcase_pressure", {"absolute pressure", "Pa"}, Sign::Positive, e.crankcasePressure);
    e.pinTdcDepth =
        number(s, "pin_tdc_depth", {"depth of the pin axis below the deck at TDC", "m"}, Sign::Positive, e.pinTdcDepth);
    if (e.bore > 2.0) s.fail("bore", fmt::format("a bore of {:g} m is above 2 m: check the units (m)", e.bore));
    if (e.stroke > 4.0) s.fail("stroke", fmt::format("a stroke of {:g} m is above 4 m: check the units (m)", e.stroke));
    if (std::abs(e.pinOffset) >= e.bore / 2)
        s.fail("pin_offset", fmt::format("|pin_offset| = {:g} m must be smaller than the bore radius {:g} m",
                                         std::abs(e.pinOffset), e.bore / 2));
    if (!(e.rodLength > e.stroke / 2 + std::abs(e.pinOffset)))
        s.fail("rod_length",
               fmt::format("the crank cannot turn: rod_length ({:g} m) must exceed stroke/2 + |pin_offset| = {:g} m",
                           e.rodLength, e.stroke / 2 + std::abs(e.pinOffset)));
}

void readPiston(const YamlSection& s, const EngineSpec& engine, PistonSpec& p) {
    p.mass = number(s, "mass", {"mass (piston without pin)", "kg"}, Sign::Positive, p.mass, true);
    p.pinMass = number(s, "pin_mass", kMass, Sign::NonNegative, p.pinMass, true);
    p.inertia = number(s, "inertia", {"rotary inertia about the pin-parallel axis through the CG", "kg m^2"},
                       Sign::Positive, p.inertia, true);
    p.cgX = number(s, "cg_x", kLength, Sign::Any, p.cgX);
    p.cgZ = number(s, "cg_z", kLength, Sign::Any, p.cgZ);
    p.skirtTop = number(s, "skirt_top", {"length (piston frame z)", "m"}, Sign::Any, p.skirtTop, true);
    p.skirtBottom = number(s, "skirt_bottom", {"length (piston frame z)", "m"}, Sign::Any, p.skirtBottom, true);
    p.clearance = number(s, "clearance", kLength, Sign::Positive, p.clearance);
    const double halfDeg = number(s, "skirt_half_angle_deg", {"angle", "deg"}, Sign::Positive, p.skirtHalfAngle / kDeg);
    p.ovality = number(s, "ovality", kLength, Sign::NonNegative, p.ovality);

    if (std::abs(p.cgX) >= engine.bore / 2)
        s.fail("cg_x", fmt::format("the CG must lie inside the bore: |cg_x| = {:g} m >= bore/2", std::abs(p.cgX)));
    if (!(p.skirtBottom < p.skirtTop))
        s.fail("skirt_bottom",
               fmt::format("expected skirt_bottom < skirt_top = {:g} m, got {:g} m", p.skirtTop, p.skirtBottom));
    if (p.skirtTop - p.skirtBottom > 2 * engine.bore)
        s.fail("skirt_bottom", fmt::format("a skirt {:g} m long is longer than twice the bore: check the units (m)",
                                           p.skirtTop - p.skirtBottom));
    if (p.clearance > 0.01 * engine.bore)
        s.fail("clearance", fmt::format("expected a radial clearance below 1% of the bore ({:g} m), got {:g} m: "
                                        "check the units (m; 50 um = 5e-05)",
                                        0.01 * engine.bore, p.clearance));
    if (!(halfDeg <= 180.0))
        s.fail("skirt_half_angle_deg", fmt::format("expected 0 < angle <= 180 deg, got {:g}", halfDeg));
    if (s.has("skirt_half_angle_deg")) p.skirtHalfAngle = halfDeg * kDeg;
    if (p.ovality > 0.01 * engine.bore)
        s.fail("ovality", fmt::format("expected an ovality below 1% of the bore ({:g} m), got {:g} m",
                                      0.01 * engine.bore, p.ovality));

    p.profile.clear();
    if (s.has("profile")) {
        const YAML::Node list = s.get("profile");
        const std::string expected = "a list of [z, drop] pairs in m, z ascending";
        if (!list.IsSequence()) s.fail("profile", "expected " + expected + ", got " + describe(list));
        const std::string path = s.keyPath("profile");
        for (std::size_t i = 0; i < list.size(); ++i) {
            const YAML::Node row = list[i];
            const std::string rowPath = fmt::format("{}[{}]", path, i);
            double z = 0.0, drop = 0.0;
            if (!row.IsSequence() || row.size() != 2 || !row[0].IsScalar() || !row[1].IsScalar() ||
                !parseNumber(row[0].Scalar(), z) || !parseNumber(row[1].Scalar(), drop))
                s.source().fail(rowPath, row,
                     "expected a pair [z, drop] of numbers in m, got " + describe(row) +
                         (row.IsSequence() ? fmt::format(" with {} entries", row.size()) : ""));
            if (!p.profile.empty() && !(z > p.profile.back().z))
                s.source().fail(rowPath, row,
                     fmt::format("profile z must be strictly ascending: {:g} m follows {:g} m", z, p.profile.back().z));
            if (!(drop > -p.clearance))
                s.source().fail(rowPath, row,
                     fmt::format("a drop of {:g} m makes the skirt touch the bore (clearance {:g} m)", drop,
                                 p.clearance));
            if (std::abs(drop) > 0.01 * engine.bore)
                s.source().fail(rowPath, row,
                     fmt::format("a drop of {:g} m is more than 1% of the bore: check the units (m)", drop));
            p.profile.push_back({z, drop});
        }
        if (p.profile.size() == 1) s.fail("profile", "a profile needs at least two points (or none: cylindrical)");
        if (!p.profile.empty()) {
            const double tol = 1e-9;
            if (p.profile.front().z > p.skirtBottom + tol || p.profile.back().z < p.skirtTop - tol)
                s.fail("profile",
                       fmt::format("the profile (z from {:g} to {:g} m) must cover the skirt, skirt_bottom = {:g} m to "
                                   "skirt_top = {:g} m",
                                   p.profile.front().z, p.profile.back().z, p.skirtBottom, p.skirtTop));
        }
    }
}

// lubricant.supply (docs/case-file.md): flooded, or the liner's oil layer (constant or a table over
// the depth below the deck) with its replenishment.
void readOilSupply(const YamlSection& lubricant, LubricantSpec& l) {
    const YamlSection s(lubricant.source(), lubricant.get("supply"), lubricant.keyPath("supply"),
                        {"model", "thickness", "thickness_table", "replenish", "replenish_below_depth"});
    OilSupplySpec& o = l.supply;
    o.model = choice(s, "model", {"flooded", "liner_layer"}, 0) == 0 ? OilSupplyModel::Flooded : OilSupplyModel::LinerLayer;
    if (o.model == OilSupplyModel::Flooded) {
        for (const char* key : {"thickness", "thickness_table", "replenish", "replenish_below_depth"})
            if (s.has(key)) s.fail(key, "belongs to model: liner_layer; a flooded supply has no oil layer");
        return;
    }
    if (l.cavitation != CavitationModel::MassConserving)
        s.fail("model", "a liner oil layer needs lubricant.cavitation: mass_conserving (the Reynolds condition has no "
                        "film fraction, so it cannot carry a partial film)");
    if (s.has("thickness") == s.has("thickness_table"))
        s.fail(s.has("thickness") ? "thickness_table" : "model",
               "give the liner's oil layer as either thickness (m, constant) or thickness_table ([depth m, thickness m] "
               "rows), one of them");
    o.layer.clear();
    if (s.has("thickness")) {
        o.layer.push_back({0.0, number(s, "thickness", {"oil layer thickness", "m"}, Sign::NonNegative, 0.0)});
    } else {
        const YAML::Node list = s.get("thickness_table");
        const std::string expected = "a list of [depth, thickness] pairs in m, depth ascending";
        if (!list.IsSequence() || list.size() == 0) s.fail("thickness_table", "expected " + expected + ", got " + describe(list));
        for (std::size_t i = 0; i < list.size(); ++i) {
            const YAML::Node row = list[i];
            const std::string rowPath = fmt::format("{}[{}]", s.keyPath("thickness_table"), i);
            double depth = 0.0, t = 0.0;
            if (!row.IsSequence() || row.size() != 2 || !row[0].IsScalar() || !row[1].IsScalar() ||
                !parseNumber(row[0].Scalar(), depth) || !parseNumber(row[1].Scalar(), t))
                s.source().fail(rowPath, row, "expected a pair [depth, thickness] of numbers in m, got " + describe(row));
            if (!o.layer.empty() && !(depth > o.layer.back().depth))
                s.source().fail(rowPath, row,
                                fmt::format("depth must be strictly ascending: {:g} m follows {:g} m", depth, o.layer.back().depth));
            if (t < 0.0) s.source().fail(rowPath, row, fmt::format("expected a thickness >= 0 m, got {:g}", t));
            o.layer.push_back({depth, t});
        }
    }
    for (const OilLayerPoint& pt : o.layer)
        if (pt.thickness > 1e-3)
            s.fail(s.has("thickness") ? "thickness" : "thickness_table",
                   fmt::format("an oil layer of {:g} m is above 1 mm: check the units (m; 3 um = 3e-06)", pt.thickness));
    o.replenish = boolean(s, "replenish", true);
    if (s.has("replenish_below_depth")) {
        if (!o.replenish) s.fail("replenish_below_depth", "is the depth of the replenishment, which replenish: false turns off");
        o.replenishBelowDepth =
            number(s, "replenish_below_depth", {"depth below the deck", "m"}, Sign::NonNegative, 0.0);
    }
}

void readLubricant(const YamlSection& s, const EngineSpec& engine, LubricantSpec& l) {
    l.viscosity = number(s, "viscosity", {"dynamic viscosity", "Pa s"}, Sign::Positive, l.viscosity);
    l.density = number(s, "density", {"density", "kg/m^3"}, Sign::Positive, l.density);
    l.barusAlpha =
        number(s, "barus_alpha", {"pressure-viscosity coefficient", "1/Pa"}, Sign::NonNegative, l.barusAlpha);
    l.cavitationPressure = number(s, "cavitation_pressure", {"gauge pressure", "Pa"}, Sign::Any, l.cavitationPressure);
    if (l.viscosity > 10.0)
        s.fail("viscosity", fmt::format("{:g} Pa s is not an engine oil (0.002-0.1 Pa s): check the units (Pa s, "
                                        "not cP or mm^2/s)",
                                        l.viscosity));
    if (l.barusAlpha > 1e-7)
        s.fail("barus_alpha", fmt::format("expected a pressure-viscosity coefficient below 1e-7 1/Pa (oils: 1e-8 to "
                                          "3e-8), got {:g}",
                                          l.barusAlpha));
    l.cavitation = choice(s, "cavitation", {"reynolds", "mass_conserving"}, 0) == 0 ? CavitationModel::Reynolds
                                                                                : CavitationModel::MassConserving;
    if (l.cavitation == CavitationModel::MassConserving && l.barusAlpha > 0.0)
        s.fail("cavitation", "mass_conserving needs a constant viscosity (barus_alpha: 0): the mass-conserving film "
                             "solver has no pressure-dependent viscosity");
    readOilSupply(s, l);
    if (l.cavitationPressure > 0.0 || l.cavitationPressure < -engine.crankcasePressure)
        s.fail("cavitation_pressure",
               fmt::format("expected a gauge pressure between -crankcase_pressure ({:g} Pa) and 0, got {:g} Pa",
                           -engine.crankcasePressure, l.cavitationPressure));
}

void readContact(const YamlSection& s, ContactSpec& c) {
    c.sigma = number(s, "sigma", {"composite rms roughness", "m"}, Sign::Positive, c.sigma);
    c.beta = number(s, "beta", {"asperity tip radius", "m"}, Sign::Positive, c.beta);
    c.asperityDensity = number(s, "asperity_density", {"asperity density", "1/m^2"}, Sign::Positive, c.asperityDensity);
    c.boundaryFriction =
        number(s, "boundary_friction", {"friction coefficient", ""}, Sign::NonNegative, c.boundaryFriction);
    for (const auto& [key, k] : {std::pair{"piston_wear_coefficient", &c.pistonWearCoefficient},
                                 std::pair{"liner_wear_coefficient", &c.linerWearCoefficient}}) {
        *k = number(s, key, {"Archard wear coefficient", "m^2/N"}, Sign::NonNegative, *k);
        if (*k > 1e-10)
            s.fail(key, fmt::format("a wear coefficient of {:g} m^2/N is far above any engine material's (about 1e-18 "
                                    "to 1e-13 m^2/N): check the units (m^2/N = m^3/(N m))",
                                    *k));
    }
    if (c.boundaryFriction > 1.0)
        s.fail("boundary_friction",
               fmt::format("expected a friction coefficient between 0 and 1, got {:g}", c.boundaryFriction));
    if (c.sigma > 1e-4)
        s.fail("sigma", fmt::format("a roughness of {:g} m is above 100 um: check the units (m)", c.sigma));

    // E*: given directly, or from the two surfaces' elastic constants (Hertz: 1/E* = Σ (1−ν²)/E).
    const std::vector<std::string> materialKeys{"piston_youngs_modulus", "piston_poisson_ratio", "liner_youngs_modulus",
                                                "liner_poisson_ratio"};
    const bool anyMaterial =
        std::any_of(materialKeys.begin(), materialKeys.end(), [&](const auto& k) { return s.has(k); });
    if (s.has("composite_modulus") && anyMaterial)
        s.fail("composite_modulus",
               "give either composite_modulus or the four piston_/liner_ youngs_modulus and "
               "poisson_ratio keys, not both");
    if (anyMaterial) {
        double compliance = 0.0;
        for (const char* body : {"piston", "liner"}) {
            const std::string e = std::string(body) + "_youngs_modulus", nu = std::string(body) + "_poisson_ratio";
            const double E = number(s, e, {"Young's modulus", "Pa"}, Sign::Positive, 0.0, true);
            const double v = number(s, nu, {"Poisson's ratio", ""}, Sign::Any, 0.0, true);
            if (!(v > -1.0 && v < 0.5)) s.fail(nu, fmt::format("expected a Poisson's ratio in (-1, 0.5), got {:g}", v));
            compliance += (1.0 - v * v) / E;
        }
        c.compositeModulus = 1.0 / compliance;
    } else {
        c.compositeModulus = number(s, "composite_modulus", {"composite modulus E* (0 = contact off)", "Pa"},
                                    Sign::NonNegative, c.compositeModulus);
    }

    // Hard contact below h = 0: the coating as a bonded elastic layer, or the stiffness directly.
    const bool anyCoating = s.has("coating_thickness") || s.has("coating_youngs_modulus") || s.has("coating_poisson_ratio");
    if (s.has("hard_contact_stiffness") && anyCoating)
        s.fail("hard_contact_stiffness",
               "give either hard_contact_stiffness or the coating_ thickness / youngs_modulus / poisson_ratio keys, "
               "not both");
    c.coatingThickness = number(s, "coating_thickness", {"coating thickness", "m"}, Sign::Positive, c.coatingThickness);
    if (c.coatingThickness > 1e-3)
        s.fail("coating_thickness",
               fmt::format("a coating of {:g} m is thicker than 1 mm: check the units (m)", c.coatingThickness));
    c.coatingModulus =
        number(s, "coating_youngs_modulus", {"Young's modulus", "Pa"}, Sign::Positive, c.coatingModulus);
    c.coatingPoisson = number(s, "coating_poisson_ratio", {"Poisson's ratio", ""}, Sign::Any, c.coatingPoisson);
    if (!(c.coatingPoisson > -1.0 && c.coatingPoisson < 0.5))
        s.fail("coating_poisson_ratio",
               fmt::format("expected a Poisson's ratio in (-1, 0.5), got {:g}", c.coatingPoisson));
    c.hardContactStiffness = number(s, "hard_contact_stiffness", {"contact stiffness", "Pa/m"}, Sign::Positive,
                                    c.hardContactStiffness);
}

// ---- liner bore distortion and thermal displacements (BoreDistortion, ClearanceTerms) --

/// liner.bore_distortion: {format: fourier, file: CSV} | {format: fourier, orders: [...]} |
/// {format: nodal, file: CSV}. Tables are read and checked here; errors name the key.
void readLiner(const YamlSection& top, const EngineSpec& engine, LinerSpec& l) {
    const YamlSection s(top.source(), top.get("liner"), "liner", {"bore_distortion"});
    if (!s.has("bore_distortion")) return;
    const YamlSection d(s.source(), s.get("bore_distortion"), s.keyPath("bore_distortion"),
                    {"format", "file", "orders", "field"});
    BoreDistortionSpec& b = l.boreDistortion;
    if (!d.has("format")) d.missing("format", "fourier (orders per axial position) or nodal (an FE result)");
    const bool fourier = choice(d, "format", {"fourier", "nodal"}, 0) == 0;
    if (d.has("file") && d.has("orders"))
        d.fail("orders", "give either file (a CSV table) or orders (an inline table), not both");
    if (!fourier && d.has("orders"))
        d.fail("orders", "an inline table needs format: fourier; a nodal FE result is read from a file");
    if (!d.has("file") && !d.has("orders"))
        d.missing("file", fourier ? "the Fourier table (CSV), or an inline table under orders"
                                  : "the FE result on the bore (CSV: x, y, z, ux, uy, uz or ur; or a .vtu)");
    if (d.has("file")) {
        b.file = d.source().resolve(text(d, "file", "", "a file path")).string();
        if (d.has("field") && (fourier || !isVtuFile(b.file)))
            d.fail("field", "names the point-data array of a nodal result in a .vtu file; this table is a CSV");
        const std::string field = text(d, "field", "displacement", "the point-data array of the .vtu file");
        try {
            if (fourier)
                b.fourier = readFourierTable(b.file, engine.bore);
            else
                b.nodes = readBoreNodes(b.file, engine.bore, field);
        } catch (const std::exception& e) {
            d.fail("file", e.what());
        }
        b.format = fourier ? BoreDistortionFormat::Fourier : BoreDistortionFormat::Nodal;
        return;
    }
    const YAML::Node list = d.get("orders");
    const std::string expected = "a list of {z or depth, order, amplitude, phase or phase_deg} mappings";
    if (!list.IsSequence() || list.size() == 0) d.fail("orders", "expected " + expected + ", got " + describe(list));
    std::vector<std::string> paths;
    for (std::size_t i = 0; i < list.size(); ++i) {
        paths.push_back(fmt::format("{}[{}]", d.keyPath("orders"), i));
        const YamlSection e(d.source(), list[i], paths.back(), {"z", "depth", "order", "amplitude", "phase", "phase_deg"});
        if (!list[i].IsMap())
            d.source().fail(paths.back(), list[i], "expected " + expected + ", got " + describe(list[i]));
        FourierTerm t;
        if (e.has("z") == e.has("depth"))
            e.fail(e.has("z") ? "depth" : "z", "give exactly one of z (m, liner frame) and depth (m below the liner top)");
        t.z = e.has("z") ? number(e, "z", kLength, Sign::Any, 0.0) : -number(e, "depth", kLength, Sign::Any, 0.0);
        if (!e.has("order")) e.missing("order", "a whole number from 0 to 100 (the Fourier order)");
        t.order = integer(e, "order", 0, 100, 0, "");
        t.amplitude = number(e, "amplitude", {"radial amplitude", "m"}, Sign::Any, 0.0, true);
        if (e.has("phase") == e.has("phase_deg"))
            e.fail(e.has("phase") ? "phase_deg" : "phase", "give exactly one of phase (rad) and phase_deg (deg)");
        t.phase = e.has("phase") ? number(e, "phase", {"angle", "rad"}, Sign::Any, 0.0)
                                 : number(e, "phase_deg", {"angle", "deg"}, Sign::Any, 0.0) * kDeg;
        b.fourier.push_back(t);
    }
    if (const auto problem = checkFourierTerms(b.fourier, engine.bore))
        d.source().fail(paths[problem->index], list[problem->index],
             problem->message + (problem->first != problem->index ? " (first at " + paths[problem->first] + ")" : ""));
    sortFourierTerms(b.fourier);
    b.format = BoreDistortionFormat::Fourier;
}

/// thermal: {file: thermal.h5}. With options.checkBodyFiles the file is read and validated.
void readThermal(const YamlSection& top, const CaseFileOptions& options, ThermalSpec& t) {
    if (!top.has("thermal")) return;
    const YamlSection s(top.source(), top.get("thermal"), "thermal", {"file"});
    const std::string file =
        text(s, "file", "", "the thermal-displacement file (HDF5, from `flexehd thermal`)", true);
    t.file = s.source().resolve(file).string();
    if (options.checkBodyFiles) {
        try {
            (void)readThermalDisplacementFile(t.file);
        } catch (const std::exception& e) {
            s.fail("file", e.what());
        }
    }
}

BodySpec readBody(const YamlSection& bodies, const std::string& key, const std::string& defSurface,
                  const std::vector<std::string>& defInterfaces, const CaseFileOptions& options) {
    BodySpec b;
    if (!bodies.has(key)) return b;  // rigid
    const YAML::Node n = bodies.get(key);
    const std::string path = bodies.keyPath(key);
    const YamlSource& ctx = bodies.source();
    if (n.IsScalar()) {
        const std::string v(trim(n.Scalar()));
        if (v == "rigid") return b;
        ctx.fail(path, n,
             fmt::format("expected 'rigid' or a mapping {{file: ..., surface: ..., interface: ...}} for a flexible "
                         "body, got '{}'",
                         v));
    }
    if (!n.IsMap())
        ctx.fail(path, n,
             "expected 'rigid' or a mapping {file: ..., surface: ..., interface: ...}, got " + describe(n));
    const YamlSection s(ctx, n, path, {"file", "surface", "interface"});
    b.model = BodyModel::Flexible;
    const std::string file = text(s, "file", "", "the reduced-body file (HDF5, from `flexehd reduce`)", true);
    const fs::path resolved = ctx.resolve(file);
    b.file = resolved.string();
    if (options.checkBodyFiles) {
        std::error_code ec;
        if (!fs::exists(resolved, ec))
            s.fail("file", fmt::format("reduced-body file {} does not exist (make it with `flexehd reduce`)", b.file));
        if (fs::is_directory(resolved, ec))
            s.fail("file", fmt::format("{} is a directory, not a reduced-body file", b.file));
        if (!std::ifstream(resolved, std::ios::binary))
            s.fail("file", fmt::format("reduced-body file {} cannot be opened for reading", b.file));
        if (!looksLikeHdf5(resolved))
            s.fail("file",
                   fmt::format("{} is not an HDF5 file (expected a reduced body from `flexehd reduce`)", b.file));
    }
    b.surface = text(s, "surface", defSurface, "the name of a physical surface");
    b.interfaces = defInterfaces;
    if (s.has("interface")) {
        const YAML::Node itf = s.get("interface");
        const std::string expected = "an interface name or a list of them";
        b.interfaces.clear();
        if (itf.IsScalar() && !trim(itf.Scalar()).empty()) {
            b.interfaces.emplace_back(trim(itf.Scalar()));
        } else if (itf.IsSequence() && itf.size() > 0) {
            for (std::size_t i = 0; i < itf.size(); ++i) {
                if (!itf[i].IsScalar() || trim(itf[i].Scalar()).empty())
                    ctx.fail(fmt::format("{}[{}]", s.keyPath("interface"), i), itf[i],
                         "expected an interface name, got " + describe(itf[i]));
                const std::string name(trim(itf[i].Scalar()));
                if (std::find(b.interfaces.begin(), b.interfaces.end(), name) != b.interfaces.end())
                    ctx.fail(fmt::format("{}[{}]", s.keyPath("interface"), i), itf[i], "interface listed twice");
                b.interfaces.push_back(name);
            }
        } else {
            s.fail("interface", "expected " + expected + ", got " + describe(itf));
        }
    }
    b.interface = b.interfaces.empty() ? std::string() : b.interfaces.front();
    return b;
}

}  // namespace

std::vector<PressureSample> readPressureTable(const std::string& path) {
    std::string error;
    const std::string content = readWholeFile(path, error);
    if (!error.empty()) throw std::runtime_error(path + ": " + error);
    std::vector<PressureSample> samples;
    std::vector<int> lines;
    std::istringstream in(content);
    DataLines table(in);
    bool headerAllowed = true;
    while (table.next()) {
        const int lineNo = table.number();
        const std::string_view line = table.text();
        const std::vector<std::string_view> fields = splitFields(line);
        double angle = 0.0, pressure = 0.0;
        const bool firstIsNumber = !fields.empty() && parseNumber(fields[0], angle);
        if (headerAllowed && !firstIsNumber) {  // a header line
            headerAllowed = false;
            continue;
        }
        headerAllowed = false;
        if (fields.size() != 2 || !firstIsNumber || !parseNumber(fields[1], pressure))
            throw std::runtime_error(
                fmt::format("{}:{}: expected two numbers, crank angle in deg and absolute pressure in Pa, got '{}'",
                            path, lineNo, line));
        samples.push_back({angle, pressure});
        lines.push_back(lineNo);
    }
    try {
        const CylinderPressure check(samples);
        if (check.peak() < 1e4)
            throw std::runtime_error(
                fmt::format("{}: the peak pressure is {:g}: the table must hold absolute pressures in Pa (bar or MPa?)",
                            path, check.peak()));
    } catch (const PressureTableError& e) {
        if (e.sample() == PressureTableError::npos) throw std::runtime_error(path + ": " + e.reason());
        throw std::runtime_error(fmt::format("{}:{}: {}", path, lines[e.sample()], e.reason()));
    }
    return samples;
}

namespace {

YAML::Node loadCaseYaml(const std::string& path, const fs::path& absolute) {
    std::string error;
    const std::string content = readWholeFile(absolute, error);
    if (!error.empty()) throw std::runtime_error(path + ": cannot read the case file: " + error);
    YAML::Node root;
    try {
        root = YAML::Load(content);
    } catch (const YAML::Exception& e) {
        throw std::runtime_error(
            fmt::format("{}:{}:{}: YAML syntax error: {}", path, e.mark.line + 1, e.mark.column + 1, e.msg));
    }
    if (!root.IsDefined() || root.IsNull()) throw std::runtime_error(path + ": the case file is empty");
    return root;
}

// engine.pin_tdc_depth where the liner's tables or mesh need the piston placed on them.
void requirePinTdcDepth(const YamlSection& engine, const EngineCase& c) {
    if ((c.liner.boreDistortion.format != BoreDistortionFormat::None || !c.thermal.file.empty()) &&
        !engine.has("pin_tdc_depth"))
        engine.missing("pin_tdc_depth",
                       "the depth of the pin axis below the deck at TDC in m (required with liner.bore_distortion "
                       "or thermal: it places the piston on the liner's tables)");
    if (c.linerBody.model == BodyModel::Flexible && !engine.has("pin_tdc_depth"))
        engine.missing("pin_tdc_depth",
                       "the depth of the pin axis below the deck at TDC in m (required with a "
                       "flexible liner: it places the piston on the liner mesh)");
}

// The skirt top below the deck at TDC.
void requireSkirtBelowDeck(const YamlSection& engine, const EngineCase& c) {
    if ((engine.has("pin_tdc_depth") || c.linerBody.model == BodyModel::Flexible) &&
        !(c.engine.pinTdcDepth > c.piston.skirtTop))
        engine.fail("pin_tdc_depth",
                    fmt::format("at TDC the skirt top (piston.skirt_top = {:g} m above the pin) would stand above the "
                                "deck: pin_tdc_depth must exceed it, got {:g} m",
                                c.piston.skirtTop, c.engine.pinTdcDepth));
}

void readCylinderPressure(const YamlSection& top, const YamlSource& ctx, EngineCase& c) {
    const std::string csv =
        text(top, "cylinder_pressure", "",
             "the path of the cylinder-pressure CSV (crank angle in deg, pressure in Pa)", true);
    const fs::path resolved = ctx.resolve(csv);
    c.cylinderPressureFile = resolved.string();
    try {
        c.cylinderPressure = readPressureTable(c.cylinderPressureFile);
    } catch (const std::exception& e) {
        top.fail("cylinder_pressure", e.what());
    }
}

void readGrid(const YamlSection& grid, const PistonSpec& piston, GridSpec& g) {
    g.axialNodes = integer(grid, "axial_nodes", 3, 100000, g.axialNodes, "nodes");
    g.circumferentialNodes = integer(grid, "circumferential_nodes", 8, 100000, g.circumferentialNodes, "nodes");
    // Each skirt panel (2 × half angle wide) must hold at least 3 grid columns.
    const double spacing = 2 * kPi / g.circumferentialNodes;
    const double halfAngle = std::min(piston.skirtHalfAngle, kPi / 2);
    if (2 * halfAngle / spacing < 2.0)
        grid.fail("circumferential_nodes",
                  fmt::format("{} nodes around the circumference leave fewer than 3 across a skirt panel of {:g} "
                              "deg; use at least {}",
                              g.circumferentialNodes, 2 * halfAngle / kDeg,
                              static_cast<int>(std::ceil(2.0 * 2 * kPi / (2 * halfAngle)))));
}

void readTime(const YamlSection& time, TimeSpec& t) {
    t.startDeg = number(time, "start_deg", {"crank angle", "deg"}, Sign::NonNegative, t.startDeg);
    if (!(t.startDeg < 720.0))
        time.fail("start_deg", fmt::format("expected a crank angle in [0, 720) deg, got {:g}", t.startDeg));
    t.maxStepDeg = number(time, "max_step_deg", {"crank-angle step", "deg"}, Sign::Positive, t.maxStepDeg);
    t.minStepDeg = number(time, "min_step_deg", {"crank-angle step", "deg"}, Sign::Positive, t.minStepDeg);
    if (t.maxStepDeg > 10.0)
        time.fail("max_step_deg", fmt::format("expected at most 10 deg, got {:g}", t.maxStepDeg));
    if (!(t.maxStepDeg >= t.minStepDeg))
        time.fail(
            time.has("max_step_deg") ? "max_step_deg" : "min_step_deg",
            fmt::format("expected max_step_deg ({:g}) >= min_step_deg ({:g})", t.maxStepDeg, t.minStepDeg));
    t.lateralTolerance =
        number(time, "lateral_tolerance", {"length", "m"}, Sign::Positive, t.lateralTolerance);
    if (time.has("tilt_tolerance_deg"))
        t.tiltTolerance = number(time, "tilt_tolerance_deg", {"angle", "deg"}, Sign::Positive, 0.0) * kDeg;
    t.maxCycles = integer(time, "max_cycles", 1, 1000, t.maxCycles, "cycles");
    t.periodicityTolerance =
        number(time, "periodicity_tolerance", {"length", "m"}, Sign::Positive, t.periodicityTolerance);
    t.oilPeriodicityTolerance = number(time, "oil_periodicity_tolerance", {"relative change of the oil volume", ""},
                                       Sign::Positive, t.oilPeriodicityTolerance);
}

void readCoupling(const YamlSection& coupling, CouplingSpec& k) {
    k.tolerance =
        number(coupling, "tolerance", {"relative tolerance", ""}, Sign::Positive, k.tolerance);
    if (!(k.tolerance < 1.0))
        coupling.fail("tolerance",
                      fmt::format("expected a relative tolerance below 1, got {:g}", k.tolerance));
    k.maxIterations = integer(coupling, "max_iterations", 1, 10000, k.maxIterations, "iterations");
    k.acceleration = choice(coupling, "acceleration", {"iqn-ils", "aitken"}, 0) == 0
                                  ? CouplingAcceleration::IqnIls
                                  : CouplingAcceleration::Aitken;
    k.method = choice(coupling, "method", {"newton", "partitioned"}, 0) == 0 ? CouplingMethod::Newton
                                                                                      : CouplingMethod::Partitioned;
    // Default: the whole film thickness's rate with the Newton method (the partitioned iteration
    // cannot carry it; docs/coupling.md section 3).
    k.elasticSqueeze =
        boolean(coupling, "elastic_squeeze", k.method == CouplingMethod::Newton);
    if (k.elasticSqueeze && k.method == CouplingMethod::Partitioned)
        coupling.fail("elastic_squeeze",
                      "the elastic deformation rate in the squeeze term needs coupling.method: newton (the partitioned "
                      "iteration's gain grows as 1/time step and does not converge with it; docs/coupling.md section 3)");
}

void readOutput(const YamlSection& output, const YamlSource& ctx, OutputSpec& o) {
    const fs::path dir = ctx.resolve(text(output, "directory", "results", "a directory path"));
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        output.fail("directory", fmt::format("{} exists and is not a directory", dir.string()));
    o.directory = dir.string();
    o.vtkEveryDeg = number(output, "vtk_every_deg", {"crank-angle spacing (0 = no VTK)", "deg"}, Sign::NonNegative,
                           o.vtkEveryDeg);
    if (o.vtkEveryDeg > 720.0 || (o.vtkEveryDeg > 0.0 && o.vtkEveryDeg < 0.01))
        output.fail("vtk_every_deg",
                    fmt::format("expected 0 (no VTK) or 0.01 to 720 deg, got {:g}: a snapshot every 0.01 deg is already "
                                "72 000 files per cycle, and snapshots closer than the time steps only shorten them",
                                o.vtkEveryDeg));
    o.modeShapes = boolean(output, "mode_shapes", o.modeShapes);
}

// The mass-conserving film with a flexible body: the coupled Newton method, on a flooded supply
// (docs/coupling.md §6).
void requireSupportedMassConserving(const YamlSection& lubricant, const YamlSection& coupling, const EngineCase& c) {
    const bool flexible = c.pistonBody.model == BodyModel::Flexible || c.linerBody.model == BodyModel::Flexible;
    if (c.lubricant.cavitation != CavitationModel::MassConserving || !flexible) return;
    if (c.coupling.method == CouplingMethod::Partitioned)
        coupling.fail("method", "partitioned does not converge with lubricant.cavitation: mass_conserving and a flexible "
                                "body: the film's content term carries the elastic thickness change, a coupling gain "
                                "that grows as 1/dt (docs/coupling.md section 6). Use coupling.method: newton (the "
                                "default)");
    if (c.lubricant.supply.model == OilSupplyModel::LinerLayer)
        lubricant.fail("supply", "model: liner_layer runs with rigid bodies only: with a flexible body the coupled "
                                 "Newton iteration does not converge on the starved film (its linearisation holds the "
                                 "full-film / cavitated partition, and a starved film's meniscus moves with the "
                                 "deformation; docs/coupling.md section 6). Use rigid bodies (flexehd run --rigid), or "
                                 "the flooded supply with flexible ones");
}

}  // namespace

EngineCase readCaseFile(const std::string& path, const CaseFileOptions& options) {
    const fs::path absolute = fs::absolute(fs::path(path)).lexically_normal();
    YamlSource ctx{path, absolute.parent_path()};

    const YAML::Node root = loadCaseYaml(path, absolute);
    const YamlSection top(ctx, root, "",
                      {"name", "engine", "piston", "lubricant", "contact", "cylinder_pressure", "bodies", "grid",
                       "time", "coupling", "output", "liner", "thermal"});
    EngineCase c;
    c.path = absolute.string();
    c.name = text(top, "name", absolute.stem().string(), "a name (text)");

    // Bodies first: whether the liner is flexible decides whether engine.pin_tdc_depth is required.
    const YamlSection bodies(ctx, top.get("bodies"), "bodies", {"piston", "liner", "response"});
    c.pistonBody = readBody(bodies, "piston", "skirt", {"pin_bore"}, options);
    c.linerBody = readBody(bodies, "liner", "bore", {"top_seat", "bottom_seat"}, options);
    if (options.rigidBodies) c.pistonBody.model = c.linerBody.model = BodyModel::Rigid;
    c.coupling.response = choice(bodies, "response", {"quasi_static", "dynamic"}, 0) == 0 ? ElasticResponse::QuasiStatic
                                                                                          : ElasticResponse::Dynamic;

    if (!top.has("engine")) top.missing("engine", "the engine section (bore, stroke, rod_length, speed_rpm, ...)");
    const YamlSection engine(
        ctx, top.get("engine"), "engine",
        {"bore", "stroke", "rod_length", "pin_offset", "speed_rpm", "crankcase_pressure", "pin_tdc_depth"});
    readEngine(engine, c.engine);
    readLiner(top, c.engine, c.liner);
    readThermal(top, options, c.thermal);
    requirePinTdcDepth(engine, c);

    if (!top.has("piston")) top.missing("piston", "the piston section (mass, pin_mass, inertia, skirt_top, ...)");
    const YamlSection piston(ctx, top.get("piston"), "piston",
                         {"mass", "pin_mass", "inertia", "cg_x", "cg_z", "skirt_top", "skirt_bottom", "clearance",
                          "skirt_half_angle_deg", "profile", "ovality"});
    readPiston(piston, c.engine, c.piston);
    requireSkirtBelowDeck(engine, c);

    const YamlSection lubricant(ctx, top.get("lubricant"), "lubricant",
                            {"viscosity", "density", "barus_alpha", "cavitation_pressure", "cavitation", "supply"});
    readLubricant(lubricant, c.engine, c.lubricant);

    const YamlSection contact(
        ctx, top.get("contact"), "contact",
        {"sigma", "beta", "asperity_density", "composite_modulus", "boundary_friction", "piston_youngs_modulus",
         "piston_poisson_ratio", "liner_youngs_modulus", "liner_poisson_ratio", "coating_thickness",
         "coating_youngs_modulus", "coating_poisson_ratio", "hard_contact_stiffness", "piston_wear_coefficient",
         "liner_wear_coefficient"});
    readContact(contact, c.contact);

    readCylinderPressure(top, ctx, c);

    const YamlSection grid(ctx, top.get("grid"), "grid", {"axial_nodes", "circumferential_nodes"});
    readGrid(grid, c.piston, c.grid);

    const YamlSection time(ctx, top.get("time"), "time",
                       {"start_deg", "max_step_deg", "min_step_deg", "lateral_tolerance", "tilt_tolerance_deg",
                        "max_cycles", "periodicity_tolerance", "oil_periodicity_tolerance"});
    readTime(time, c.time);

    const YamlSection coupling(ctx, top.get("coupling"), "coupling", {"tolerance", "max_iterations", "method", "acceleration", "elastic_squeeze"});
    readCoupling(coupling, c.coupling);
    requireSupportedMassConserving(lubricant, coupling, c);
    const YamlSection output(ctx, top.get("output"), "output", {"directory", "vtk_every_deg", "mode_shapes"});
    readOutput(output, ctx, c.output);
    return c;
}

}  // namespace flexehd::cosim
