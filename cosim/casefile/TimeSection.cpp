// time: the crank-angle steps, their error control and the cycles (docs/case-file.md, "time").
#include "cosim/casefile/CaseSections.hpp"

#include <fmt/format.h>

namespace flexehd::cosim::casefile {
namespace {

constexpr double kFinestMotionTolerance = 1e-12;  // m of lateral shift, rad of tilt

}  // namespace

void readTime(const YamlSection& top, TimeSpec& t) {
    const YamlSection time(top.source(), top.get("time"), "time",
                           {"start_deg", "max_step_deg", "min_step_deg", "lateral_tolerance", "tilt_tolerance_deg",
                            "max_cycles", "periodicity_tolerance", "oil_periodicity_tolerance"});
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
    // The film forces are solved to a relative residual of 1e-8 (SolverControl), so the motion is
    // no more accurate than about 1e-8 of the clearance: a tighter step tolerance is never met.
    if (t.lateralTolerance < kFinestMotionTolerance)
        time.fail("lateral_tolerance",
                  fmt::format("{:g} m is below what the film solution resolves (about {:g} m, the film forces being "
                              "solved to 1e-8 relative): no step meets it; give {:g} m or more (default 0.2e-6)",
                              t.lateralTolerance, kFinestMotionTolerance, kFinestMotionTolerance));
    if (t.tiltTolerance < kFinestMotionTolerance)
        time.fail("tilt_tolerance_deg",
                  fmt::format("{:g} deg is below what the film solution resolves (about {:g} deg): no step meets "
                              "it; give {:g} deg or more (default 2.865e-4)",
                              t.tiltTolerance / kDeg, kFinestMotionTolerance / kDeg, kFinestMotionTolerance / kDeg));
    t.maxCycles = integer(time, "max_cycles", 1, 1000, t.maxCycles, "cycles");
    t.periodicityTolerance =
        number(time, "periodicity_tolerance", {"length", "m"}, Sign::Positive, t.periodicityTolerance);
    t.oilPeriodicityTolerance = number(time, "oil_periodicity_tolerance", {"relative change of the oil volume", ""},
                                       Sign::Positive, t.oilPeriodicityTolerance);
}

}  // namespace flexehd::cosim::casefile
