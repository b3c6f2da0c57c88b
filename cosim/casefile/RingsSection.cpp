// rings: the piston's ring pack, top ring first (docs/case-file.md, "rings").
#include "cosim/casefile/CaseSections.hpp"

#include <cmath>
#include <filesystem>
#include <string>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "cosim/io/YamlDocument.hpp"
#include "cosim/io/YamlKeys.hpp"

namespace flexehd::cosim::casefile {
namespace {

// A size sanity bound: a ring dimension above 10 % of the bore is a unit mistake.
void requireBelowBoreShare(const YamlSection& s, const char* key, double value, double bore) {
    if (value > 0.1 * bore)
        s.fail(key, fmt::format("{:g} m is more than 10% of the bore ({:g} m): check the units (m; 1.2 mm = 0.0012)",
                                value, bore));
}

// face: a barrel (crown_height, vertex_offset) or a table of [x, drop] rows across the face.
RingFaceSpec readFace(const YamlSection& ring, double height) {
    if (!ring.has("face"))
        ring.missing("face", "the running face: crown_height and vertex_offset (barrel) or table ([x, drop] rows, m)");
    const YamlSection s(ring.source(), ring.get("face"), ring.keyPath("face"), {"crown_height", "vertex_offset", "table"});
    RingFaceSpec f;
    if (s.has("table") == (s.has("crown_height") || s.has("vertex_offset")))
        s.fail(s.has("table") ? "table" : "crown_height",
               "give the face either as a barrel (crown_height, vertex_offset) or as a table ([x, drop] rows), one of them");
    if (!s.has("table")) {
        f.crownHeight = number(s, "crown_height", {"barrel crown height", "m"}, Sign::NonNegative, 0.0, true);
        f.vertexOffset = number(s, "vertex_offset", {"offset of the barrel's vertex towards the crown", "m"}, Sign::Any, 0.0);
        if (!(std::abs(f.vertexOffset) < 0.5 * height))
            s.fail("vertex_offset", fmt::format("the vertex must lie on the face: |vertex_offset| < height/2 = {:g} m, "
                                                "got {:g} m",
                                                0.5 * height, f.vertexOffset));
        if (f.crownHeight > 0.1 * height)
            s.fail("crown_height", fmt::format("a crown of {:g} m on a face {:g} m high is more than 10% of it: check "
                                               "the units (m; 5 um = 5e-06)",
                                               f.crownHeight, height));
        return f;
    }
    const YAML::Node list = s.get("table");
    const std::string path = s.keyPath("table");
    if (!list.IsSequence() || list.size() < 2)
        s.fail("table", "expected at least two [x, drop] rows in m (x across the face from its centre, ascending), got " +
                            describeNode(list));
    for (std::size_t i = 0; i < list.size(); ++i) {
        const YAML::Node row = list[i];
        const std::string rowPath = fmt::format("{}[{}]", path, i);
        double x = 0.0, drop = 0.0;
        if (!row.IsSequence() || row.size() != 2 || !row[0].IsScalar() || !row[1].IsScalar() ||
            !parseNumber(row[0].Scalar(), x) || !parseNumber(row[1].Scalar(), drop))
            s.source().fail(rowPath, row, "expected a pair [x, drop] of numbers in m, got " + describeNode(row));
        if (!f.table.empty() && !(x > f.table.back().first))
            s.source().fail(rowPath, row,
                            fmt::format("x must be strictly ascending: {:g} m follows {:g} m", x, f.table.back().first));
        if (std::abs(x) > 0.5 * height * (1.0 + 1e-9))
            s.source().fail(rowPath, row,
                            fmt::format("x = {:g} m lies beyond the face: |x| <= height/2 = {:g} m", x, 0.5 * height));
        if (!(drop >= 0.0) || drop > 0.1 * height)
            s.source().fail(rowPath, row,
                            fmt::format("expected a radial drop from 0 to 10% of the ring height ({:g} m), got {:g} m",
                                        0.1 * height, drop));
        f.table.emplace_back(x, drop);
    }
    return f;
}

// lands: the oil-control ring's two rails, symmetric about its mid-height.
OilControlLandsSpec readLands(const YamlSection& ring, double height) {
    if (!ring.has("lands")) ring.missing("lands", "the oil-control ring's two lands: width, separation, crown_height (m)");
    const YamlSection s(ring.source(), ring.get("lands"), ring.keyPath("lands"), {"width", "separation", "crown_height"});
    OilControlLandsSpec l;
    l.width = number(s, "width", {"axial width of each land", "m"}, Sign::Positive, 0.0, true);
    l.separation = number(s, "separation", {"distance between the lands' centres", "m"}, Sign::Positive, 0.0, true);
    l.crownHeight = number(s, "crown_height", {"barrel crown height of each land", "m"}, Sign::NonNegative, 0.0, true);
    if (!(l.separation >= l.width))
        s.fail("separation", fmt::format("the lands overlap: separation must be at least the land width {:g} m, got {:g} m",
                                         l.width, l.separation));
    if (l.separation + l.width > height * (1.0 + 1e-9))
        s.fail("separation", fmt::format("the lands ({:g} m apart, {:g} m wide) do not fit the ring's height {:g} m",
                                         l.separation, l.width, height));
    if (l.crownHeight > 0.1 * l.width)
        s.fail("crown_height", fmt::format("a crown of {:g} m on a land {:g} m wide is more than 10% of it: check the "
                                           "units (m)",
                                           l.crownHeight, l.width));
    return l;
}

RingGrooveSpec readGroove(const YamlSection& ring, double bore) {
    if (!ring.has("groove")) ring.missing("groove", "the ring's groove: lower_flank, side_clearance, back_clearance (m)");
    const YamlSection s(ring.source(), ring.get("groove"), ring.keyPath("groove"),
                        {"lower_flank", "side_clearance", "back_clearance"});
    RingGrooveSpec g;
    g.lowerFlank = number(s, "lower_flank", {"piston-frame z of the groove's lower flank", "m"}, Sign::Any, 0.0, true);
    g.sideClearance = number(s, "side_clearance", {"groove width minus ring height", "m"}, Sign::Any, 0.0, true);
    if (!(g.sideClearance > 0.0))
        s.fail("side_clearance", fmt::format("the ring is as tall as its groove or taller: the groove's width minus the "
                                             "ring's height must be positive, got {:g} m",
                                             g.sideClearance));
    g.backClearance = number(s, "back_clearance", {"radial space behind the ring", "m"}, Sign::NonNegative, 0.0, true);
    requireBelowBoreShare(s, "side_clearance", g.sideClearance, bore);
    requireBelowBoreShare(s, "back_clearance", g.backClearance, bore);
    return g;
}

// tangential_force (N, at the closed gap) or elastic_pressure (Pa) as the load per unit
// circumference on the bore: 2 F_t / D, or p_e times the ring's contact height (the lands' for
// the oil-control ring).
double readTension(const YamlSection& s, const RingSpec& r, double bore) {
    if (s.has("tangential_force") == s.has("elastic_pressure"))
        s.fail(s.has("tangential_force") ? "elastic_pressure" : "tangential_force",
               "give the ring's tension either as tangential_force (N at the closed gap) or as elastic_pressure (Pa), "
               "one of them");
    if (s.has("tangential_force"))
        return 2.0 * number(s, "tangential_force", {"tangential force at the closed gap", "N"}, Sign::Positive, 0.0) / bore;
    const double contactHeight = r.lands ? 2.0 * r.lands->width : r.height;
    return number(s, "elastic_pressure", {"elastic pressure on the bore", "Pa"}, Sign::Positive, 0.0) * contactHeight;
}

RingSpec readRing(const YamlSection& s, double bore, double sigma) {
    RingSpec r;
    r.name = text(s, "name", "", "a name (text)", true);
    const std::size_t kind = choice(s, "kind", {"compression", "scraper", "oil_control"}, 0);
    r.kind = kind == 0 ? RingKind::Compression : kind == 1 ? RingKind::Scraper : RingKind::OilControl;
    if (!s.has("kind")) s.missing("kind", "compression, scraper or oil_control");
    r.height = number(s, "height", {"axial height", "m"}, Sign::Positive, 0.0, true);
    r.radialWidth = number(s, "radial_width", {"radial width", "m"}, Sign::Positive, 0.0, true);
    requireBelowBoreShare(s, "height", r.height, bore);
    requireBelowBoreShare(s, "radial_width", r.radialWidth, bore);
    if (r.kind == RingKind::OilControl) {
        if (s.has("face")) s.fail("face", "an oil-control ring runs on its two lands: give lands, not face");
        r.lands = readLands(s, r.height);
    } else {
        if (s.has("lands")) s.fail("lands", "lands belong to kind: oil_control; this ring runs on its face");
        r.face = readFace(s, r.height);
    }
    r.tensionPerLength = readTension(s, r, bore);
    r.closedGap = number(s, "closed_gap", {"end gap of the closed ring", "m"}, Sign::Positive, 0.0, true);
    requireBelowBoreShare(s, "closed_gap", r.closedGap, bore);
    r.mass = number(s, "mass", kMass, Sign::Positive, 0.0, true);
    if (r.mass > 1.0) s.fail("mass", fmt::format("a ring of {:g} kg: check the units (kg; 6 g = 0.006)", r.mass));
    r.roughness = number(s, "roughness", {"composite rms roughness of the face and the liner", "m"}, Sign::Positive, sigma);
    if (r.roughness > 1e-4)
        s.fail("roughness", fmt::format("an rms roughness of {:g} m: check the units (m; 0.3 um = 3e-07)", r.roughness));
    r.groove = readGroove(s, bore);
    return r;
}

// The ring belt: each groove above the skirt and, at TDC, below the deck; top ring first and no
// two grooves overlapping. `groove` is the ring's groove section (for the messages).
void placeOnPiston(const YamlSection& groove, const RingSpec& r, const RingSpec* above, const EngineCase& c) {
    auto fail = [&](const std::string& msg) { groove.fail("lower_flank", fmt::format("ring '{}': {}", r.name, msg)); };
    if (r.groove.lowerFlank < c.piston.skirtTop)
        fail(fmt::format("the groove must lie on the ring belt above the skirt: its lower flank at or above "
                         "piston.skirt_top = {:g} m, got {:g} m",
                         c.piston.skirtTop, r.groove.lowerFlank));
    if (!(r.grooveTop() < c.engine.pinTdcDepth))
        fail(fmt::format("at TDC the groove (up to {:g} m above the pin) would stand above the deck and the ring leave "
                         "the liner: it must lie below engine.pin_tdc_depth = {:g} m",
                         r.grooveTop(), c.engine.pinTdcDepth));
    if (above && !(r.grooveTop() <= above->groove.lowerFlank))
        fail(fmt::format("the rings are listed top ring first and their grooves may not overlap: this groove reaches "
                         "up to {:g} m, above the lower flank of ring '{}' ({:g} m)",
                         r.grooveTop(), above->name, above->groove.lowerFlank));
}

// The rings' list: in the case file, or in the YAML file it names (its key `rings`).
struct RingList {
    YamlSource source;
    YAML::Node list;
    std::string path;  // "rings"
};

RingList ringList(const YamlSection& top) {
    const YAML::Node node = top.get("rings");
    if (!node.IsScalar()) return {top.source(), node, "rings"};
    const std::filesystem::path file = top.source().resolve(node.Scalar());
    YAML::Node root;
    try {
        root = loadYamlDocument(file.string(), "the ring-pack file");
    } catch (const std::runtime_error& e) {
        top.fail("rings", e.what());
    }
    RingList r{{file.string(), file.parent_path()}, YAML::Node(), "rings"};
    const YamlSection fileTop(r.source, root, "", {"rings"});
    if (!fileTop.hasValue("rings")) fileTop.missing("rings", "the ring pack: a list of rings, top ring first");
    r.list = root["rings"];
    return r;
}

}  // namespace

void readRings(const YamlSection& top, const YamlSection& engine, EngineCase& c) {
    c.rings.clear();
    if (!top.hasValue("rings")) return;
    if (!engine.has("pin_tdc_depth"))
        engine.missing("pin_tdc_depth", "the depth of the pin axis below the deck at TDC in m (required with rings: it "
                                        "places the rings on the liner)");
    const RingList rings = ringList(top);
    if (!rings.list.IsSequence() || rings.list.size() == 0)
        rings.source.fail(rings.path, rings.list,
                          "expected a list of rings, top ring first (name, kind, height, ...), got " +
                              describeNode(rings.list));
    for (std::size_t i = 0; i < rings.list.size(); ++i) {
        const YamlSection s(rings.source, rings.list[i], fmt::format("{}[{}]", rings.path, i),
                            {"name", "kind", "height", "radial_width", "face", "lands", "tangential_force",
                             "elastic_pressure", "closed_gap", "mass", "roughness", "groove"});
        RingSpec r = readRing(s, c.engine.bore, c.contact.sigma);
        for (const RingSpec& other : c.rings)
            if (other.name == r.name) s.fail("name", fmt::format("the name '{}' is given to two rings", r.name));
        placeOnPiston(YamlSection(s.source(), s.get("groove"), s.keyPath("groove"),
                                  {"lower_flank", "side_clearance", "back_clearance"}),
                      r,
                      c.rings.empty() ? nullptr : &c.rings.back(), c);
        c.rings.push_back(std::move(r));
    }
}

void readRingGas(const YamlSection& top, EngineCase& c) {
    c.ringGas = RingGasSpec{};
    if (!top.has("ring_gas")) return;
    const YamlSection g(top.source(), top.get("ring_gas"), "ring_gas",
                        {"model", "discharge_coefficient", "land_clearance", "land_temperatures", "ring_lift"});
    RingGasSpec& r = c.ringGas;
    r.model = choice(g, "model", {"none", "lands"}, 0) == 1 ? RingGasModel::Lands : RingGasModel::None;
    r.dischargeCoefficient =
        number(g, "discharge_coefficient", {"discharge coefficient", ""}, Sign::Positive, r.dischargeCoefficient);
    if (r.dischargeCoefficient > 1.0)
        g.fail("discharge_coefficient", fmt::format("expected a discharge coefficient in (0, 1], got {:g}",
                                                    r.dischargeCoefficient));
    r.landClearance = number(g, "land_clearance", kLength, Sign::Positive, r.landClearance);
    r.ringLift = boolean(g, "ring_lift", r.ringLift);
    if (g.has("land_temperatures")) {
        const YAML::Node list = g.get("land_temperatures");
        const std::string expected = fmt::format("a list of {} temperatures in K (one per land between the rings, "
                                                 "top first)", c.rings.empty() ? 0 : c.rings.size() - 1);
        if (!list.IsSequence() || c.rings.empty() || list.size() != c.rings.size() - 1)
            g.fail("land_temperatures", "expected " + expected + ", got " + describeNode(list));
        for (std::size_t i = 0; i < list.size(); ++i) {
            double t = 0.0;
            if (!list[i].IsScalar() || !parseNumber(list[i].Scalar(), t) || !(t > 0.0) || !std::isfinite(t))
                g.source().fail(fmt::format("{}[{}]", g.keyPath("land_temperatures"), i), list[i],
                                "expected a positive temperature in K, got " + describeNode(list[i]));
            r.landTemperatures.push_back(t);
        }
    }
    if (r.model == RingGasModel::None) return;
    if (c.rings.empty()) g.fail("model", "the gas between the rings needs a ring pack (case key rings)");
    for (std::size_t i = 0; i + 1 < c.rings.size(); ++i)
        if (!(c.rings[i + 1].grooveTop() < c.rings[i].groove.lowerFlank))
            g.fail("model", fmt::format("rings '{}' and '{}' have no land between their grooves (the lower one's "
                                        "reaches up to {:g} m, the upper one's lower flank is at {:g} m): the gas "
                                        "between them has no volume",
                                        c.rings[i + 1].name, c.rings[i].name, c.rings[i + 1].grooveTop(),
                                        c.rings[i].groove.lowerFlank));
}

}  // namespace flexehd::cosim::casefile
