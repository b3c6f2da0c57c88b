#include "cosim/casefile/CrossSectionChecks.hpp"

#include <cmath>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

namespace flexehd::cosim::casefile {

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

// The mass-conserving film with a flexible body: the coupled Newton method (docs/coupling.md §6).
void requireSupportedMassConserving(const YamlSection& coupling, const EngineCase& c) {
    if (c.lubricant.cavitation != CavitationModel::MassConserving || !c.hasFlexibleBody()) return;
    if (c.coupling.method == CouplingMethod::Partitioned)
        coupling.fail("method", "partitioned does not converge with lubricant.cavitation: mass_conserving and a flexible "
                                "body: the film's content term carries the elastic thickness change, a coupling gain "
                                "that grows as 1/dt (docs/coupling.md section 6). Use coupling.method: newton (the "
                                "default)");
}

// The oil-control ring's band above the skirt and below the deck at TDC (docs/case-file.md,
// "lubricant.supply").
void requireOilControlRingOnPiston(const YamlSection& lubricant, const EngineCase& c) {
    const std::optional<OilControlRingSpec>& r = c.lubricant.supply.oilControlRing;
    if (!r) return;
    const YAML::Node ring = lubricant.get("supply")["oil_control_ring"];
    auto fail = [&](const char* key, const std::string& msg) {
        lubricant.source().fail(lubricant.keyPath(std::string("supply.oil_control_ring.") + key), ring[key], msg);
    };
    if (r->bottom < c.piston.skirtTop)
        fail("bottom", fmt::format("the oil-control ring sits above the skirt: its lower edge must be at or above "
                                        "piston.skirt_top = {:g} m, got {:g} m",
                                        c.piston.skirtTop, r->bottom));
    if (!(r->top < c.engine.pinTdcDepth))
        fail("top", fmt::format("at TDC the ring's upper edge would stand above the deck: it must lie below "
                                     "engine.pin_tdc_depth = {:g} m above the pin, got {:g} m",
                                     c.engine.pinTdcDepth, r->top));
}

// The depth the skirt's lower edge reaches at BDC: the pin's travel of the offset crank-slider
// (docs/dynamics.md §1), sqrt((l + r)² − e²) − sqrt((l − r)² − e²), below its TDC depth.
void requireReplenishWithinReach(const YamlSection& lubricant, const EngineCase& c) {
    const OilSupplySpec& sp = c.lubricant.supply;
    if (!sp.replenish || std::isnan(sp.replenishBelowDepth)) return;
    const double r = c.engine.stroke / 2, l = c.engine.rodLength, e = c.engine.pinOffset;
    const double travel = std::sqrt((l + r) * (l + r) - e * e) - std::sqrt((l - r) * (l - r) - e * e);
    const double deepest = c.engine.pinTdcDepth + travel - c.piston.skirtBottom;
    if (sp.replenishBelowDepth > deepest)
        lubricant.source().fail(
            lubricant.keyPath("supply.replenish_below_depth"), lubricant.get("supply")["replenish_below_depth"],
            fmt::format("{:g} m is deeper than the skirt's lower edge ever reaches ({:.4g} m below the deck, at BDC): "
                        "the layer would never be replenished; give a depth up to {:.4g} m, or replenish: false",
                        sp.replenishBelowDepth, deepest, deepest));
}

void requireRingPackForItsLoads(const YamlSection& top, const EngineCase& c) {
    if (!c.pistonBody.loads.ringPack || (c.ringGas.model == RingGasModel::Lands && c.ringGas.ringLift)) return;
    top.source().fail("bodies.piston.loads", top.get("bodies")["piston"]["loads"],
                      "ring_pack needs the gas of the lands and grooves and the rings' positions in their grooves: a "
                      "ring pack (rings) with ring_gas: {model: lands, ring_lift: true} (docs/coupling.md section 2)");
}

}  // namespace flexehd::cosim::casefile
