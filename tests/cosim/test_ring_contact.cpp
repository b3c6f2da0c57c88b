// A piston ring as a film contact (RingContact, docs/ring-pack.md): in steady sliding its radial
// balance settles on the film of Martin's parabola; at rest on the gap where the asperities alone
// carry its tension; with the cylinder's pressure above and behind the top ring on the gap where
// the asperities and the film of the gas's leakage flow across the face carry tension and gas
// load (both found independently by quadrature and bisection); and what is not built is refused.
#include "cosim/ringpack/RingContact.hpp"
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/run/CaseRun.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "RingCases.hpp"
#include "SmallEngineCase.hpp"
#include "TestFiles.hpp"

using namespace flexehd;
using namespace flexehd::cosim;
using ::testing::HasSubstr;

using test::barrelRing;
using test::ringCase;

namespace {

// Steps of dt at a constant piston velocity and cylinder pressure until the gap settles (its change
// per step below 1e-9 of it); the last iterate.
ContactIterate settle(RingContact& ring, double dt, double velocity, double pressure, double gap, int maxSteps) {
    ContactStep step;
    step.dt = dt;
    step.pistonVelocity = velocity;
    step.cylinderPressure = pressure;
    ContactState now = ring.initialState(0.0);
    now.minGap = gap;
    ContactIterate it;
    WorkTally work;
    for (int k = 0; k < maxSteps; ++k) {
        ring.evaluate(step, now, now, Eigen::Vector2d::Zero(), Eigen::VectorXd(), it, work);
        const double change = std::abs(it.minGap - now.minGap);
        now = ring.accepted(step, now, it);
        if (change <= 1e-9 * now.minGap) break;
    }
    return it;
}

// The asperity load (N/m) of the barrel face at the minimum gap g: Simpson's rule over the face.
double asperityLoad(const lube::GreenwoodTripp& law, double b, double c, double g) {
    const int n = 4000;
    const double dx = b / n;
    double w = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double s = (-0.5 * b + i * dx) / (0.5 * b);
        w += (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0)) * law.pressure(g + c * s * s);
    }
    return w * dx / 3.0;
}

// The load (N/m) of the film through which the gas leaks from p above the face to 0 below it at
// rest: the flow h³/(12η) dp/dx is the same across the face, so p(x) = p ∫₋^x h⁻³ / ∫₋^+ h⁻³.
double leakageFilmLoad(double b, double c, double g, double p) {
    const int n = 20000;
    const double dx = b / n;
    auto h3 = [&](int i) {
        const double s = (-0.5 * b + i * dx) / (0.5 * b);
        const double h = g + c * s * s;
        return 1.0 / (h * h * h);
    };
    std::vector<double> cumulative(n + 1, 0.0);
    for (int i = 1; i <= n; ++i) cumulative[i] = cumulative[i - 1] + 0.5 * (h3(i - 1) + h3(i)) * dx;
    double w = 0.0;
    for (int i = 1; i <= n; ++i) w += 0.5 * (cumulative[i - 1] + cumulative[i]) / cumulative[n] * p * dx;
    return w;
}

}  // namespace

// Martin's parabola (Hamrock, Fundamentals of Fluid Film Lubrication): a flooded face of vertex
// radius R sliding at U carries w' = 4.896 η (U/2) R / h0 per unit length. With the tension T as
// the load the ring settles at h0 = 4.896 η (U/2) R / T.
TEST(RingContact, SteadySlidingSettlesOnMartinsFilm) {
    const EngineCase c = ringCase();
    const double b = 6e-3, crown = 4.5e-3, R = 0.25 * b * b / (2.0 * crown), U = 10.0, h0 = 3e-6;
    const double eta = c.lubricant.viscosity, T = 4.896 * eta * 0.5 * U * R / h0;
    // At h0 = 10 sigma the asperities carry nothing.
    RingContact ring(c, barrelRing(b, crown, T, 0.3e-6), false, 6001);
    // The face spans X = x/sqrt(2 R h0) = +-38.7: the inlet's truncation lowers the load by about
    // 0.25 % (0.6 % at X = -20, 0.03 % at -200: RingFilm's test), the grid (dX = 0.013) by 1e-4.
    const ContactIterate it = settle(ring, 1e-3, -U, 0.0, 1e-6, 3000);
    std::printf("settled minimum film %.6g m (Martin %.6g m), squeeze %.3g m/s, friction %.4g N\n", it.minGap, h0,
                it.dhdt[0], it.action.fz);
    EXPECT_NEAR(it.minGap / h0, 1.0, 4e-3);
    EXPECT_LT(std::abs(it.dhdt[0]), 1e-9);
    EXPECT_GT(it.action.fz, 0.0);  // the piston moves down: the ring's friction pulls it up
    EXPECT_EQ(it.loads.boundaryFrictionPower, 0.0);
    EXPECT_GT(it.loads.viscousDissipation, 0.0);
    EXPECT_EQ(it.action.fx, 0.0);
    EXPECT_EQ(it.action.my, 0.0);
}

TEST(RingContact, AtRestTheAsperitiesCarryTheTensionAndTheTopRingsGasLoad) {
    const EngineCase c = ringCase();
    const double b = 1.15e-3, crown = 8e-6, T = 209.3, sigma = 0.3e-6;
    const lube::GreenwoodTripp law(sigma, c.contact.beta, c.contact.asperityDensity, c.contact.compositeModulus);
    auto balance = [&](double load, double p) {  // the gap where asperities and leakage film carry `load`
        double lo = 1e-10, hi = 10e-6;
        for (int it = 0; it < 100; ++it) {
            const double g = 0.5 * (lo + hi);
            (asperityLoad(law, b, crown, g) + leakageFilmLoad(b, crown, g, p) > load ? lo : hi) = g;
        }
        return 0.5 * (lo + hi);
    };
    RingContact second(c, barrelRing(b, crown, T, sigma), false, 401);
    const double atRest = balance(T, 0.0);
    EXPECT_NEAR(second.restingGap() / atRest, 1.0, 1e-4);
    const ContactIterate rest = settle(second, 1e-2, 0.0, 0.0, 3e-6, 2000);
    std::printf("at rest: settled %.6g m, asperity balance %.6g m\n", rest.minGap, atRest);
    EXPECT_NEAR(rest.minGap / atRest, 1.0, 1e-4);
    EXPECT_LT(std::abs(rest.action.fz), 1e-12);
    // 50 kPa in the cylinder: behind the top ring and above its face; the second ring sees none.
    const double p = 5e4;
    RingContact top(c, barrelRing(b, crown, T, sigma), true, 401);
    const ContactIterate pressed = settle(top, 1e-2, 0.0, p, 3e-6, 2000);
    const double gas = balance(T + p * b, p);
    std::printf("top ring at %.3g Pa: settled %.6g m, balance %.6g m (the second ring %.6g m)\n", p, pressed.minGap,
                gas, settle(second, 1e-2, 0.0, p, 3e-6, 2000).minGap);
    EXPECT_NEAR(pressed.minGap / gas, 1.0, 2e-3);  // the leakage film on 401 nodes against 20000
    EXPECT_LT(pressed.minGap, 0.9 * atRest);
    EXPECT_NEAR(settle(second, 1e-2, 0.0, p, 3e-6, 2000).minGap / atRest, 1.0, 1e-4);
}

// The oil-control ring's two lands share its tension: at rest each carries half of it on its
// asperities, and sliding each carries half on its film.
TEST(RingContact, TheOilControlRingRunsOnItsTwoLands) {
    const EngineCase c = ringCase();
    const double w = 0.4e-3, crown = 4e-6, T = 580.0, sigma = 0.3e-6;
    RingSpec oil = barrelRing(2.43e-3, 0.0, T, sigma);
    oil.kind = RingKind::OilControl;
    oil.lands = OilControlLandsSpec{w, 2.03e-3, crown};
    RingContact ring(c, oil, false, 201);
    RingContact land(c, barrelRing(w, crown, 0.5 * T, sigma), false, 201);  // one land alone, half the tension
    EXPECT_NEAR(ring.restingGap() / land.restingGap(), 1.0, 1e-12);
    const lube::GreenwoodTripp law(sigma, c.contact.beta, c.contact.asperityDensity, c.contact.compositeModulus);
    double lo = -1e-6, hi = 3e-6;  // the gap where the lands' asperities carry T: 2 W(g) = T
    for (int it = 0; it < 100; ++it) (2.0 * asperityLoad(law, w, crown, 0.5 * (lo + hi)) > T ? lo : hi) = 0.5 * (lo + hi);
    EXPECT_NEAR(ring.restingGap() / (0.5 * (lo + hi)), 1.0, 1e-4);
    // The lands' asperities carry at most 2 x 182 N/m at a positive gap: the mean planes overlap.
    EXPECT_LT(ring.restingGap(), 0.0);
    const ContactIterate both = settle(ring, 1e-3, 8.0, 0.0, 1e-6, 400);
    const ContactIterate one = settle(land, 1e-3, 8.0, 0.0, 1e-6, 400);
    EXPECT_NEAR(both.minGap / one.minGap, 1.0, 1e-9);
    EXPECT_NEAR(both.action.fz / one.action.fz, 2.0, 1e-9);
    EXPECT_LT(both.action.fz, 0.0);  // the piston moves up: the friction pulls it down
}

TEST(RingContact, WhatIsNotBuiltIsRefused) {
    const EngineCase c = ringCase();
    EngineCase smooth = c;
    smooth.contact.compositeModulus = 0.0;
    EXPECT_THAT(test::errorOf([&] { RingContact(smooth, barrelRing(1.15e-3, 8e-6, 200.0, 0.2e-6), true); }),
                HasSubstr("composite_modulus"));
    EngineCase flexible = c;  // a flexible piston: the ring acts on its axial equation only
    flexible.pistonBody.model = BodyModel::Flexible;
    EXPECT_NO_THROW(RingContact(flexible, barrelRing(1.15e-3, 8e-6, 200.0, 0.3e-6), true));
    EngineCase soft = c;
    soft.contact.compositeModulus = 1e6;
    EXPECT_THAT(test::errorOf([&] { RingContact(soft, barrelRing(1.15e-3, 8e-6, 200.0, 0.3e-6), true).restingGap(); }),
                HasSubstr("less than its tension"));
}

// The example's HD case with its ring pack, one cycle: each ring's film is thinner at the dead
// centres than at mid-stroke (at a given load the film grows with the sliding speed: Martin), and
// the taper-faced second ring rides on a thicker film on the upstroke than on the downstroke,
// where its lower edge scrapes.
TEST(RingContact, TheExamplePackRunsWithTheExampleEngine) {
    const std::string source = std::string(FLEXEHD_SOURCE_DIR) + "/examples/engine86/";
    const std::filesystem::path dir = test::scratchDir();
    // hd.yaml with the pack: read as the case file reads it, on the example's piston.
    std::ifstream hd(source + "hd.yaml");
    std::stringstream text;
    text << hd.rdbuf() << "\nrings: " << source << "rings.yaml\n";
    test::writeFile(dir / "case.yaml", text.str());
    for (const char* csv : {"cylinder_pressure.csv"})
        std::filesystem::copy_file(source + csv, dir / csv, std::filesystem::copy_options::overwrite_existing);
    EngineCase c = readCaseFile((dir / "case.yaml").string());
    ASSERT_EQ(c.rings.size(), 3u);
    c.output.directory = (dir / "out").string();
    c.output.vtkEveryDeg = 0.0;
    c.time.maxCycles = 1;
    runCase(c, {});
    std::ifstream history(dir / "out" / "history.csv");
    std::string header;
    std::getline(history, header);
    std::map<std::string, int> column;
    {
        std::stringstream h(header);
        std::string name;
        for (int k = 0; std::getline(h, name, ','); ++k) column[name] = k;
    }
    for (const char* ring : {"top", "second", "oil_control"})
        ASSERT_TRUE(column.count(std::string("ring_") + ring + "_min_film_m")) << ring;
    // The film at the crank angle nearest each of these.
    std::map<int, std::map<std::string, double>> at;
    std::map<int, double> nearest;
    std::map<std::string, double> energy;  // J: each ring's friction power over the cycle (trapezoidal)
    double lastTime = 0.0;
    std::map<std::string, double> lastPower;
    bool first = true;
    const int angles[] = {0, 90, 180, 270, 450, 540, 630, 720};
    std::string line;
    while (std::getline(history, line)) {
        if (line.empty() || line[0] == '#') continue;  // the header's comment lines
        std::vector<double> v;
        std::stringstream l(line);
        std::string cell;
        while (std::getline(l, cell, ',')) v.push_back(std::stod(cell));
        const double crank = v[static_cast<std::size_t>(column["crank_deg"])];
        const double time = v[static_cast<std::size_t>(column["time_s"])];
        for (const char* ring : {"top", "second", "oil_control"}) {
            const double power = v[static_cast<std::size_t>(column[std::string("ring_") + ring + "_friction_power_w"])];
            if (!first) energy[ring] += 0.5 * (power + lastPower[ring]) * (time - lastTime);
            lastPower[ring] = power;
        }
        lastTime = time;
        first = false;
        for (int a : angles)
            if (!nearest.count(a) || std::abs(crank - a) < nearest[a]) {
                nearest[a] = std::abs(crank - a);
                for (const char* ring : {"top", "second", "oil_control"})
                    at[a][ring] = v[static_cast<std::size_t>(column[std::string("ring_") + ring + "_min_film_m"])];
            }
    }
    for (const char* ring : {"top", "second", "oil_control"}) {
        std::printf("%-12s min film (um) at 0/90/180/270/450/540/630 deg: %.3g %.3g %.3g %.3g %.3g %.3g %.3g\n", ring,
                    at[0][ring] * 1e6, at[90][ring] * 1e6, at[180][ring] * 1e6, at[270][ring] * 1e6,
                    at[450][ring] * 1e6, at[540][ring] * 1e6, at[630][ring] * 1e6);
        for (int mid : {90, 270, 450, 630})
            for (int dead : {0, 180, 540, 720}) EXPECT_GT(at[mid][ring], at[dead][ring]) << ring << " " << mid << " " << dead;
    }
    // The friction mean effective pressures: each ring's cycle energy over the swept volume, and
    // the assembly's the skirt's and the rings' sum.
    std::ifstream summaryFile(dir / "out" / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(summaryFile);
    const double swept = 0.25 * std::numbers::pi * 0.086 * 0.086 * 0.086;
    double total = summary["fmep_pa"].get<double>();
    for (const char* ring : {"top", "second", "oil_control"}) {
        const double fmep = summary["rings"][ring]["fmep_pa"].get<double>();
        EXPECT_NEAR(fmep, energy[ring] / swept, 1e-6 * fmep) << ring;
        total += fmep;
    }
    std::printf("FMEP: skirt %.0f Pa, assembly %.0f Pa\n", summary["fmep_pa"].get<double>(),
                summary["fmep_total_pa"].get<double>());
    EXPECT_NEAR(summary["fmep_total_pa"].get<double>(), total, 1e-9 * total);
    EXPECT_GT(at[270]["second"], 5.0 * at[90]["second"]);  // upstroke (compression) against downstroke (intake)
    EXPECT_GT(at[630]["second"], 5.0 * at[450]["second"]);
}
