#pragma once
// Signals shared by the acoustics tests: sampled sines of given amplitude, frequency and phase.
#include <Eigen/Core>
#include <cmath>
#include <numbers>

namespace flexehd::acoustics::test {

// 51.2 kHz, 8192 samples: bins 6.25 Hz apart, bin 160 at 1000 Hz.
constexpr double kSampleRate_hz = 51200.0;
constexpr int kSamples = 8192;
constexpr double kBinWidth_hz = kSampleRate_hz / kSamples;  // 6.25 Hz

/// A (m/s) sin(2π f t + φ) at t = n / f_s, n = 0..count−1.
inline Eigen::VectorXd tone(double amplitude, double frequency_hz, double phase = 0.3, int count = kSamples,
                            double sampleRate_hz = kSampleRate_hz) {
    Eigen::VectorXd x(count);
    for (int n = 0; n < count; ++n)
        x(n) = amplitude * std::sin(2.0 * std::numbers::pi * frequency_hz * n / sampleRate_hz + phase);
    return x;
}

}  // namespace flexehd::acoustics::test
