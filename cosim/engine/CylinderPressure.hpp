#pragma once
// CylinderPressure: the cylinder pressure over the four-stroke cycle as a periodic, piecewise
// linear function of the crank angle (0–720°, 0° = gas-exchange TDC, 360° = firing TDC), built
// from a table of samples (EngineCase::cylinderPressure, read from the case's CSV file).
//
// Table rules (checked by the constructor):
//  - at least two samples; angles and pressures finite; pressures (absolute, Pa) > 0;
//  - angles strictly ascending, the first at 0°, none above 720°;
//  - the table covers the cycle: either the last sample is at 720° and repeats the pressure of
//    the 0° sample (relative difference ≤ 1e-6), or the last sample is below 720° and the gap
//    to 720° is no wider than the widest spacing inside the table — the function then runs
//    linearly from the last sample to the 0° sample's pressure at 720°.
// Violations throw PressureTableError (a std::invalid_argument).
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosim/case/EngineCase.hpp"

namespace flexehd::cosim {

/// A table that breaks the rules above: `sample()` is the 0-based index of the offending
/// sample (npos when the table as a whole is at fault), `reason()` the message without it.
class PressureTableError : public std::invalid_argument {
public:
    static constexpr std::size_t npos = static_cast<std::size_t>(-1);
    PressureTableError(std::size_t sample, const std::string& reason);
    std::size_t sample() const { return sample_; }
    const std::string& reason() const { return reason_; }

private:
    std::size_t sample_;
    std::string reason_;
};

class CylinderPressure {
public:
    explicit CylinderPressure(std::vector<PressureSample> samples);

    /// Absolute pressure (Pa) at any crank angle (°): periodic with period 720°, linear
    /// between samples.
    double operator()(double crankDeg) const;
    /// Largest pressure of the table (Pa) and the crank angle (°) of its first occurrence.
    double peak() const { return peak_; }
    double peakAngleDeg() const { return peakAngleDeg_; }

    /// The table as given (validated).
    const std::vector<PressureSample>& samples() const { return samples_; }

private:
    std::vector<PressureSample> samples_;
    double peak_ = 0.0;
    double peakAngleDeg_ = 0.0;
};

}  // namespace flexehd::cosim
