// ShortTimeRadiatedPower (acoustics/ShortTimeRadiatedPower.hpp): 8192 samples at 51.2 kHz,
// silent for the first 4096 and a 1 mm/s 1000 Hz tone on a 0.01 m² plate after; frames of 1024
// samples every 512: ⌊(8192 − 1024)/512⌋ + 1 = 15 frames; at 3000 rpm (18000 °/s) a hop is 180°
// and frame j's centre (512 j + 512 samples) sits at −360 + 180 (j + 1) degrees; frames ending by
// sample 4096 hold nothing, frames starting at or after it hold ½ρcv²A = 2.06486e-6 W in the 1 kHz
// band.
#include <gtest/gtest.h>

#include "acoustics/ShortTimeRadiatedPower.hpp"
#include "tests/acoustics/AcousticsTestSupport.hpp"

using namespace flexehd::acoustics;
using namespace flexehd::acoustics::test;

TEST(ShortTimeRadiatedPower, ABurstShowsInTheFramesAfterItsStart) {
    Eigen::MatrixXd x = Eigen::MatrixXd::Zero(kSamples, 1);
    x.col(0).tail(4096) = tone(1e-3, 1000.0, 0.4, 4096);
    ShortTimeRadiatedPower stft(RadiatedPower(Eigen::VectorXd::Constant(1, 0.01)), kSampleRate_hz, 1024, 512);
    const CrankAngleBandMap m = stft.map(x, 3000.0, -360.0);
    ASSERT_EQ(m.crankAngle_deg.size(), 15);
    ASSERT_EQ(m.power_W.rows(), 15);
    EXPECT_DOUBLE_EQ(m.crankAngle_deg(0), -180.0);
    EXPECT_DOUBLE_EQ(m.crankAngle_deg(14), 2340.0);
    // Bins of a 1024-frame are 50 Hz apart: bands from 50 Hz's to 25.6 kHz's.
    EXPECT_EQ(m.band.front(), OneThirdOctaveBand::containing(50.0));
    EXPECT_EQ(m.band.back(), OneThirdOctaveBand::containing(25600.0));
    const int kHz = 0 - m.band.front();
    EXPECT_NEAR(m.midFrequency_hz(kHz), 1000.0, 1e-9);
    for (int j = 0; j <= 6; ++j) EXPECT_EQ(m.power_W.row(j).sum(), 0.0) << "frame " << j;
    EXPECT_GT(m.power_W(7, kHz), 0.0);  // straddles the start
    for (int j = 8; j < 15; ++j) {
        EXPECT_NEAR(m.power_W(j, kHz), 2.06486e-6, 2.06486e-6 * 1e-9) << "frame " << j;
        EXPECT_NEAR(m.power_W.row(j).sum(), 2.06486e-6, 2.06486e-6 * 1e-9) << "frame " << j;
    }
}
