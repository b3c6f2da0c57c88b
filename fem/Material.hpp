#pragma once
// Isotropic linear elastic and thermal material data (SI units).
#include <stdexcept>
#include <string>

namespace flexehd::fem {

struct ElasticMaterial {
    double E = 0.0;    ///< Young's modulus, Pa
    double nu = 0.0;   ///< Poisson's ratio, -
    double rho = 0.0;  ///< density, kg/m^3

    double lambda() const { return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)); }
    double mu() const { return E / (2.0 * (1.0 + nu)); }
    /// Bulk term 3*lambda + 2*mu = E / (1 - 2 nu): stress per unit volumetric thermal strain.
    double thermalStressFactor() const { return E / (1.0 - 2.0 * nu); }

    /// Throws std::invalid_argument naming the offending parameter.
    void validate() const {
        if (!(E > 0.0)) throw std::invalid_argument("Young's modulus E must be > 0 Pa, got " + std::to_string(E));
        if (!(nu > -1.0 && nu < 0.5))
            throw std::invalid_argument("Poisson's ratio nu must lie in (-1, 0.5), got " + std::to_string(nu));
        if (!(rho > 0.0)) throw std::invalid_argument("density rho must be > 0 kg/m^3, got " + std::to_string(rho));
    }
};

struct ThermalMaterial {
    double conductivity = 0.0;  ///< k, W/(m K)
    double expansion = 0.0;     ///< alpha, 1/K

    void validate() const {
        if (!(conductivity > 0.0))
            throw std::invalid_argument("thermal conductivity must be > 0 W/(m K), got " +
                                        std::to_string(conductivity));
        if (!(expansion >= 0.0))
            throw std::invalid_argument("thermal expansion coefficient must be >= 0 1/K, got " +
                                        std::to_string(expansion));
    }
};

}  // namespace flexehd::fem
