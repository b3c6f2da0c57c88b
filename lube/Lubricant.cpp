#include "lube/Lubricant.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::lube {

Lubricant::Lubricant(double viscosity, double density) : eta0_(viscosity), rho0_(density) {
    if (!(viscosity > 0.0) || !std::isfinite(viscosity))
        throw std::invalid_argument("Lubricant: viscosity must be positive (Pa·s), got " +
                                    std::to_string(viscosity));
    if (!(density > 0.0) || !std::isfinite(density))
        throw std::invalid_argument("Lubricant: density must be positive (kg/m³), got " +
                                    std::to_string(density));
}

Lubricant& Lubricant::withBarus(double alpha) {
    if (!(alpha >= 0.0) || !std::isfinite(alpha))
        throw std::invalid_argument("Lubricant::withBarus: alpha must be >= 0 (1/Pa), got " +
                                    std::to_string(alpha));
    alpha_ = alpha;
    viscosityModel_ = ViscosityModel::Barus;
    return *this;
}

Lubricant& Lubricant::withRoelands(double alpha) {
    if (!(alpha >= 0.0) || !std::isfinite(alpha))
        throw std::invalid_argument("Lubricant::withRoelands: alpha must be >= 0 (1/Pa), got " +
                                    std::to_string(alpha));
    const double lnTerm = std::log(eta0_) + 9.67;
    if (!(lnTerm > 0.0))
        throw std::invalid_argument("Lubricant::withRoelands: needs ln(eta0) + 9.67 > 0, i.e. "
                                    "eta0 > 6.3e-5 Pa·s");
    alpha_ = alpha;
    roelandsZ_ = alpha * kRoelandsPressure / lnTerm;
    viscosityModel_ = ViscosityModel::Roelands;
    return *this;
}

Lubricant& Lubricant::withDowsonHigginson() {
    densityModel_ = DensityModel::DowsonHigginson;
    return *this;
}

double Lubricant::viscosity(double p) const {
    const double pp = p > 0.0 ? p : 0.0;
    switch (viscosityModel_) {
    case ViscosityModel::Constant: return eta0_;
    case ViscosityModel::Barus: return eta0_ * std::exp(alpha_ * pp);
    case ViscosityModel::Roelands:
        return eta0_ * std::exp((std::log(eta0_) + 9.67) *
                                (std::pow(1.0 + pp / kRoelandsPressure, roelandsZ_) - 1.0));
    }
    return eta0_;
}

double Lubricant::density(double p) const {
    const double pp = p > 0.0 ? p : 0.0;
    if (densityModel_ == DensityModel::DowsonHigginson)
        return rho0_ * (1.0 + 0.6e-9 * pp / (1.0 + 1.7e-9 * pp));
    return rho0_;
}

}  // namespace flexehd::lube
