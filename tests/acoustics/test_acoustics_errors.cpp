// Bad input to acoustics/ throws std::invalid_argument naming the argument and what was
// expected: non-positive sample rates, fewer than 2 samples, areas not matching the points,
// NaN samples, records of the wrong length, negative powers.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "acoustics/RadiatedPower.hpp"
#include "acoustics/ShortTimeRadiatedPower.hpp"
#include "acoustics/SoundPowerLevel.hpp"
#include "acoustics/SpectrumAnalyzer.hpp"

using namespace flexehd::acoustics;
using testing::HasSubstr;
using testing::ThrowsMessage;

namespace {
template <typename F>
void expectInvalid(F f, const std::string& text) {
    EXPECT_THAT(f, ThrowsMessage<std::invalid_argument>(HasSubstr(text)));
}
}  // namespace

TEST(AcousticsErrors, NonPositiveSampleRate) {
    expectInvalid([] { SpectrumAnalyzer(16, 0.0); }, "sampleRate_hz: expected a positive finite rate in Hz, got 0");
    expectInvalid([] { SpectrumAnalyzer(16, -100.0); }, "sampleRate_hz: expected a positive finite rate in Hz, got -100");
    expectInvalid([] { ShortTimeRadiatedPower(RadiatedPower(Eigen::VectorXd::Ones(1)), -1.0, 16, 8); },
                  "sampleRate_hz");
}

TEST(AcousticsErrors, FewerThanTwoSamples) {
    expectInvalid([] { SpectrumAnalyzer(1, 1000.0); }, "sampleCount: expected samples per record (at least 2), got 1");
    expectInvalid([] { ShortTimeRadiatedPower(RadiatedPower(Eigen::VectorXd::Ones(1)), 1000.0, 1, 1); },
                  "frameLength_samples");
    ShortTimeRadiatedPower stft(RadiatedPower(Eigen::VectorXd::Ones(1)), 1000.0, 4, 2);
    expectInvalid([&] { stft.map(Eigen::MatrixXd::Zero(1, 1), 1000.0, 0.0); },
                  "samples rows: expected samples per point, one row per sample (at least 2), got 1");
    expectInvalid([&] { stft.map(Eigen::MatrixXd::Zero(3, 1), 1000.0, 0.0); },
                  "samples: expected at least one frame (4 rows), got 3");
}

TEST(AcousticsErrors, AreasNotMatchingPoints) {
    SpectrumAnalyzer analyzer(16, 1000.0);
    const VelocitySpectrum s = analyzer.analyze(Eigen::MatrixXd::Ones(16, 4));
    const RadiatedPower erp(Eigen::VectorXd::Constant(3, 0.1));
    expectInvalid([&] { erp.perBin_W(s); },
                  "pointArea_m2: expected one area per point of the spectrum (4 points), got 3 areas");
    ShortTimeRadiatedPower stft(erp, 1000.0, 8, 4);
    expectInvalid([&] { stft.map(Eigen::MatrixXd::Zero(16, 4), 1000.0, 0.0); }, "pointArea_m2: expected one area per point");
    expectInvalid([] { RadiatedPower(Eigen::Vector2d(0.1, -0.1)); }, "pointArea_m2: expected finite areas ≥ 0 m²");
    expectInvalid([] { RadiatedPower(Eigen::VectorXd(0)); }, "pointArea_m2 size");
}

TEST(AcousticsErrors, NaNSamples) {
    SpectrumAnalyzer analyzer(16, 1000.0);
    Eigen::MatrixXd x = Eigen::MatrixXd::Zero(16, 2);
    x(3, 1) = std::numeric_limits<double>::quiet_NaN();
    expectInvalid([&] { analyzer.analyze(x); }, "samples: expected finite values, got nan at sample 3 of point 1");
}

TEST(AcousticsErrors, WrongRecordLengthAndOtherArguments) {
    SpectrumAnalyzer analyzer(16, 1000.0);
    expectInvalid([&] { analyzer.analyze(Eigen::MatrixXd::Zero(15, 1)); },
                  "samples: expected 16 rows (the analyser's record length), got 15");
    expectInvalid([] { soundPowerLevel_dB(-1.0); }, "power_W: expected a finite power ≥ 0 W");
    expectInvalid([] { RadiatedPower(Eigen::VectorXd::Ones(1), AirProperties{0.0, 343.0}); }, "air.density_kg_m3");
    expectInvalid([] { OneThirdOctaveBand::containing(0.0); }, "frequency_hz");
}
