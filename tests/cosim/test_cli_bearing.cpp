// The `flexehd bearing` command as a user runs it: journal-bearing loads, dimensionless design
// numbers and flows against classical solutions (Sommerfeld, Ocvirk; Hamrock, Fundamentals of Fluid Film Lubrication), solver agreement, and bad input.
#include <cmath>
#include <numbers>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "CliRunner.hpp"

using flexehd::test::CommandResult;
using flexehd::test::runFlexehd;
using testing::HasSubstr;

namespace {

constexpr double kPi = std::numbers::pi;
// Default geometry of the command, restated: R = 50 mm, c = 50 µm, μ = 0.01 Pa·s, N = 50 rev/s.
constexpr double R = 0.05, c = 50e-6, mu = 0.01, N = 50.0, omega = 2 * kPi * N;

nlohmann::json bearing(const std::string& args) {
    const CommandResult r = runFlexehd("-q bearing --json " + args);
    EXPECT_EQ(r.status, 0) << r.err;
    return nlohmann::json::parse(r.out);  // stdout holds only the JSON object
}

double num(const nlohmann::json& d, const char* key) { return d.at(key).get<double>(); }

}  // namespace

// Infinitely long bearing, half Sommerfeld, ε = 0.6: in units of 6μωR³L/c², W_r = 0.47669
// (along the line of centres), W_t = 0.99839 (half Sommerfeld); 0.5% as in the lube tests at 240 nodes.
TEST(CliBearing, LongHalfSommerfeldLoad) {
    const auto d = bearing("--eccentricity 0.6 --infinitely-long --cavitation half-sommerfeld "
                           "--grid 240x3 --length 0.1");
    const double unit = 6 * mu * omega * std::pow(R, 3) * 0.1 / (c * c);
    const double Wr = 0.47669, Wt = 0.99839, W = std::hypot(Wr, Wt);
    EXPECT_NEAR(d.at("load_components_n").at("along_line_of_centres").get<double>() / unit, Wr, 5e-3 * W);
    EXPECT_NEAR(d.at("load_components_n").at("perpendicular").get<double>() / unit, Wt, 5e-3 * W);
    EXPECT_NEAR(num(d, "load_n") / unit, W, 5e-3 * W);
    EXPECT_NEAR(num(d, "attitude_deg"), std::atan2(Wt, Wr) * 180 / kPi, 0.3);
    EXPECT_EQ(num(d, "side_flow_m3_s"), 0.0);
}

// Infinitely long, full Sommerfeld, ε = 0.6: W = 1.99677 (Sommerfeld) at 90° attitude. Friction on
// the journal T = (4πμωR³L/c)(1+2ε²)/[(2+ε²)√(1−ε²)] gives (R/c)f = T/(cW) = (1+2ε²)/(3ε);
// circumferential flow Q = ωRcL(1−ε²)/(2+ε²) gives Q/(RcNL) = 2π(1−ε²)/(2+ε²).
TEST(CliBearing, LongFullSommerfeldLoadFrictionAndFlow) {
    const double eps = 0.6;
    const auto d = bearing("--eccentricity 0.6 --infinitely-long --cavitation none --grid 240x3 --length 0.1");
    const double unit = 6 * mu * omega * std::pow(R, 3) * 0.1 / (c * c);
    EXPECT_NEAR(num(d, "load_n") / unit / 1.99677, 1.0, 1e-3);
    EXPECT_NEAR(num(d, "attitude_deg"), 90.0, 1e-6);
    EXPECT_NEAR(num(d, "friction_variable") / ((1 + 2 * eps * eps) / (3 * eps)), 1.0, 1e-3);
    EXPECT_NEAR(num(d, "flow_variable") / (2 * kPi * (1 - eps * eps) / (2 + eps * eps)), 1.0, 1e-3);
    EXPECT_NEAR(num(d, "friction_power_w"), num(d, "friction_torque_nm") * omega, 1e-9 * num(d, "friction_power_w"));
}

// The Sommerfeld number and the pressure ratio are consistent with their definitions and the
// reported load: S = (R/c)² μN/P, P = W/(LD), N in rev/s; P/p_max.
TEST(CliBearing, SommerfeldNumberDefinition) {
    const auto d = bearing("--eccentricity 0.5 --length-over-diameter 0.5 --radius 0.03 --clearance 30e-6 "
                           "--speed 25 --viscosity 0.02 --grid 64x17");
    const double L = 0.5 * 0.06, P = num(d, "load_n") / (L * 0.06);
    EXPECT_NEAR(num(d, "specific_load_pa"), P, 1e-12 * P);
    EXPECT_NEAR(num(d, "sommerfeld"), 1e6 * 0.02 * 25 / P, 1e-12 * num(d, "sommerfeld"));
    EXPECT_NEAR(num(d, "max_pressure_ratio"), P / num(d, "max_pressure_pa"), 1e-12);
    EXPECT_NEAR(num(d, "min_film_m"), 30e-6 * 0.5, 1e-12);  // grid has a node at θ = π
    EXPECT_NEAR(d.at("input").at("length_m").get<double>(), L, 1e-15);
    EXPECT_GT(num(d, "cavitated_fraction"), 0.2);
    EXPECT_LT(num(d, "cavitated_fraction"), 0.6);
    EXPECT_GT(d.at("iterations").get<int>(), 0);
    EXPECT_GE(num(d, "seconds"), 0.0);
}

// Short bearing (Ocvirk), half Sommerfeld, L/D = 1/16, no supply groove (the lube test's set-up):
// W = μωR L³ ε √(π²(1−ε²)+16ε²)/[4c²(1−ε²)²], tan φ = π√(1−ε²)/(4ε). The theory neglects the
// circumferential pressure flow, an O((L/D)²) excess: deficit < 1%, attitude within 0.2°.
TEST(CliBearing, ShortBearingOcvirk) {
    const double eps = 0.6, L = 0.1 / 16;
    const auto d = bearing("--eccentricity 0.6 --length-over-diameter 0.0625 --cavitation half-sommerfeld "
                           "--no-groove --grid 240x41");
    const double W = mu * omega * R * std::pow(L, 3) * eps * std::sqrt(kPi * kPi * (1 - eps * eps) + 16 * eps * eps) /
                     (4 * c * c * std::pow(1 - eps * eps, 2));
    const double deficit = 1 - num(d, "load_n") / W;
    EXPECT_GT(deficit, 0.0);
    EXPECT_LT(deficit, 0.01);
    EXPECT_NEAR(num(d, "attitude_deg"), std::atan(kPi * std::sqrt(1 - eps * eps) / (4 * eps)) * 180 / kPi, 0.2);
}

// Raimondi & Boyd (ASLE Trans. 1 (1958) 159), full 360° bearing, L/D = 1, h0/c = 0.4 (ε = 0.6),
// Reynolds condition, p = 0 at the maximum film. Verified against an independent reproduction
// of the L/D = 1 table (MathWorks Answers 707318, "design of journal bearing": arrays
// S_1 = [0.0188 0.0446 0.121 0.264 0.631 1.33], hoc_1 = [0.1 0.2 0.4 0.6 0.8 0.9],
// Rfc_1 = [1.05 1.70 3.2 5.79 12.8 26.4]): S = 0.121, (R/c)f = 3.2 (given to two digits there).
// Only these two are asserted. The rest of the row as recalled from Shigley's Mechanical
// Engineering Design (φ = 50.58°, Q/(RcNL) = 4.33, Qs/Q = 0.680, P/p_max = 0.415) is not
// checked against a published source here and is not asserted; the command gives
// 50.53°, 4.329, 0.668 and 0.4145 at 256×65. S and P/p_max are checked against their definitions
// in SommerfeldNumberDefinition, friction and flow against the long-bearing closed forms in
// LongFullSommerfeldLoadFrictionAndFlow.
TEST(CliBearing, RaimondiBoydTableRow) {
    const auto d = bearing("--eccentricity 0.6 --length-over-diameter 1 --grid 256x65");
    EXPECT_NEAR(num(d, "sommerfeld"), 0.121, 0.01 * 0.121);  // table value to 3 digits: 1%
    EXPECT_NEAR(num(d, "friction_variable"), 3.2, 0.05);    // 3.2 as printed: ±0.05
}

// The three complementarity solvers solve the same discrete problem; JFO (mass-conserving) agrees
// with the Reynolds condition on a steady groove-fed bearing (docs/lube.md §3b).
TEST(CliBearing, SolversAgree) {
    const std::string base = "--eccentricity 0.7 --length-over-diameter 0.8 --grid 64x17 --tolerance 1e-11";
    const auto ref = bearing(base + " --solver active-set");
    const double W = num(ref, "load_n");
    for (const char* s : {"psor", "multigrid", "fast"}) {
        const auto d = bearing(base + " --solver " + s);
        EXPECT_NEAR(num(d, "load_n"), W, 1e-7 * W) << s;
        EXPECT_NEAR(num(d, "attitude_deg"), num(ref, "attitude_deg"), 1e-5) << s;
        EXPECT_NEAR(num(d, "friction_variable"), num(ref, "friction_variable"), 1e-7 * num(ref, "friction_variable")) << s;
        EXPECT_EQ(d.at("input").at("solver"), std::string(s) == "fast" ? "multigrid" : s);
    }
    const auto jfo = bearing(base + " --cavitation jfo");  // active-set method (sparse LU)
    EXPECT_EQ(jfo.at("input").at("solver"), "jfo-active-set");
    EXPECT_NEAR(num(jfo, "load_n"), W, 1e-5 * W);
    EXPECT_NEAR(num(jfo, "flow_variable"), num(ref, "flow_variable"), 1e-5 * num(ref, "flow_variable"));
    const auto sweeps = bearing(base + " --cavitation jfo --solver psor");  // Gauss-Seidel sweeps
    EXPECT_EQ(sweeps.at("input").at("solver"), "jfo-gauss-seidel");
    EXPECT_NEAR(num(sweeps, "load_n"), num(jfo, "load_n"), 1e-7 * W);
    EXPECT_NEAR(num(sweeps, "friction_variable"), num(jfo, "friction_variable"), 1e-7 * num(jfo, "friction_variable"));
    EXPECT_LT(jfo.at("iterations").get<int>(), sweeps.at("iterations").get<int>());
    // Couette shear scales with the film fraction in the cavitated zone: less friction.
    EXPECT_LT(num(jfo, "friction_variable"), num(ref, "friction_variable"));
}

TEST(CliBearing, TableOutput) {
    const CommandResult r = runFlexehd("bearing --eccentricity 0.6 --grid 32x9");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("Sommerfeld number"));
    EXPECT_THAT(r.out, HasSubstr("friction variable"));
    EXPECT_THAT(r.err, HasSubstr("solved:"));  // progress on stderr
    const CommandResult h = runFlexehd("bearing --help");
    EXPECT_EQ(h.status, 0);
    EXPECT_THAT(h.out, HasSubstr("[rev/s]"));
    EXPECT_THAT(h.out, HasSubstr("[Pa s]"));
}

TEST(CliBearing, BadInputFailsClearly) {
    struct Case { const char* args; const char* message; };
    for (const Case& k : {Case{"--eccentricity 1", "--eccentricity must be in (0, 1)"},
                          Case{"--eccentricity 1.2", "--eccentricity must be in (0, 1)"},
                          Case{"--eccentricity 0.5 --viscosity -0.01", "--viscosity must be positive"},
                          Case{"--eccentricity 0.5 --solver gmres", "unknown solver 'gmres'"},
                          Case{"--eccentricity 0.5 --cavitation elrod", "unknown cavitation model 'elrod'"},
                          Case{"--eccentricity 0.5 --grid 64", "expected NTHETAxNZ"},
                          Case{"--eccentricity 0.5 --grid 100000x100000",
                               "--grid 100000x100000: the film grid of 100000 × 100000 = 10000000000 nodes is larger "
                               "than the film solvers can index"},
                          Case{"--eccentricity 0.5 --grid 100000x4000",
                               "--grid 100000x4000: the film grid of 100000 × 4000 = 400000000 nodes needs at least "
                               "200 GB of memory"},
                          Case{"--eccentricity 0.5 --length 0.1 --length-over-diameter 1", "not both"},
                          Case{"--eccentricity 0.5 --length 0", "--length must be positive and finite (got 0)"},
                          Case{"--eccentricity 0.5 --length-over-diameter 0",
                               "--length-over-diameter must be positive and finite (got 0)"},
                          Case{"--eccentricity 0.5 --length 0 --length-over-diameter 1", "not both"},
                          Case{"--eccentricity 0.5 --groove-angle 360", "--groove-angle must be in [0, 360)"},
                          Case{"--eccentricity 0.5 --groove-angle -10", "--groove-angle must be in [0, 360)"},
                          Case{"--eccentricity 0.5 --supply-fraction 0", "--supply-fraction must be in (0, 1]"},
                          Case{"--eccentricity 0.5 --supply-fraction 0.5", "needs --cavitation jfo"},
                          Case{"--eccentricity 0.5 --no-groove --groove-angle 90", "drop --no-groove"}}) {
        const CommandResult r = runFlexehd(std::string("bearing ") + k.args);
        EXPECT_EQ(r.status, 1) << k.args;
        EXPECT_TRUE(r.out.empty()) << k.args;
        EXPECT_THAT(r.err, HasSubstr("flexehd: error: ")) << k.args;
        EXPECT_THAT(r.err, HasSubstr(k.message)) << k.args;
    }
}
