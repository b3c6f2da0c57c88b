// acoustics: the liner's surface velocity recorded for slap noise (docs/case-file.md,
// "acoustics"; docs/acoustics.md).
#include "cosim/casefile/CaseSections.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace flexehd::cosim::casefile {

void readAcoustics(const YamlSection& top, EngineCase& c) {
    if (!top.has("acoustics")) return;
    const YamlSection s(top.source(), top.get("acoustics"), "acoustics", {"surface", "up_to_hz"});
    AcousticsSpec& a = c.acoustics;
    a.enabled = true;
    a.surface = text(s, "surface", a.surface, "a surface group of the liner's mesh");
    a.upToHz = number(s, "up_to_hz", {"frequency", "Hz"}, Sign::Positive, a.upToHz);
    if (c.linerBody.model != BodyModel::Flexible)
        top.fail("acoustics", "needs a flexible liner (bodies.liner with a reduced-body file): the record is the "
                              "liner's surface velocity");
    // The record's force on the liner is linear between the accepted steps: none longer than the
    // sampling interval, so that the force follows the recorded range (docs/acoustics.md §8).
    const double sampleDeg = 6.0 * c.engine.speedRpm / a.sampleRateHz();
    if (sampleDeg < c.time.minStepDeg)
        s.fail("up_to_hz", fmt::format("{:g} Hz needs steps of at most {:.3g} deg at {:g} rpm (2.56 samples per "
                                       "hertz), below time.min_step_deg = {:g} deg",
                                       a.upToHz, sampleDeg, c.engine.speedRpm, c.time.minStepDeg));
    c.time.maxStepDeg = std::min(c.time.maxStepDeg, sampleDeg);
}

}  // namespace flexehd::cosim::casefile
