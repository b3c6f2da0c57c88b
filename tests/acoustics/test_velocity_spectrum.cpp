// VelocitySpectrum through SpectrumAnalyzer (acoustics/SpectrumAnalyzer.hpp): two sines of known
// amplitude, one on a bin centre and one half a bin off, come back with their amplitudes (the
// off-bin one lowered by the window's scalloping loss: Hann 8/(3π) = 0.8488, −1.42 dB; rectangular
// 2/π = 0.6366, −3.92 dB; Harris, Proc. IEEE 66 (1978) 51); the bins' mean squares add up to the
// time-domain mean square (Parseval) for the tones and for seeded white noise of variance 0.09;
// one plan serves many points and records.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "acoustics/SpectrumAnalyzer.hpp"
#include "tests/acoustics/AcousticsTestSupport.hpp"

using namespace flexehd::acoustics;
using namespace flexehd::acoustics::test;

namespace {

// 2 mm/s at bin 160 (1000 Hz) and 0.5 mm/s at bin 480.5 (3003.125 Hz).
Eigen::MatrixXd twoTones() {
    Eigen::MatrixXd x(kSamples, 1);
    x.col(0) = tone(2e-3, 1000.0) + tone(0.5e-3, 480.5 * kBinWidth_hz, 1.1);
    return x;
}

double meanSquareOf(const Eigen::MatrixXd& x) { return x.squaredNorm() / x.size(); }

}  // namespace

TEST(VelocitySpectrum, BinsSitAtMultiplesOfTheSampleRateOverTheLength) {
    SpectrumAnalyzer analyzer(kSamples, kSampleRate_hz);
    const VelocitySpectrum s = analyzer.analyze(twoTones());
    ASSERT_EQ(s.binCount(), kSamples / 2 + 1);
    EXPECT_DOUBLE_EQ(s.binWidth_hz(), 6.25);
    EXPECT_DOUBLE_EQ(s.frequency_hz()(160), 1000.0);
    EXPECT_DOUBLE_EQ(s.frequency_hz()(kSamples / 2), 25600.0);  // Nyquist
}

TEST(VelocitySpectrum, HannRecoversAnOnBinToneAndScallopsAnOffBinOneBy1Point42Db) {
    SpectrumAnalyzer analyzer(kSamples, kSampleRate_hz);  // Hann by default
    const VelocitySpectrum s = analyzer.analyze(twoTones());
    // The off-bin tone's Hann sidelobes (falling as δ⁻³) reach bin 160 at ~1e-9.
    EXPECT_NEAR(s.amplitude(160, 0), 2e-3, 2e-3 * 1e-8);
    // Half a bin off: both neighbours read A · 8/(3π).
    const double scalloped = 0.5e-3 * 8.0 / (3.0 * std::numbers::pi);
    EXPECT_NEAR(s.amplitude(480, 0), scalloped, scalloped * 1e-4);
    EXPECT_NEAR(s.amplitude(481, 0), scalloped, scalloped * 1e-4);
    EXPECT_NEAR(20.0 * std::log10(s.amplitude(480, 0) / 0.5e-3), -1.42, 0.005);
    // Far from both tones the Hann sidelobes (−18 dB/octave) leave nothing of note.
    EXPECT_LT(s.amplitude(1500, 0), 1e-12);
}

TEST(VelocitySpectrum, RectangularRecoversAnOnBinToneAndScallopsAnOffBinOneBy3Point92Db) {
    SpectrumAnalyzer analyzer(kSamples, kSampleRate_hz, WindowKind::Rectangular);
    const VelocitySpectrum s = analyzer.analyze(twoTones());
    // The off-bin tone's slowly decaying rectangular sidelobes (A/(πδ)) reach bin 160 at ~2.5e-4.
    EXPECT_NEAR(s.amplitude(160, 0), 2e-3, 2e-3 * 1e-3);
    const double scalloped = 0.5e-3 * 2.0 / std::numbers::pi;
    // Its own negative-frequency image perturbs it at the 1e-3 level.
    EXPECT_NEAR(s.amplitude(480, 0), scalloped, scalloped * 5e-3);
    EXPECT_NEAR(20.0 * std::log10(s.amplitude(480, 0) / 0.5e-3), -3.92, 0.05);
}

TEST(VelocitySpectrum, TonesPowerAddsUpToTheTimeDomainMeanSquare) {
    const Eigen::MatrixXd x = twoTones();
    // By hand: A1²/2 + A2²/2 = 2e-6 + 1.25e-7, less the tones' cross term, which does not average
    // out over a record holding a half-integer number of the second tone's periods (~8e-5 here).
    EXPECT_NEAR(meanSquareOf(x), 2.125e-6, 2.125e-6 * 1e-4);
    // Rectangular: Parseval exactly, cross term included.
    SpectrumAnalyzer rectangular(kSamples, kSampleRate_hz, WindowKind::Rectangular);
    EXPECT_NEAR(rectangular.analyze(x).meanSquare().sum(), meanSquareOf(x), meanSquareOf(x) * 1e-10);
    // Hann: the power-corrected bins hold the tones' powers (the taper removes the cross term).
    SpectrumAnalyzer hann(kSamples, kSampleRate_hz);
    const VelocitySpectrum s = hann.analyze(x);
    EXPECT_NEAR(s.meanSquare().sum(), 2.125e-6, 2.125e-6 * 1e-9);
    EXPECT_NEAR(s.meanSquare().sum(), meanSquareOf(x), meanSquareOf(x) * 1e-4);
    // Hann spreads the on-bin tone's power ½ A² over three bins as 1/6, 2/3, 1/6 (its DFT lines
    // −¼, ½, −¼ squared).
    EXPECT_NEAR(s.meanSquare(160, 0), 2e-6 * 2.0 / 3.0, 2e-6 * 1e-8);
    EXPECT_NEAR(s.meanSquare(159, 0), 2e-6 / 6.0, 2e-6 * 1e-8);
    EXPECT_NEAR(s.meanSquare(161, 0), 2e-6 / 6.0, 2e-6 * 1e-8);
}

TEST(VelocitySpectrum, WhiteNoisePowerAddsUpToItsVariance) {
    const int n = 65536;
    std::mt19937_64 rng(20240607);
    std::normal_distribution<double> gauss(0.0, 0.3);  // variance 0.09 (m/s)²
    Eigen::MatrixXd x(n, 1);
    for (int i = 0; i < n; ++i) x(i, 0) = gauss(rng);
    const double timeMeanSquare = meanSquareOf(x);
    EXPECT_NEAR(timeMeanSquare, 0.09, 0.09 * 0.03);  // sample variance: ±0.55 % (1σ) at this n

    SpectrumAnalyzer rectangular(n, kSampleRate_hz, WindowKind::Rectangular);
    EXPECT_NEAR(rectangular.analyze(x).meanSquare().sum(), timeMeanSquare, timeMeanSquare * 1e-10);  // Parseval, exact

    SpectrumAnalyzer hann(n, kSampleRate_hz);
    const Eigen::MatrixXd m = hann.analyze(x).meanSquare();
    EXPECT_NEAR(m.sum(), timeMeanSquare, timeMeanSquare * 0.02);  // power correction: unbiased, not exact
    // A flat spectrum: each interior bin holds 2σ²/N on average.
    const double perBin = m.col(0).segment(1, n / 2 - 1).mean();
    EXPECT_NEAR(perBin, 2.0 * 0.09 / n, 2.0 * 0.09 / n * 0.05);
}

TEST(VelocitySpectrum, OddLengthHasNoNyquistBinAndStillAddsUp) {
    const int n = 1001;
    Eigen::MatrixXd x(n, 1);
    x.col(0) = tone(1.0, 37.0 * kSampleRate_hz / n, 0.2, n) + Eigen::VectorXd::Constant(n, 0.25);
    SpectrumAnalyzer analyzer(n, kSampleRate_hz, WindowKind::Rectangular);
    const VelocitySpectrum s = analyzer.analyze(x);
    EXPECT_EQ(s.binCount(), 501);
    EXPECT_NEAR(s.amplitude(0, 0), 0.25, 1e-12);  // the mean
    EXPECT_NEAR(s.amplitude(37, 0), 1.0, 1e-12);
    EXPECT_NEAR(s.meanSquare().sum(), 0.5 + 0.0625, 1e-12);
}

TEST(VelocitySpectrum, OnePlanServesManyPointsAndRecords) {
    SpectrumAnalyzer analyzer(kSamples, kSampleRate_hz);
    Eigen::MatrixXd x(kSamples, 3);
    x.col(0) = tone(1e-3, 1000.0);
    x.col(1) = 3.0 * x.col(0);
    x.col(2) = tone(1e-3, 2000.0);
    const VelocitySpectrum first = analyzer.analyze(x);
    EXPECT_NEAR(first.amplitude(160, 1), 3e-3, 1e-12);
    EXPECT_NEAR(first.amplitude(320, 2), 1e-3, 1e-12);
    EXPECT_LT(first.amplitude(320, 0), 1e-15);
    const VelocitySpectrum second = analyzer.analyze(x.rightCols(1));  // a block, no copy
    EXPECT_NEAR(second.amplitude(320, 0), 1e-3, 1e-12);
}
