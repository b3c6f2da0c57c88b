// SpectralWindow (acoustics/SpectralWindow.hpp): the periodic Hann window's coherent gain ½,
// power gain 3/8 and equivalent noise bandwidth 1.5 bins (Harris, Proc. IEEE 66 (1978) 51,
// Table 1); the rectangular window's 1, 1, 1.
#include <gtest/gtest.h>

#include "acoustics/SpectralWindow.hpp"

using namespace flexehd::acoustics;

TEST(SpectralWindow, HannGainsAreHalfThreeEighthsAndOneAndAHalfBins) {
    const SpectralWindow w(WindowKind::Hann, 1024);
    EXPECT_NEAR(w.coherentGain(), 0.5, 1e-14);
    EXPECT_NEAR(w.powerGain(), 0.375, 1e-14);
    EXPECT_NEAR(w.equivalentNoiseBandwidth_bins(), 1.5, 1e-13);
    EXPECT_DOUBLE_EQ(w.coefficients()(0), 0.0);    // periodic: starts at 0 ...
    EXPECT_NEAR(w.coefficients()(512), 1.0, 1e-15);  // ... peaks at N/2 and does not return to 0
    EXPECT_EQ(w.name(), "hann");
}

TEST(SpectralWindow, RectangularGainsAreOne) {
    const SpectralWindow w(WindowKind::Rectangular, 7);
    EXPECT_DOUBLE_EQ(w.coherentGain(), 1.0);
    EXPECT_DOUBLE_EQ(w.powerGain(), 1.0);
    EXPECT_DOUBLE_EQ(w.equivalentNoiseBandwidth_bins(), 1.0);
}
