#include "lube/ElasticFoundation.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::lube {

ElasticFoundation::ElasticFoundation(double stiffness) : stiffness_(stiffness) {
    if (!(stiffness > 0.0) || !std::isfinite(stiffness))
        throw std::invalid_argument("ElasticFoundation: the contact stiffness must be positive and finite (Pa/m), got " +
                                    std::to_string(stiffness));
}

double ElasticFoundation::layerStiffness(double E, double nu, double t) {
    if (!(E > 0.0) || !(nu > -1.0 && nu < 0.5) || !(t > 0.0) || !std::isfinite(E) || !std::isfinite(t))
        throw std::invalid_argument("ElasticFoundation::layerStiffness: expected E > 0 Pa, -1 < nu < 0.5 and a layer "
                                    "thickness > 0 m");
    return E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu) * t);
}

}  // namespace flexehd::lube
