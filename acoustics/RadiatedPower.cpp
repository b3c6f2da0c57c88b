// RadiatedPower: equivalent radiated power per bin, in total and in 1/3-octave bands (header).
#include "acoustics/RadiatedPower.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "acoustics/InputChecks.hpp"

namespace flexehd::acoustics {

RadiatedPower::RadiatedPower(Eigen::VectorXd pointArea_m2, AirProperties air)
    : area_m2_(std::move(pointArea_m2)), air_(air) {
    requirePositiveFinite("air.density_kg_m3", air_.density_kg_m3, "density in kg/m³");
    requirePositiveFinite("air.speedOfSound_m_s", air_.speedOfSound_m_s, "speed of sound in m/s");
    requireAtLeast("pointArea_m2 size", area_m2_.size(), 1, "one area per point");
    for (Eigen::Index p = 0; p < area_m2_.size(); ++p)
        if (!(std::isfinite(area_m2_(p)) && area_m2_(p) >= 0.0))
            throw std::invalid_argument("pointArea_m2: expected finite areas ≥ 0 m², got " +
                                        std::to_string(area_m2_(p)) + " at point " + std::to_string(p));
    if (!(area_m2_.sum() > 0.0)) throw std::invalid_argument("pointArea_m2: expected a total area > 0 m², got 0");
}

Eigen::VectorXd RadiatedPower::perBin_W(const VelocitySpectrum& spectrum) const {
    if (spectrum.pointCount() != area_m2_.size())
        throw std::invalid_argument("pointArea_m2: expected one area per point of the spectrum (" +
                                    std::to_string(spectrum.pointCount()) + " points), got " +
                                    std::to_string(area_m2_.size()) + " areas");
    return air_.characteristicImpedance_pa_s_m() * (spectrum.meanSquare() * area_m2_);
}

double RadiatedPower::total_W(const VelocitySpectrum& spectrum) const { return perBin_W(spectrum).sum(); }

BandSpectrum RadiatedPower::inOneThirdOctaveBands_W(const VelocitySpectrum& spectrum) const {
    return sumIntoOneThirdOctaveBands(spectrum.frequency_hz(), perBin_W(spectrum));
}

}  // namespace flexehd::acoustics
