#pragma once
// RadiatedPower: the equivalent radiated power (ERP) of a vibrating surface from the spectrum of
// its normal velocity at points standing for areas A_p (docs/acoustics.md §3):
//
//   ERP(f_k) = ρ c Σ_p m_{k,p} A_p   (W),
//
// m_{k,p} the power-corrected mean square of bin k at point p (VelocitySpectrum). For a tone of
// complex amplitude v̂ on a bin under the rectangular window m = |v̂|²/2, so this is the textbook
// ½ ρ c Σ |v̂_p|² A_p; under any window its sums over bins (totals, bands, orders) are the power
// of what the bins hold. The velocities must be the surface-normal components (m/s).
#include <Eigen/Core>

#include "acoustics/AirProperties.hpp"
#include "acoustics/OneThirdOctaveBands.hpp"
#include "acoustics/VelocitySpectrum.hpp"

namespace flexehd::acoustics {

class RadiatedPower {
public:
    /// pointArea_m2: the area each point stands for (finite, ≥ 0, at least one > 0).
    explicit RadiatedPower(Eigen::VectorXd pointArea_m2, AirProperties air = {});

    const Eigen::VectorXd& pointArea_m2() const { return area_m2_; }
    const AirProperties& air() const { return air_; }

    /// ERP of every bin (W); the spectrum must have one column per area.
    Eigen::VectorXd perBin_W(const VelocitySpectrum& spectrum) const;
    /// Σ_k ERP(f_k), the 0 Hz bin included (W).
    double total_W(const VelocitySpectrum& spectrum) const;
    /// ERP summed into 1/3-octave bands, bins by their centre frequency (W; 0 Hz in no band).
    BandSpectrum inOneThirdOctaveBands_W(const VelocitySpectrum& spectrum) const;

private:
    Eigen::VectorXd area_m2_;
    AirProperties air_;
};

}  // namespace flexehd::acoustics
