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
