// engine: the crank train and its speed (docs/case-file.md, "engine").
#include "cosim/casefile/CaseSections.hpp"

#include <cmath>

#include <fmt/format.h>

namespace flexehd::cosim::casefile {

YamlSection readEngine(const YamlSection& top, EngineSpec& e) {
    if (!top.has("engine")) top.missing("engine", "the engine section (bore, stroke, rod_length, speed_rpm, ...)");
    const YamlSection s(
        top.source(), top.get("engine"), "engine",
        {"bore", "stroke", "rod_length", "pin_offset", "speed_rpm", "crankcase_pressure", "pin_tdc_depth"});
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
    if (e.bore < 0.01) s.fail("bore", fmt::format("a bore of {:g} m is below 10 mm: check the units (m)", e.bore));
    // Piston engines turn from about 60 rev/min (large two-stroke diesels) to about 20 000 (racing).
    if (e.speedRpm < 10.0 || e.speedRpm > 30000.0)
        s.fail("speed_rpm", fmt::format("{:g} rev/min is outside the range of piston engines, 10 to 30 000 rev/min",
                                        e.speedRpm));
    if (e.crankcasePressure < 1e4 || e.crankcasePressure > 1e6)
        s.fail("crankcase_pressure",
               fmt::format("{:g} Pa is outside 10 kPa to 1 MPa (absolute; the atmosphere is 101 325 Pa): check the "
                           "units (Pa, absolute)",
                           e.crankcasePressure));
    if (e.stroke > 4.0) s.fail("stroke", fmt::format("a stroke of {:g} m is above 4 m: check the units (m)", e.stroke));
    if (std::abs(e.pinOffset) >= e.bore / 2)
        s.fail("pin_offset", fmt::format("|pin_offset| = {:g} m must be smaller than the bore radius {:g} m",
                                         std::abs(e.pinOffset), e.bore / 2));
    if (!(e.rodLength > e.stroke / 2 + std::abs(e.pinOffset)))
        s.fail("rod_length",
               fmt::format("the crank cannot turn: rod_length ({:g} m) must exceed stroke/2 + |pin_offset| = {:g} m",
                           e.rodLength, e.stroke / 2 + std::abs(e.pinOffset)));
    return s;
}

}  // namespace flexehd::cosim::casefile
