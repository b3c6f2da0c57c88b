#include "cosim/engine/CylinderPressure.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace flexehd::cosim {
namespace {

constexpr double kCycleDeg = 720.0;
constexpr double kAngleTolDeg = 1e-9;

[[noreturn]] void bad(std::size_t i, const std::string& what) {
    throw PressureTableError(i, what);
}

}  // namespace

PressureTableError::PressureTableError(std::size_t sample, const std::string& reason)
    : std::invalid_argument(sample == npos ? reason : fmt::format("pressure sample {} (0-based): {}", sample, reason)),
      sample_(sample),
      reason_(reason) {}

CylinderPressure::CylinderPressure(std::vector<PressureSample> samples) : samples_(std::move(samples)) {
    const auto& s = samples_;
    if (s.size() < 2)
        throw PressureTableError(
            PressureTableError::npos,
            fmt::format("a pressure table needs at least 2 samples covering 0-720 deg, got {}", s.size()));
    double widest = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!std::isfinite(s[i].crankDeg)) bad(i, "the crank angle is not a finite number");
        if (!std::isfinite(s[i].pressure) || !(s[i].pressure > 0.0))
            bad(i, fmt::format("expected a positive absolute pressure in Pa, got {:g} at {:g} deg", s[i].pressure,
                               s[i].crankDeg));
        if (i == 0) {
            if (std::abs(s[0].crankDeg) > kAngleTolDeg)
                bad(0, fmt::format("the table must start at 0 deg, it starts at {:g} deg", s[0].crankDeg));
            continue;
        }
        if (!(s[i].crankDeg > s[i - 1].crankDeg))
            bad(i, fmt::format("crank angles must be strictly ascending: {:g} deg follows {:g} deg", s[i].crankDeg,
                               s[i - 1].crankDeg));
        if (s[i].crankDeg > kCycleDeg + kAngleTolDeg)
            bad(i, fmt::format("crank angle {:g} deg is beyond the 720 deg cycle", s[i].crankDeg));
        widest = std::max(widest, s[i].crankDeg - s[i - 1].crankDeg);
    }
    const PressureSample& last = s.back();
    if (last.crankDeg >= kCycleDeg - kAngleTolDeg) {
        if (std::abs(last.pressure - s[0].pressure) > 1e-6 * s[0].pressure)
            bad(s.size() - 1,
                fmt::format(
                    "the 720 deg sample ({:g} Pa) must repeat the 0 deg sample ({:g} Pa): the cycle is periodic",
                    last.pressure, s[0].pressure));
    } else if (kCycleDeg - last.crankDeg > widest + kAngleTolDeg) {
        bad(s.size() - 1, fmt::format("the table does not cover 0-720 deg: it ends at {:g} deg, {:g} deg before the "
                                      "end of the cycle, more than its widest spacing ({:g} deg)",
                                      last.crankDeg, kCycleDeg - last.crankDeg, widest));
    }
    const auto top = std::max_element(
        s.begin(), s.end(), [](const PressureSample& a, const PressureSample& b) { return a.pressure < b.pressure; });
    peak_ = top->pressure;
    peakAngleDeg_ = top->crankDeg;
}

double CylinderPressure::operator()(double crankDeg) const {
    double phi = std::fmod(crankDeg, kCycleDeg);
    if (phi < 0.0) phi += kCycleDeg;
    if (phi >= kCycleDeg) phi = 0.0;  // fmod of a tiny negative number can round up to 720
    const auto& s = samples_;
    // First sample with an angle > phi; phi >= s[0].crankDeg = 0.
    const auto hi =
        std::upper_bound(s.begin(), s.end(), phi, [](double a, const PressureSample& p) { return a < p.crankDeg; });
    if (hi == s.begin()) return s.front().pressure;  // first angle within round-off above 0
    if (hi == s.end()) {                             // beyond the last sample (< 720): towards the 0 deg sample at 720
        const PressureSample& a = s.back();
        const double t = (phi - a.crankDeg) / (kCycleDeg - a.crankDeg);
        return a.pressure + t * (s.front().pressure - a.pressure);
    }
    const PressureSample& b = *hi;
    const PressureSample& a = *(hi - 1);
    const double t = (phi - a.crankDeg) / (b.crankDeg - a.crankDeg);
    return a.pressure + t * (b.pressure - a.pressure);
}

}  // namespace flexehd::cosim
