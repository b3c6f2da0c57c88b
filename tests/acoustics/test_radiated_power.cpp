// RadiatedPower (acoustics/RadiatedPower.hpp) and SoundPowerLevel: a plate of 0.01 m² (four
// points of 25 cm²) vibrating uniformly at 1 mm/s, 1000 Hz radiates ½ ρ c v² A =
// ½ · 1.204 · 343 · (1e-3)² · 0.01 = 2.06486e-6 W = 63.149 dB re 1 pW (by hand); two points of
// different velocity and area, and other air, likewise; dB re 1 pW of round powers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "acoustics/RadiatedPower.hpp"
#include "acoustics/SoundPowerLevel.hpp"
#include "acoustics/SpectrumAnalyzer.hpp"
#include "tests/acoustics/AcousticsTestSupport.hpp"

using namespace flexehd::acoustics;
using namespace flexehd::acoustics::test;

namespace {

Eigen::MatrixXd uniformPlate(int points, double amplitude, double frequency_hz) {
    Eigen::MatrixXd x(kSamples, points);
    for (int p = 0; p < points; ++p) x.col(p) = tone(amplitude, frequency_hz);
    return x;
}

constexpr double kPlateErp_W = 2.06486e-6;  // ½ · 1.204 · 343 · 1e-6 · 0.01

}  // namespace

TEST(RadiatedPower, UniformPlateRadiatesHalfRhoCVSquaredA) {
    const RadiatedPower erp(Eigen::VectorXd::Constant(4, 0.0025));
    EXPECT_DOUBLE_EQ(erp.air().characteristicImpedance_pa_s_m(), 412.972);
    SpectrumAnalyzer rectangular(kSamples, kSampleRate_hz, WindowKind::Rectangular);
    const VelocitySpectrum r = rectangular.analyze(uniformPlate(4, 1e-3, 1000.0));
    EXPECT_NEAR(erp.perBin_W(r)(160), kPlateErp_W, kPlateErp_W * 1e-9);  // one bin holds it all
    EXPECT_NEAR(erp.total_W(r), kPlateErp_W, kPlateErp_W * 1e-9);

    SpectrumAnalyzer hann(kSamples, kSampleRate_hz);
    const VelocitySpectrum h = hann.analyze(uniformPlate(4, 1e-3, 1000.0));
    EXPECT_NEAR(erp.total_W(h), kPlateErp_W, kPlateErp_W * 1e-9);  // three bins hold it
    EXPECT_NEAR(soundPowerLevel_dB(erp.total_W(h)), 63.149, 1e-3);
}

TEST(RadiatedPower, PointsOfDifferentVelocityAndAreaAddTheirPowers) {
    // ½ · 412.972 · ((1e-3)² · 0.003 + (2e-3)² · 0.001) = ½ · 412.972 · 7e-9 = 1.445402e-6 W
    Eigen::MatrixXd x(kSamples, 2);
    x.col(0) = tone(1e-3, 2000.0, 0.1);
    x.col(1) = tone(2e-3, 2000.0, 2.0);  // phase does not matter to ERP
    SpectrumAnalyzer hann(kSamples, kSampleRate_hz);
    const RadiatedPower erp(Eigen::Vector2d(0.003, 0.001));
    EXPECT_NEAR(erp.total_W(hann.analyze(x)), 1.445402e-6, 1.445402e-6 * 1e-9);
}

TEST(RadiatedPower, AirIsSettable) {
    // ρ = 1.0, c = 340: ½ · 340 · 1e-6 · 0.01 = 1.7e-6 W
    const RadiatedPower erp(Eigen::VectorXd::Constant(4, 0.0025), AirProperties{1.0, 340.0});
    SpectrumAnalyzer hann(kSamples, kSampleRate_hz);
    EXPECT_NEAR(erp.total_W(hann.analyze(uniformPlate(4, 1e-3, 1000.0))), 1.7e-6, 1.7e-6 * 1e-9);
}

TEST(SoundPowerLevel, DecibelsReOnePicowatt) {
    EXPECT_NEAR(soundPowerLevel_dB(1.0), 120.0, 1e-12);
    EXPECT_NEAR(soundPowerLevel_dB(1e-12), 0.0, 1e-12);
    EXPECT_NEAR(soundPowerLevel_dB(1e-3), 90.0, 1e-12);
    EXPECT_NEAR(soundPowerLevel_dB(2e-12), 3.0103, 1e-4);
    EXPECT_EQ(soundPowerLevel_dB(0.0), -std::numeric_limits<double>::infinity());
}
