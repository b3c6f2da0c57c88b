#include "modal/PressurePattern.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <fmt/format.h>

namespace flexehd::modal {

namespace {

// A bound: empty (open) or a finite number written whole.
bool bound(const std::string& text, double open, double& value) {
    if (text.empty()) {
        value = open;
        return true;
    }
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(value);
}

}  // namespace

PressurePattern PressurePattern::parse(const std::string& text) {
    PressurePattern p;
    const auto at = text.find('@');
    p.group = text.substr(0, at);
    const auto fail = [&] {
        throw std::invalid_argument(fmt::format("pressure pattern '{}': expected GROUP or GROUP@ZLOW:ZHIGH (z in m, "
                                                "either bound may be left out, ZLOW < ZHIGH)",
                                                text));
    };
    if (p.group.empty()) fail();
    if (at == std::string::npos) return p;
    const std::string band = text.substr(at + 1);
    const auto colon = band.find(':');
    if (colon == std::string::npos || band.find(':', colon + 1) != std::string::npos) fail();
    if (!bound(band.substr(0, colon), p.zLow, p.zLow) || !bound(band.substr(colon + 1), p.zHigh, p.zHigh)) fail();
    if (!(p.zLow < p.zHigh) || !p.banded()) fail();
    return p;
}

std::string PressurePattern::text() const {
    if (!banded()) return group;
    const auto side = [](double z) { return std::isfinite(z) ? fmt::format("{:.9g}", z) : std::string(); };
    return group + "@" + side(zLow) + ":" + side(zHigh);
}

bool PressurePattern::matches(const PressurePattern& other, double tolerance) const {
    const auto same = [&](double a, double b) {
        return std::isfinite(a) || std::isfinite(b) ? std::abs(a - b) <= tolerance : a == b;
    };
    return group == other.group && same(zLow, other.zLow) && same(zHigh, other.zHigh);
}

}  // namespace flexehd::modal
