// `flexehd reduce` end to end: reduce a cantilever through the command line, read the
// file, and load the reduced body at the tip: the quasi-static deflection must match
// Euler–Bernoulli, δ = P L³ / (3 E I).
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../fem/TestData.hpp"
#include "CliRunner.hpp"
#include "modal/ModalSuperposition.hpp"
#include "modal/ReducedBodyFile.hpp"

using flexehd::test::dataPath;
using flexehd::test::runFlexehd;
using testing::HasSubstr;
using namespace flexehd;

TEST(CliReduce, CantileverTipDeflectionFromTheFile) {
    const auto dir = flexehd::test::scratchDir();
    const std::string h5 = (dir / "bodies" / "beam.h5").string();  // the directory is made
    const auto r = runFlexehd("reduce --mesh " + dataPath("beam.geo") +
                              " --E 2.1e11 --nu 0.3 --rho 7850 --interface clamped:rbe2@0,0.01,0.01 --modes 12"
                              " --out " + h5 + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto doc = nlohmann::json::parse(r.out);
    EXPECT_EQ(doc.at("basis").at("constraint"), 6);
    EXPECT_EQ(doc.at("basis").at("normal"), 12);
    EXPECT_EQ(doc.at("rigid_body_modes"), 6);
    EXPECT_TRUE(doc.at("timings_s").contains("factorize"));

    const modal::ReducedBody body = modal::readReducedBody(h5);
    ASSERT_EQ(body.interfaces.size(), 1u);
    EXPECT_EQ(body.interfaces[0].referencePoint, Eigen::Vector3d(0, 0.01, 0.01));
    // Tip force P = 10 N along y, spread evenly over the tip face's nodes.
    const auto tip = body.mesh.groupNodes("tip");
    Eigen::VectorXd f = Eigen::VectorXd::Zero(body.shapes.rows());
    for (auto n : tip) f(3 * n + 1) = 10.0 / double(tip.size());
    modal::ModalSuperposition sup(body);
    const Eigen::VectorXd u = sup.displacement(sup.quasiStatic(sup.modalForce(f), {0}));
    double uy = 0.0;
    for (auto n : tip) uy += u(3 * n + 1) / double(tip.size());
    const double I = std::pow(0.02, 4) / 12.0, delta = 10.0 * 1.0 / (3.0 * 2.1e11 * I);
    EXPECT_NEAR(uy / delta, 1.0, 0.01);
}

TEST(CliReduce, UnknownInterfaceGroupFails) {
    const auto r = runFlexehd("reduce --mesh " + dataPath("beam.geo") +
                              " --E 2.1e11 --nu 0.3 --rho 7850 --interface pin_bore:rbe2 --out /tmp/x.h5");
    EXPECT_EQ(r.status, 1);
    EXPECT_THAT(r.err, HasSubstr("no physical group 'pin_bore'"));
    EXPECT_FALSE(std::filesystem::exists("/tmp/x.h5"));
}

TEST(CliReduce, VolumeInterfaceAndUnphysicalMaterialAreRefusedWhereTheyEnter) {
    const std::string mesh = dataPath("beam.geo");
    const auto volume = runFlexehd("reduce --mesh " + mesh + " --E 2.1e11 --nu 0.3 --rho 7850 --interface beam:rbe2 --out /tmp/x.h5");
    EXPECT_EQ(volume.status, 1);
    EXPECT_THAT(volume.err, HasSubstr("interface 'beam' is a volume group of mesh"));
    EXPECT_THAT(volume.err, HasSubstr("an interface is a surface group"));
    const auto stiff = runFlexehd("reduce --mesh " + mesh + " --E 1e300 --nu 0.3 --rho 7850 --interface clamped:rbe2 --out /tmp/x.h5");
    EXPECT_EQ(stiff.status, 1);
    EXPECT_THAT(stiff.err, HasSubstr("flexehd: error: --E: expected a number from 1e5 to 1e13, got '1e300'"));
    const auto light = runFlexehd("modes --mesh " + mesh + " --E 2.1e11 --nu 0.3 --rho 1e-3");
    EXPECT_EQ(light.status, 1);
    EXPECT_THAT(light.err, HasSubstr("--rho: expected a number from 10 to 1e5, got '1e-3'"));
    EXPECT_FALSE(std::filesystem::exists("/tmp/x.h5"));
}

// `--support GROUP:K`: Winkler springs on the beam's tip (docs/modal.md, "Spring and damper supports"). The
// file records the option's text; the held body is stiffer than the plain cantilever.
TEST(CliReduce, SpringSupportIsRecordedAndStiffensTheHeldBody) {
    const auto dir = flexehd::test::scratchDir();
    const std::string base = "reduce --mesh " + dataPath("beam.geo") +
                             " --E 2.1e11 --nu 0.3 --rho 7850 --interface clamped:rbe2 --modes 6 --size 0.02 --json";
    const std::string plain = (dir / "plain.h5").string(), supported = (dir / "supported.h5").string();
    const auto a = runFlexehd(base + " --out " + plain);
    ASSERT_EQ(a.status, 0) << a.err;
    const auto b = runFlexehd(base + " --support tip:1e10 --out " + supported);
    ASSERT_EQ(b.status, 0) << b.err;
    EXPECT_EQ(nlohmann::json::parse(b.out).at("supports"), nlohmann::json({"tip:1e10"}));
    const modal::ReducedBody p = modal::readReducedBody(plain), s = modal::readReducedBody(supported);
    EXPECT_TRUE(p.settings.supports.empty());
    EXPECT_EQ(s.settings.supports, std::vector<std::string>{"tip:1e10"});
    // K A = 1e10 · 4e-4 = 4e6 N/m against the cantilever's 3EI/L³ = 8.4e3 N/m: the tip is nearly pinned.
    EXPECT_GT(modal::heldFrequenciesHz(s, {0})(0), 3.0 * modal::heldFrequenciesHz(p, {0})(0));
    const auto inspect = runFlexehd("inspect " + supported);
    ASSERT_EQ(inspect.status, 0) << inspect.err;
    EXPECT_THAT(inspect.out, HasSubstr("supports     tip:1e10"));
}

TEST(CliReduce, BadSupportsAreRefusedNamingTheOption) {
    const std::string base = "reduce --mesh " + dataPath("beam.geo") +
                             " --E 2.1e11 --nu 0.3 --rho 7850 --interface clamped:rbe2 --out /tmp/x.h5 --support ";
    const struct {
        std::string arg, message;
    } cases[] = {
        {"tip", "--support 'tip': expected GROUP:K with K in N/m^3"},
        {"tip:stiff", "--support 'tip:stiff': K must be a number in N/m^3"},
        {"tip:-1e9", "--support 'tip:-1e9': K must be finite and > 0 N/m^3"},
        {"tip:inf", "--support 'tip:inf': K must be finite and > 0 N/m^3"},
        {"top:1e9", "--support 'top:1e9': mesh '"},
        {"clamped:1e9", "--support 'clamped:1e9': group 'clamped' is also an interface"},
    };
    for (const auto& c : cases) {
        const auto r = runFlexehd(base + c.arg);
        EXPECT_EQ(r.status, 1) << c.arg;
        EXPECT_THAT(r.err, HasSubstr(c.message)) << c.arg;
    }
    EXPECT_FALSE(std::filesystem::exists("/tmp/x.h5"));
}

// `--damper GROUP:C`: dashpots on the beam's tip, with springs on the same group (docs/modal.md,
// "Spring and damper supports"). The modes are those of the springs alone (the reduction stays
// undamped); the file carries D_s = Φᵀ C_s Φ, which `inspect` and `reduce --json` list.
TEST(CliReduce, DamperSupportIsProjectedOnTheModesAndListed) {
    const auto dir = flexehd::test::scratchDir();
    const std::string base = "reduce --mesh " + dataPath("beam.geo") +
                             " --E 2.1e11 --nu 0.3 --rho 7850 --interface clamped:rbe2 --modes 6 --size 0.02 --json"
                             " --support tip:1e10";
    const std::string springs = (dir / "springs.h5").string(), damped = (dir / "damped.h5").string();
    const auto a = runFlexehd(base + " --out " + springs);
    ASSERT_EQ(a.status, 0) << a.err;
    const auto b = runFlexehd(base + " --damper tip:1e5 --out " + damped);
    ASSERT_EQ(b.status, 0) << b.err;
    EXPECT_EQ(nlohmann::json::parse(b.out).at("dampers"), nlohmann::json({"tip:1e5"}));
    EXPECT_EQ(nlohmann::json::parse(a.out).at("dampers"), nlohmann::json::array());
    const modal::ReducedBody s = modal::readReducedBody(springs), d = modal::readReducedBody(damped);
    EXPECT_TRUE(s.settings.dampers.empty());
    EXPECT_EQ(s.supportDamping.size(), 0);
    EXPECT_EQ(d.settings.dampers, std::vector<std::string>{"tip:1e5"});
    ASSERT_EQ(d.supportDamping.rows(), d.numModes());
    EXPECT_EQ(d.frequenciesHz, s.frequenciesHz);  // the same undamped reduction
    EXPECT_GT(d.supportDamping.diagonal().maxCoeff(), 0.0);
    const auto inspect = runFlexehd("inspect " + damped);
    ASSERT_EQ(inspect.status, 0) << inspect.err;
    EXPECT_THAT(inspect.out, HasSubstr("dampers      tip:1e5 (GROUP:C, N*s/m^3)"));
    const auto json = runFlexehd("inspect --json " + damped);
    ASSERT_EQ(json.status, 0) << json.err;
    EXPECT_EQ(nlohmann::json::parse(json.out).at("settings").at("dampers"), nlohmann::json({"tip:1e5"}));
}

// The text summary lists the supports and the range the modes cover, the 6th held frequency with
// --modes 6 (modal::normalModesUpToHz; against the full model in test_craig_bampton.cpp), and
// `inspect` prints and writes the same range.
TEST(CliReduce, TheSummaryListsTheSupportsAndTheRangeTheModesCover) {
    const auto dir = flexehd::test::scratchDir();
    const std::string file = (dir / "beam.h5").string();
    const auto r = runFlexehd("reduce --mesh " + dataPath("beam.geo") +
                              " --E 2.1e11 --nu 0.3 --rho 7850 --interface clamped:rbe2 --modes 6 --size 0.02"
                              " --support tip:1e10 --damper tip:1e5 --out " + file);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("spring supports tip:1e10 [N/m^3]"));
    EXPECT_THAT(r.out, HasSubstr("damper supports tip:1e5 [N*s/m^3]"));
    const double sixth = modal::heldFrequenciesHz(modal::readReducedBody(file), {0})(5);
    EXPECT_THAT(r.out, HasSubstr(fmt::format("covers every fixed-interface normal mode up to {:.6g} Hz", sixth)));
    const auto inspect = runFlexehd("inspect " + file);
    ASSERT_EQ(inspect.status, 0) << inspect.err;
    EXPECT_THAT(inspect.out, HasSubstr(fmt::format("every fixed-interface normal mode up to {:.6g} Hz (--modes 6)", sixth)));
    const auto json = runFlexehd("inspect --json " + file);
    ASSERT_EQ(json.status, 0) << json.err;
    EXPECT_DOUBLE_EQ(nlohmann::json::parse(json.out).at("normal_modes_up_to_hz").get<double>(), sixth);
}

TEST(CliReduce, BadDampersAreRefusedNamingTheOption) {
    const std::string base = "reduce --mesh " + dataPath("beam.geo") +
                             " --E 2.1e11 --nu 0.3 --rho 7850 --interface clamped:rbe2 --out /tmp/x.h5 --damper ";
    const struct {
        std::string arg, message;
    } cases[] = {
        {"tip", "--damper 'tip': expected GROUP:C with C in N*s/m^3"},
        {"tip:soft", "--damper 'tip:soft': C must be a number in N*s/m^3"},
        {"tip:0", "--damper 'tip:0': C must be finite and > 0 N*s/m^3"},
        {"tip:-1e5", "--damper 'tip:-1e5': C must be finite and > 0 N*s/m^3"},
        {"tip:nan", "--damper 'tip:nan': C must be finite and > 0 N*s/m^3"},
        {"top:1e5", "--damper 'top:1e5': mesh '"},
        {"clamped:1e5", "--damper 'clamped:1e5': group 'clamped' is also an interface"},
        {"tip:1e5 --damper tip:2e5", "--damper 'tip:2e5': group 'tip' has a damper already"},
    };
    for (const auto& c : cases) {
        const auto r = runFlexehd(base + c.arg);
        EXPECT_EQ(r.status, 1) << c.arg;
        EXPECT_THAT(r.err, HasSubstr(c.message)) << c.arg;
    }
    EXPECT_FALSE(std::filesystem::exists("/tmp/x.h5"));
}
