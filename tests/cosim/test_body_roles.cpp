// Reduced bodies that do not fit the role the case gives them: a liner's body given as the
// piston, the piston's as the liner, and a piston surface that misses most of the film grid.
#include <cstdio>
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../TestScratch.hpp"
#include "CliRunner.hpp"
#include "SmallEngineCase.hpp"
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/mapping/FlexibleBodyLoader.hpp"

namespace {

using namespace flexehd;
using ::testing::HasSubstr;

std::string reduceSmallLiner(const std::string& file) {
    const auto r = test::runFlexehd("reduce --mesh " + std::string(FLEXEHD_SOURCE_DIR) +
                                    "/meshes/liner.geo --size 0.009 --E 1.1e11 --nu 0.26 --rho 7200 "
                                    "--interface top_seat:rbe2 --interface bottom_seat:rbe2 --modes 4 --out " +
                                    file);
    EXPECT_EQ(r.status, 0) << r.err;
    return file;
}

std::string reduceSmallPiston(const std::string& file) {
    const auto r = test::reduceSmallPiston(file);
    EXPECT_EQ(r.status, 0) << r.err;
    return file;
}

// What attaching the case's bodies to the skirt's film says (empty: accepted).
std::string attach(const cosim::EngineCase& c) {
    return test::errorOf([&] { cosim::SkirtContact(c, cosim::loadCaseBodies(c), [](double) { return 0.0; }); });
}

TEST(BodyRoles, LinerBodyGivenAsThePistonIsRefused) {
    const auto dir = test::scratchDir();
    cosim::EngineCase c = test::smallFlexibleCase(reduceSmallLiner((dir / "liner.h5").string()));
    c.path = "case.yaml";
    c.pistonBody.surface = "bore";
    c.pistonBody.interface = "top_seat";
    c.pistonBody.interfaces = {"top_seat"};
    const std::string err = attach(c);
    std::printf("%s\n", err.c_str());
    EXPECT_THAT(err, HasSubstr("case.yaml: bodies.piston.surface: the surface 'bore' of the reduced body"));
    EXPECT_THAT(err, HasSubstr("faces towards the axis, as a liner bore's does; the case expects the piston's body"));
    EXPECT_THAT(err, HasSubstr("(its interfaces: top_seat, bottom_seat)"));
}

TEST(BodyRoles, PistonBodyGivenAsTheLinerIsRefused) {
    const auto dir = test::scratchDir();
    cosim::EngineCase c = test::smallCase();
    c.path = "case.yaml";
    c.grid = {12, 40};
    c.linerBody.model = cosim::BodyModel::Flexible;
    c.linerBody.file = reduceSmallPiston((dir / "piston.h5").string());
    c.linerBody.surface = "skirt";
    c.linerBody.interface = "pin_bore";
    c.linerBody.interfaces = {"pin_bore"};
    const std::string err = attach(c);
    std::printf("%s\n", err.c_str());
    EXPECT_THAT(err, HasSubstr("case.yaml: bodies.liner.surface: the surface 'skirt' of the reduced body"));
    EXPECT_THAT(err, HasSubstr("faces away from the axis, as a piston skirt's does; the case expects the liner's body"));
}

TEST(BodyRoles, PistonSurfaceMissingMostOfTheGridIsRefused) {
    const auto dir = test::scratchDir();
    cosim::EngineCase c = test::smallFlexibleCase(reduceSmallPiston((dir / "piston.h5").string()));
    c.path = "case.yaml";
    // The case's skirt 106 mm long, the mesh's 36 mm: about two thirds of the grid lie below it.
    c.piston.skirtBottom = -0.095;
    c.piston.profile.insert(c.piston.profile.begin(), {-0.095, 20e-6});
    const std::string err = attach(c);
    std::printf("%s\n", err.c_str());
    EXPECT_THAT(err, HasSubstr("case.yaml: bodies.piston.surface: "));
    EXPECT_THAT(err, HasSubstr("film nodes of the piston's grid"));
    EXPECT_THAT(err, HasSubstr("lie outside the surface 'skirt' of the reduced body"));
    EXPECT_THAT(err, HasSubstr("mm from it: the case expects the piston's film surface over z -95.0 to"));
}

TEST(BodyRoles, MatchingPistonIsAcceptedWithAFewEdgeNodesOutside) {
    const auto dir = test::scratchDir();
    const cosim::EngineCase c = test::smallFlexibleCase(reduceSmallPiston((dir / "piston.h5").string()));
    const cosim::CaseBodies bodies = cosim::loadCaseBodies(c);
    const cosim::SkirtContact skirt(c, bodies, [](double) { return 0.0; });
    ASSERT_TRUE(skirt.piston());
    const double outside = double(skirt.piston()->outsideNodes().size());
    EXPECT_LE(outside, cosim::kMaxOutsideFraction * skirt.film().grid().filmNodeCount());
    std::printf("matching piston: %.0f of %d film nodes outside the skirt surface\n", outside,
                skirt.film().grid().filmNodeCount());
}

}  // namespace
