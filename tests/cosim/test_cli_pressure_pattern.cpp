// `flexehd reduce --pressure-pattern GROUP` end to end: the uniform-pressure vector reaches the
// file, `flexehd inspect` lists it (text and JSON), and an unknown group is named in the error;
// a band of a group (GROUP@ZLOW:ZHIGH) likewise, and an empty or malformed band is refused.
#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../fem/TestData.hpp"
#include "CliRunner.hpp"

using flexehd::test::meshPath;
using flexehd::test::runFlexehd;
using testing::HasSubstr;

namespace {

// The coarse piston: meshing and reducing it take a few seconds.
std::string reduceCoarsePiston(const std::string& extra, const std::string& out) {
    return "reduce --mesh " + meshPath("piston.geo") +
           " --size 0.012 --E 7.5e10 --nu 0.33 --rho 2700 --interface pin_bore:rbe2 --modes 6"
           " --static-correction skirt " + extra + " --out " + out;
}

}  // namespace

TEST(CliPressurePattern, ReducedBodyCarriesTheCrownPattern) {
    const auto dir = flexehd::test::scratchDir();
    const std::string h5 = (dir / "piston.h5").string();
    const auto r = runFlexehd(reduceCoarsePiston("--pressure-pattern crown", h5));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("uniform pressure on crown"));

    const auto text = runFlexehd("inspect " + h5);
    ASSERT_EQ(text.status, 0) << text.err;
    EXPECT_THAT(text.out, HasSubstr("pressure patterns crown"));
    EXPECT_THAT(text.out, HasSubstr("load patterns  inertia relief (pin_bore), static correction skirt (axial order "
                                    "4, circumferential order 6), uniform pressure crown\n"));

    const auto json = runFlexehd("inspect " + h5 + " --json");
    ASSERT_EQ(json.status, 0) << json.err;
    EXPECT_EQ(nlohmann::json::parse(json.out).at("settings").at("pressure_patterns"),
              (std::vector<std::string>{"crown"}));
}

TEST(CliPressurePattern, UnknownGroupIsNamed) {
    const auto dir = flexehd::test::scratchDir();
    const std::string h5 = (dir / "piston.h5").string();
    const auto r = runFlexehd(reduceCoarsePiston("--pressure-pattern nosuchgroup", h5));
    EXPECT_EQ(r.status, 1);
    EXPECT_THAT(r.err, HasSubstr("pressure pattern 'nosuchgroup'"));
    EXPECT_FALSE(std::filesystem::exists(h5));
}

TEST(CliPressurePattern, ABandOfAGroupIsAPatternOfItsOwn) {
    const auto dir = flexehd::test::scratchDir();
    const std::string h5 = (dir / "piston.h5").string();
    const auto r = runFlexehd(reduceCoarsePiston(
        "--pressure-pattern ring_grooves@0.01979:0.01981 --pressure-pattern ring_lands@0.0265:", h5));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("uniform pressure on ring_grooves@0.01979:0.01981, ring_lands@0.0265:"));
    const auto json = runFlexehd("inspect " + h5 + " --json");
    ASSERT_EQ(json.status, 0) << json.err;
    EXPECT_EQ(nlohmann::json::parse(json.out).at("settings").at("pressure_patterns"),
              (std::vector<std::string>{"ring_grooves@0.01979:0.01981", "ring_lands@0.0265:"}));
    for (const std::string bad : {"ring_grooves@0.5:0.6", "ring_grooves@0.02:0.01", "ring_grooves@x:"}) {
        const std::string out = (dir / "bad.h5").string();
        const auto e = runFlexehd(reduceCoarsePiston("--pressure-pattern " + bad, out));
        EXPECT_EQ(e.status, 1) << bad;
        EXPECT_THAT(e.err, HasSubstr("pressure pattern '" + bad + "'")) << bad;
        EXPECT_FALSE(std::filesystem::exists(out)) << bad;
    }
}
