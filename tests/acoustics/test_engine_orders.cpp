// EngineOrderSpectrum (acoustics/EngineOrderSpectrum.hpp): at 3000 rpm (50 Hz) a 150 Hz tone is
// order 3 and a 375 Hz tone order 7.5; ranked by ERP the plate's 1 mm/s tone (2.06486e-6 W) comes
// before its 0.5 mm/s one (5.16215e-7 W, a quarter), each line holding its tone's whole power.
#include <gtest/gtest.h>

#include <gmock/gmock.h>

#include <stdexcept>

#include "acoustics/EngineOrderSpectrum.hpp"
#include "acoustics/RadiatedPower.hpp"
#include "acoustics/SpectrumAnalyzer.hpp"
#include "tests/acoustics/AcousticsTestSupport.hpp"

using namespace flexehd::acoustics;
using namespace flexehd::acoustics::test;

namespace {
struct TwoOrders {
    VelocitySpectrum spectrum;
    Eigen::VectorXd erp_W;
};
TwoOrders twoOrders() {
    Eigen::MatrixXd x(kSamples, 1);
    x.col(0) = tone(0.5e-3, 375.0) + tone(1e-3, 150.0, 0.7);
    SpectrumAnalyzer hann(kSamples, kSampleRate_hz);
    VelocitySpectrum s = hann.analyze(x);
    Eigen::VectorXd erp = RadiatedPower(Eigen::VectorXd::Constant(1, 0.01)).perBin_W(s);
    return {std::move(s), std::move(erp)};
}
}  // namespace

TEST(EngineOrderSpectrum, AToneAtThreeTimesTheCrankFrequencyIsOrderThree) {
    const TwoOrders t = twoOrders();
    const EngineOrderSpectrum orders(t.spectrum.frequency_hz(), t.erp_W, 3000.0);
    EXPECT_DOUBLE_EQ(orders.crankFrequency_hz(), 50.0);
    EXPECT_DOUBLE_EQ(orders.binOrder()(24), 3.0);  // 150 Hz
    const std::vector<OrderLine> top = orders.top(2);
    ASSERT_EQ(top.size(), 2u);
    EXPECT_DOUBLE_EQ(top[0].order, 3.0);
    EXPECT_DOUBLE_EQ(top[0].frequency_hz, 150.0);
    EXPECT_NEAR(top[0].power, 2.06486e-6, 2.06486e-6 * 1e-9);
    EXPECT_DOUBLE_EQ(top[1].order, 7.5);
    EXPECT_NEAR(top[1].power, 5.16215e-7, 5.16215e-7 * 1e-9);
    EXPECT_DOUBLE_EQ(orders.lines().front().order, 0.5);
    EXPECT_NEAR(orders.lines()[5].power, 2.06486e-6, 2.06486e-6 * 1e-9);  // line 6 × ½ = order 3
}

TEST(EngineOrderSpectrum, WholeOrdersForATwoStroke) {
    const TwoOrders t = twoOrders();
    const EngineOrderSpectrum orders(t.spectrum.frequency_hz(), t.erp_W, 3000.0, 1.0);
    EXPECT_DOUBLE_EQ(orders.top(1).front().order, 3.0);
    EXPECT_DOUBLE_EQ(orders.lines()[1].order, 2.0);
}

TEST(EngineOrderSpectrum, AnOrderStepFinerThanTheBinsIsRefused) {
    const TwoOrders t = twoOrders();  // bins 6.25 Hz = 0.125 orders at 50 Hz
    EXPECT_THAT([&] { EngineOrderSpectrum(t.spectrum.frequency_hz(), t.erp_W, 3000.0, 0.1); },
                testing::ThrowsMessage<std::invalid_argument>(testing::HasSubstr("orderStep: expected at least")));
}
