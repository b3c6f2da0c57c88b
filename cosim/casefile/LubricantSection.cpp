// lubricant: the oil's properties, the cavitation model and the oil supply (docs/case-file.md,
// "lubricant").
#include "cosim/casefile/CaseSections.hpp"

#include <string>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "cosim/io/YamlKeys.hpp"

namespace flexehd::cosim::casefile {

namespace {

// lubricant.supply.oil_control_ring: the ring's band on the piston and the layer it leaves (its
// place against the skirt and the deck is checked with the piston's, CrossSectionChecks).
OilControlRingSpec readOilControlRing(const YamlSection& supply) {
    const YamlSection s(supply.source(), supply.get("oil_control_ring"), supply.keyPath("oil_control_ring"),
                        {"bottom", "top", "thickness"});
    OilControlRingSpec r;
    r.bottom = number(s, "bottom", {"piston-frame z of the ring's lower edge", "m"}, Sign::Any, 0.0, true);
    r.top = number(s, "top", {"piston-frame z of the ring's upper edge", "m"}, Sign::Any, 0.0, true);
    if (!(r.top > r.bottom))
        s.fail("top", fmt::format("the ring's upper edge must lie above its lower edge (bottom = {:g} m), got {:g} m",
                                  r.bottom, r.top));
    r.thickness = number(s, "thickness", {"oil layer the ring leaves on the liner", "m"}, Sign::NonNegative, 0.0, true);
    if (r.thickness > 1e-3)
        s.fail("thickness", fmt::format("an oil layer of {:g} m is above 1 mm: check the units (m; 3 um = 3e-06)",
                                        r.thickness));
    return r;
}

// lubricant.supply (docs/case-file.md): flooded, or the liner's oil layer (constant or a table over
// the depth below the deck) with its replenishment.
void readOilSupply(const YamlSection& lubricant, LubricantSpec& l) {
    const YamlSection s(lubricant.source(), lubricant.get("supply"), lubricant.keyPath("supply"),
                        {"model", "thickness", "thickness_table", "replenish", "replenish_below_depth",
                         "oil_control_ring"});
    OilSupplySpec& o = l.supply;
    o.model = choice(s, "model", {"flooded", "liner_layer"}, 0) == 0 ? OilSupplyModel::Flooded : OilSupplyModel::LinerLayer;
    if (o.model == OilSupplyModel::Flooded) {
        for (const char* key : {"thickness", "thickness_table", "replenish", "replenish_below_depth", "oil_control_ring"})
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
        if (!list.IsSequence() || list.size() == 0) s.fail("thickness_table", "expected " + expected + ", got " + describeNode(list));
        for (std::size_t i = 0; i < list.size(); ++i) {
            const YAML::Node row = list[i];
            const std::string rowPath = fmt::format("{}[{}]", s.keyPath("thickness_table"), i);
            double depth = 0.0, t = 0.0;
            if (!row.IsSequence() || row.size() != 2 || !row[0].IsScalar() || !row[1].IsScalar() ||
                !parseNumber(row[0].Scalar(), depth) || !parseNumber(row[1].Scalar(), t))
                s.source().fail(rowPath, row, "expected a pair [depth, thickness] of numbers in m, got " + describeNode(row));
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
    if (s.has("oil_control_ring")) o.oilControlRing = readOilControlRing(s);
}

}  // namespace

YamlSection readLubricant(const YamlSection& top, const EngineSpec& engine, LubricantSpec& l) {
    const YamlSection s(top.source(), top.get("lubricant"), "lubricant",
                        {"viscosity", "density", "barus_alpha", "cavitation_pressure", "cavitation", "supply"});
    l.viscosity = number(s, "viscosity", {"dynamic viscosity", "Pa s"}, Sign::Positive, l.viscosity);
    l.density = number(s, "density", {"density", "kg/m^3"}, Sign::Positive, l.density);
    l.barusAlpha =
        number(s, "barus_alpha", {"pressure-viscosity coefficient", "1/Pa"}, Sign::NonNegative, l.barusAlpha);
    l.cavitationPressure = number(s, "cavitation_pressure", {"gauge pressure", "Pa"}, Sign::Any, l.cavitationPressure);
    if (l.viscosity > 10.0)
        s.fail("viscosity", fmt::format("{:g} Pa s is not an engine oil (0.002-0.1 Pa s): check the units (Pa s, "
                                        "not cP or mm^2/s)",
                                        l.viscosity));
    if (l.viscosity < 1e-4)
        s.fail("viscosity", fmt::format("{:g} Pa s is thinner than water (0.001 Pa s), not an engine oil (0.002-0.1 "
                                        "Pa s): check the units (Pa s)",
                                        l.viscosity));
    if (l.density < 500.0 || l.density > 2000.0)
        s.fail("density", fmt::format("{:g} kg/m^3 is not an oil's density (800-900 kg/m^3): check the units (kg/m^3)",
                                      l.density));
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
    return s;
}

}  // namespace flexehd::cosim::casefile
