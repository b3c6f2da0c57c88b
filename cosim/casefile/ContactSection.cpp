// contact: asperity contact, hard contact of the coating, boundary friction and wear
// (docs/case-file.md, "contact").
#include "cosim/casefile/CaseSections.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace flexehd::cosim::casefile {

void readContact(const YamlSection& top, ContactSpec& c) {
    const YamlSection s(
        top.source(), top.get("contact"), "contact",
        {"sigma", "beta", "asperity_density", "composite_modulus", "boundary_friction", "piston_youngs_modulus",
         "piston_poisson_ratio", "liner_youngs_modulus", "liner_poisson_ratio", "coating_thickness",
         "coating_youngs_modulus", "coating_poisson_ratio", "hard_contact_stiffness", "restitution", "piston_wear_coefficient",
         "liner_wear_coefficient"});
    c.sigma = number(s, "sigma", {"composite rms roughness", "m"}, Sign::Positive, c.sigma);
    c.beta = number(s, "beta", {"asperity tip radius", "m"}, Sign::Positive, c.beta);
    c.asperityDensity = number(s, "asperity_density", {"asperity density", "1/m^2"}, Sign::Positive, c.asperityDensity);
    c.boundaryFriction =
        number(s, "boundary_friction", {"friction coefficient", ""}, Sign::NonNegative, c.boundaryFriction);
    for (const auto& [key, k] : {std::pair{"piston_wear_coefficient", &c.pistonWearCoefficient},
                                 std::pair{"liner_wear_coefficient", &c.linerWearCoefficient}}) {
        *k = number(s, key, {"Archard wear coefficient", "m^2/N"}, Sign::NonNegative, *k);
        if (*k > 1e-10)
            s.fail(key, fmt::format("a wear coefficient of {:g} m^2/N is far above any engine material's (about 1e-18 "
                                    "to 1e-13 m^2/N): check the units (m^2/N = m^3/(N m))",
                                    *k));
    }
    if (c.boundaryFriction > 1.0)
        s.fail("boundary_friction",
               fmt::format("expected a friction coefficient between 0 and 1, got {:g}", c.boundaryFriction));
    if (c.sigma > 1e-4)
        s.fail("sigma", fmt::format("a roughness of {:g} m is above 100 um: check the units (m)", c.sigma));

    // E*: given directly, or from the two surfaces' elastic constants (Hertz: 1/E* = Σ (1−ν²)/E).
    const std::vector<std::string> materialKeys{"piston_youngs_modulus", "piston_poisson_ratio", "liner_youngs_modulus",
                                                "liner_poisson_ratio"};
    const bool anyMaterial =
        std::any_of(materialKeys.begin(), materialKeys.end(), [&](const auto& k) { return s.has(k); });
    if (s.has("composite_modulus") && anyMaterial)
        s.fail("composite_modulus",
               "give either composite_modulus or the four piston_/liner_ youngs_modulus and "
               "poisson_ratio keys, not both");
    if (anyMaterial) {
        double compliance = 0.0;
        for (const char* body : {"piston", "liner"}) {
            const std::string e = std::string(body) + "_youngs_modulus", nu = std::string(body) + "_poisson_ratio";
            const double E = number(s, e, {"Young's modulus", "Pa"}, Sign::Positive, 0.0, true);
            const double v = number(s, nu, {"Poisson's ratio", ""}, Sign::Any, 0.0, true);
            if (!(v > -1.0 && v < 0.5)) s.fail(nu, fmt::format("expected a Poisson's ratio in (-1, 0.5), got {:g}", v));
            compliance += (1.0 - v * v) / E;
        }
        c.compositeModulus = 1.0 / compliance;
    } else {
        c.compositeModulus = number(s, "composite_modulus", {"composite modulus E* (0 = contact off)", "Pa"},
                                    Sign::NonNegative, c.compositeModulus);
    }

    // Hard contact below h = 0: the coating as a bonded elastic layer, or the stiffness directly.
    const bool anyCoating = s.has("coating_thickness") || s.has("coating_youngs_modulus") || s.has("coating_poisson_ratio");
    if (s.has("hard_contact_stiffness") && anyCoating)
        s.fail("hard_contact_stiffness",
               "give either hard_contact_stiffness or the coating_ thickness / youngs_modulus / poisson_ratio keys, "
               "not both");
    c.coatingThickness = number(s, "coating_thickness", {"coating thickness", "m"}, Sign::Positive, c.coatingThickness);
    if (c.coatingThickness > 1e-3)
        s.fail("coating_thickness",
               fmt::format("a coating of {:g} m is thicker than 1 mm: check the units (m)", c.coatingThickness));
    c.coatingModulus =
        number(s, "coating_youngs_modulus", {"Young's modulus", "Pa"}, Sign::Positive, c.coatingModulus);
    c.coatingPoisson = number(s, "coating_poisson_ratio", {"Poisson's ratio", ""}, Sign::Any, c.coatingPoisson);
    if (!(c.coatingPoisson > -1.0 && c.coatingPoisson < 0.5))
        s.fail("coating_poisson_ratio",
               fmt::format("expected a Poisson's ratio in (-1, 0.5), got {:g}", c.coatingPoisson));
    c.hardContactStiffness = number(s, "hard_contact_stiffness", {"contact stiffness", "Pa/m"}, Sign::Positive,
                                    c.hardContactStiffness);
    c.restitution = number(s, "restitution", {"coefficient of restitution", ""}, Sign::Positive, c.restitution);
    if (c.restitution > 1.0)
        s.fail("restitution",
               fmt::format("expected a coefficient of restitution in (0, 1] (1: an elastic impact), got {:g}",
                           c.restitution));
}

}  // namespace flexehd::cosim::casefile
