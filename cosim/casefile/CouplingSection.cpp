// coupling: the film–structure iteration of each step (docs/case-file.md, "coupling").
#include "cosim/casefile/CaseSections.hpp"

#include <fmt/format.h>

namespace flexehd::cosim::casefile {

YamlSection readCoupling(const YamlSection& top, CouplingSpec& k) {
    const YamlSection coupling(top.source(), top.get("coupling"), "coupling",
                               {"tolerance", "max_iterations", "method", "acceleration", "elastic_squeeze",
                                "keep_jacobian"});
    k.tolerance =
        number(coupling, "tolerance", {"relative tolerance", ""}, Sign::Positive, k.tolerance);
    if (!(k.tolerance < 1.0))
        coupling.fail("tolerance",
                      fmt::format("expected a relative tolerance below 1, got {:g}", k.tolerance));
    if (k.tolerance < 1e-8)
        coupling.fail("tolerance", fmt::format("{:g} is below the film solver's own tolerance (1e-8 relative), which "
                                               "bounds what the coupling can reach: give 1e-8 or more (default 1e-3)",
                                               k.tolerance));
    k.maxIterations = integer(coupling, "max_iterations", 1, 10000, k.maxIterations, "iterations");
    k.keepJacobian = boolean(coupling, "keep_jacobian", k.keepJacobian);
    k.acceleration = choice(coupling, "acceleration", {"iqn-ils", "aitken"}, 0) == 0
                                  ? CouplingAcceleration::IqnIls
                                  : CouplingAcceleration::Aitken;
    k.method = choice(coupling, "method", {"newton", "partitioned"}, 0) == 0 ? CouplingMethod::Newton
                                                                                      : CouplingMethod::Partitioned;
    // Default: the whole film thickness's rate with the Newton method (the partitioned iteration
    // cannot carry it; docs/coupling.md section 3).
    k.elasticSqueeze =
        boolean(coupling, "elastic_squeeze", k.method == CouplingMethod::Newton);
    if (k.elasticSqueeze && k.method == CouplingMethod::Partitioned)
        coupling.fail("elastic_squeeze",
                      "the elastic deformation rate in the squeeze term needs coupling.method: newton (the partitioned "
                      "iteration's gain grows as 1/time step and does not converge with it; docs/coupling.md section 3)");
    return coupling;
}

}  // namespace flexehd::cosim::casefile
