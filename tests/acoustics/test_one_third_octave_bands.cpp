// OneThirdOctaveBands (acoustics/OneThirdOctaveBands.hpp): the IEC 61260-1 base-10 mid
// frequencies and edges (1000 · 10^(k/10), edges × 10^(±1/20): band 0 from 891.251 to
// 1122.018 Hz, the nominal 1250 Hz band's exact mid 1258.925 Hz); a 1000 Hz tone's ERP lands in
// band 0 whole; a Hann tone one bin below band 0's upper edge leaves the bin above the edge, 1/6 of
// its power (the Hann DFT lines ½, −¼, −¼ squared), in band 1.
#include <gtest/gtest.h>

#include "acoustics/OneThirdOctaveBands.hpp"
#include "acoustics/RadiatedPower.hpp"
#include "acoustics/SpectrumAnalyzer.hpp"
#include "tests/acoustics/AcousticsTestSupport.hpp"

using namespace flexehd::acoustics;
using namespace flexehd::acoustics::test;

TEST(OneThirdOctaveBands, MidFrequenciesAndEdgesAreBaseTen) {
    EXPECT_DOUBLE_EQ(OneThirdOctaveBand::midFrequency_hz(0), 1000.0);
    EXPECT_NEAR(OneThirdOctaveBand::lowerEdge_hz(0), 891.2509, 1e-4);
    EXPECT_NEAR(OneThirdOctaveBand::upperEdge_hz(0), 1122.0185, 1e-4);
    EXPECT_NEAR(OneThirdOctaveBand::midFrequency_hz(1), 1258.9254, 1e-4);
    EXPECT_NEAR(OneThirdOctaveBand::midFrequency_hz(-10), 100.0, 1e-10);
    EXPECT_NEAR(OneThirdOctaveBand::midFrequency_hz(10), 10000.0, 1e-9);
    EXPECT_NEAR(OneThirdOctaveBand::upperEdge_hz(-1), OneThirdOctaveBand::lowerEdge_hz(0), 1e-9);  // contiguous
}

TEST(OneThirdOctaveBands, AFrequencyBelongsToTheBandBetweenItsEdges) {
    EXPECT_EQ(OneThirdOctaveBand::containing(1000.0), 0);
    EXPECT_EQ(OneThirdOctaveBand::containing(891.25), -1);
    EXPECT_EQ(OneThirdOctaveBand::containing(891.26), 0);
    EXPECT_EQ(OneThirdOctaveBand::containing(1122.01), 0);
    EXPECT_EQ(OneThirdOctaveBand::containing(1122.02), 1);
    EXPECT_EQ(OneThirdOctaveBand::containing(100.0), -10);
    EXPECT_EQ(OneThirdOctaveBand::containing(20.0), -17);  // the 20 Hz band, mid 19.953 Hz
}

namespace {
BandSpectrum plateBands(double frequency_hz) {
    Eigen::MatrixXd x(kSamples, 1);
    x.col(0) = tone(1e-3, frequency_hz);
    SpectrumAnalyzer hann(kSamples, kSampleRate_hz);
    return RadiatedPower(Eigen::VectorXd::Constant(1, 0.01)).inOneThirdOctaveBands_W(hann.analyze(x));
}
int column(const BandSpectrum& b, int band) { return band - b.band.front(); }
constexpr double kPlateErp_W = 2.06486e-6;  // ½ · 1.204 · 343 · (1e-3)² · 0.01
}  // namespace

TEST(OneThirdOctaveBands, AToneLandsInItsBand) {
    const BandSpectrum b = plateBands(1000.0);
    EXPECT_EQ(b.band.front(), OneThirdOctaveBand::containing(6.25));   // the first bin's band
    EXPECT_EQ(b.band.back(), OneThirdOctaveBand::containing(25600.0));  // Nyquist's
    const int c = column(b, 0);
    EXPECT_NEAR(b.midFrequency_hz(c), 1000.0, 1e-9);
    EXPECT_NEAR(b.value(c), kPlateErp_W, kPlateErp_W * 1e-9);
    EXPECT_NEAR(b.value.sum(), kPlateErp_W, kPlateErp_W * 1e-9);
}

TEST(OneThirdOctaveBands, BinsGoWholeToTheBandOfTheirCentre) {
    // 1118.75 Hz (bin 179): Hann puts 1/6, 2/3, 1/6 of ½ρcv²A in 1112.5, 1118.75 and 1125 Hz;
    // 1125 Hz lies above band 0's upper edge 1122.018 Hz.
    const BandSpectrum b = plateBands(1118.75);
    EXPECT_NEAR(b.value(column(b, 0)), kPlateErp_W * 5.0 / 6.0, kPlateErp_W * 1e-9);
    EXPECT_NEAR(b.value(column(b, 1)), kPlateErp_W / 6.0, kPlateErp_W * 1e-9);
}
