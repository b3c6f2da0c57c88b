// piston: mass, inertia, the skirt and its profile (docs/case-file.md, "piston").
#include "cosim/casefile/CaseSections.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "cosim/io/YamlKeys.hpp"

namespace flexehd::cosim::casefile {
namespace {

constexpr double kMinClearance = 1e-6;  // m: below the skirt's and liner's combined roughness

}  // namespace

void readPiston(const YamlSection& top, const EngineSpec& engine, PistonSpec& p) {
    if (!top.has("piston")) top.missing("piston", "the piston section (mass, pin_mass, inertia, skirt_top, ...)");
    const YamlSection s(top.source(), top.get("piston"), "piston",
                        {"mass", "pin_mass", "inertia", "cg_x", "cg_z", "skirt_top", "skirt_bottom", "clearance",
                         "skirt_half_angle_deg", "profile", "ovality"});
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
    if (p.clearance < kMinClearance)
        s.fail("clearance", fmt::format("a radial clearance of {:g} m is below 1 um, less than the surfaces' "
                                        "roughness: the skirt would run on its asperities everywhere; check the "
                                        "units (m; 50 um = 5e-05)",
                                        p.clearance));
    // A solid steel cylinder of the bore's diameter and twice its height: heavier than any piston.
    const double heaviest = 7850.0 * M_PI / 4 * std::pow(engine.bore, 2) * 2 * engine.bore;
    if (p.mass > heaviest)
        s.fail("mass", fmt::format("{:g} kg is heavier than a solid steel cylinder of the bore, twice the bore high "
                                   "({:.3g} kg): check the units (kg)",
                                   p.mass, heaviest));
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
        if (!list.IsSequence()) s.fail("profile", "expected " + expected + ", got " + describeNode(list));
        const std::string path = s.keyPath("profile");
        for (std::size_t i = 0; i < list.size(); ++i) {
            const YAML::Node row = list[i];
            const std::string rowPath = fmt::format("{}[{}]", path, i);
            double z = 0.0, drop = 0.0;
            if (!row.IsSequence() || row.size() != 2 || !row[0].IsScalar() || !row[1].IsScalar() ||
                !parseNumber(row[0].Scalar(), z) || !parseNumber(row[1].Scalar(), drop))
                s.source().fail(rowPath, row,
                     "expected a pair [z, drop] of numbers in m, got " + describeNode(row) +
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

}  // namespace flexehd::cosim::casefile
