// Ring lift in a run (docs/ring-pack.md, "Ring lift in a run"): each ring's axial motion in its
// groove and its groove as a gas volume of its own (ring_gas.ring_lift).
//  - Without gas or friction a ring leaves its lower flank where the piston's deceleration first
//    exceeds gravity (the root of the slider-crank's exact acceleration, found here by bisection)
//    and reaches the upper flank after the free flight under its inertia force (integrated here
//    on a fine grid).
//  - Held on its upper flank, a ring's groove is a dead end open to the land below: its pressure
//    is that land's, and the lands settle where they do without lift (the gaps alone pass gas).
//  - Over a fired cycle with lifts and flutter the pack keeps its gas: what enters from the
//    cylinder is the blow-by plus what the lands and grooves gain, step by step.
//  - In the example's run the top ring sits on its lower flank through the firing, where the gas
//    above it presses it down, and lifts where summary.json says; the flanks' openings add paths
//    to the gaps', so the blow-by rises.
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/run/CaseRun.hpp"
#include "cosim/ringpack/RingPackGas.hpp"
#include "../TestScratch.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

using namespace flexehd::cosim;

namespace {

EngineCase examplePack(bool lift) {
    EngineCase c = readCaseFile(std::string(FLEXEHD_SOURCE_DIR) + "/examples/engine86/hd_rings.yaml");
    c.grid.axialNodes = 24;
    c.grid.circumferentialNodes = 72;
    c.time.maxCycles = 2;
    c.output.vtkEveryDeg = 0.0;
    c.ringGas.model = RingGasModel::Lands;
    c.ringGas.ringLift = lift;
    return c;
}

// The piston pin's height above the crank axis (m) at crank angle θ (rad) and its second
// derivative in time at ω (rad/s) by central differences (exact slider-crank, no pin offset).
double pinHeight(double r, double l, double theta) {
    return r * std::cos(theta) + std::sqrt(l * l - r * r * std::sin(theta) * std::sin(theta));
}
double pinAcceleration(double r, double l, double omega, double theta) {
    const double d = 1e-4;
    return omega * omega * (pinHeight(r, l, theta + d) - 2.0 * pinHeight(r, l, theta) + pinHeight(r, l, theta - d)) / (d * d);
}

std::vector<std::vector<double>> readHistory(const std::filesystem::path& file, std::vector<std::string>& header) {
    std::ifstream csv(file);
    std::string line;
    std::getline(csv, line);
    for (std::stringstream h(line); std::getline(h, line, ',');) header.push_back(line);
    std::vector<std::vector<double>> rows;
    while (std::getline(csv, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::vector<double> row;
        for (std::stringstream f(line); std::getline(f, line, ',');) row.push_back(std::stod(line));
        rows.push_back(row);
    }
    return rows;
}

}  // namespace

TEST(RingLift, WithoutGasARingLeavesItsLowerFlankWhereThePistonDeceleratesPastGravity) {
    EngineCase c = examplePack(true);
    const double r = 0.5 * c.engine.stroke, l = c.engine.rodLength, omega = 3000.0 * std::numbers::pi / 30.0,
                 g = 9.81, p = c.engine.crankcasePressure;
    const double step = 0.05 * std::numbers::pi / 180.0, dt = step / omega;
    auto accel = [&](double theta) { return pinAcceleration(r, l, omega, theta) + g; };
    // From 90° (the piston accelerating up: the rings pressed down) towards TDC at 360°.
    const double root = [&] {
        double lo = 0.6 * std::numbers::pi, hi = 2.0 * std::numbers::pi;  // A > 0 at lo, < 0 at hi
        for (int it = 0; it < 200; ++it) (accel(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
        return 0.5 * (lo + hi);
    }();
    // The free flight from the root: z'' = −A(θ(t)), until z = c, on a fine grid.
    const RingSpec& top = c.rings.front();
    double z = 0.0, v = 0.0, arrival = root;
    for (double theta = root; z < top.groove.sideClearance; theta += step / 1000.0) {
        v += -accel(theta) * dt / 1000.0;
        z += v * dt / 1000.0;
        arrival = theta;
    }
    RingPackGas gas(c);
    double left = -1.0, reached = -1.0;
    for (double theta = 0.5 * std::numbers::pi; theta < 2.0 * std::numbers::pi; theta += step) {
        const std::vector<RingGas>& around = gas.trial(dt, p, accel(theta + step));
        gas.accept();
        if (left < 0.0 && around.front().position > 0.0) left = theta + step;
        if (reached < 0.0 && around.front().position >= top.groove.sideClearance) reached = theta + step;
        for (const RingGas& ring : around) EXPECT_NEAR(ring.above, 0.0, 1e-6 * p);
    }
    const double deg = 180.0 / std::numbers::pi;
    std::printf("top ring at 3000 rpm without gas: leaves its lower flank at %.3f deg (A = 0 at %.3f deg), reaches "
                "the upper one at %.3f deg (free flight %.3f deg)\n",
                left * deg, root * deg, reached * deg, arrival * deg);
    EXPECT_GE(left, root);
    EXPECT_LE(left, root + step * 1.0001);
    EXPECT_NEAR(reached, arrival, 2.0 * step);
}

TEST(RingLift, OnTheUpperFlankTheGrooveHoldsTheGasOfTheLandBelow) {
    const double pc = 20e5, upward = -2e5;  // m/s²: the inertia lifts every ring against the gas
    auto settle = [&](bool lift) {
        RingPackGas gas(examplePack(lift));
        for (int i = 0; i < 200; ++i) {
            gas.trial(1.0, pc, lift ? upward : 0.0);
            gas.accept();
        }
        return std::make_pair(gas.landPressures(), gas.trial(1.0, pc, lift ? upward : 0.0));
    };
    const auto [lands, around] = settle(true);
    const auto [chainLands, chain] = settle(false);
    const EngineCase c = examplePack(true);
    for (std::size_t i = 0; i < around.size(); ++i) {
        EXPECT_DOUBLE_EQ(around[i].position, c.rings[i].groove.sideClearance) << c.rings[i].name;
        EXPECT_NEAR(around[i].behind, around[i].below, 1e-9 * pc) << c.rings[i].name;
    }
    for (std::size_t i = 0; i < lands.size(); ++i) EXPECT_NEAR(lands[i], chainLands[i], 1e-6 * pc);
    std::printf("rings on their upper flanks at 20 bar: grooves %.5g, %.5g, %.5g Pa gauge behind the rings "
                "(lands %.5g, %.5g Pa)\n",
                around[0].behind, around[1].behind, around[2].behind, lands[0], lands[1]);
}

TEST(RingLift, OverAFiredCycleThePackKeepsItsGas) {
    const EngineCase c = examplePack(true);
    RingPackGas gas(c);
    const double r = 0.5 * c.engine.stroke, l = c.engine.rodLength, omega = 1000.0 * std::numbers::pi / 30.0;
    const double degree = 1.0 / (omega * 180.0 / std::numbers::pi), dt = 0.25 * degree;
    double worst = 0.0, throughput = 0.0;
    int departures = 0;
    std::vector<double> before(c.rings.size(), 0.0);
    for (int s = 1; s <= 2 * 4 * 720; ++s) {
        const double deg = std::fmod(0.25 * s, 720.0);
        const double pc = 1e5 + 44e5 * std::exp(-std::pow((deg - 372.0) / 30.0, 2));
        const double m0 = gas.mass();
        const double A = pinAcceleration(r, l, omega, deg * std::numbers::pi / 180.0) + 9.81;
        const std::vector<RingGas>& around = gas.trial(dt, pc, A, {-3.0, -2.0, -4.0});
        gas.accept();
        for (std::size_t i = 0; i < around.size(); ++i) {
            if (before[i] <= 0.0 && around[i].position > 0.0) ++departures;
            before[i] = around[i].position;
        }
        worst = std::max(worst, std::abs(gas.mass() - m0 - dt * (gas.inflow() - gas.blowBy())));
        throughput += dt * std::abs(gas.inflow());
    }
    std::printf("two fired cycles: %d departures from a lower flank, worst step imbalance %.3g kg of %.3g kg in\n",
                departures, worst, throughput);
    EXPECT_GT(departures, 2);
    EXPECT_LT(worst, 1e-9 * throughput);
}

TEST(RingLift, TheTopRingSitsOnItsLowerFlankThroughTheFiringAndTheFlanksAddBlowBy) {
    auto run = [](bool lift, std::vector<std::string>& header, nlohmann::json& summary) {
        const std::filesystem::path dir = flexehd::test::scratchDir();
        EngineCase c = examplePack(lift);
        c.output.directory = dir.string();
        runCase(c, {});
        std::ifstream s(dir / "summary.json");
        summary = nlohmann::json::parse(s);
        return readHistory(dir / "history.csv", header);
    };
    std::vector<std::string> header, plainHeader;
    nlohmann::json summary, plain;
    const auto rows = run(true, header, summary);
    run(false, plainHeader, plain);
    auto index = [&](const std::string& name) {
        const auto at = std::find(header.begin(), header.end(), name);
        EXPECT_NE(at, header.end()) << name;
        return static_cast<std::size_t>(at - header.begin());
    };
    const std::size_t cycle = index("cycle"), crank = index("crank_deg"), top = index("ring_top_axial_position_m");
    std::vector<double> lifts;
    double previous = -1.0;
    for (const auto& row : rows) {
        if (row[cycle] != 2.0) {
            previous = row[top];
            continue;
        }
        if (row[crank] > 340.0 && row[crank] < 420.0) EXPECT_EQ(row[top], 0.0) << "at " << row[crank] << " deg";
        if (previous <= 0.0 && row[top] > 0.0) lifts.push_back(row[crank]);
        previous = row[top];
    }
    const nlohmann::json& ring = summary.at("rings").at("top");
    std::printf("top ring lifts at");
    for (double a : lifts) std::printf(" %.1f", a);
    std::printf(" deg; blow-by %.4g l/min with lift, %.4g without\n", summary["blow_by"]["mean_l_per_min"].get<double>(),
                plain["blow_by"]["mean_l_per_min"].get<double>());
    ASSERT_FALSE(lifts.empty());
    EXPECT_EQ(ring.at("lifts_per_cycle").get<double>(), static_cast<double>(lifts.size()));
    ASSERT_EQ(ring.at("lift_deg").size(), lifts.size());
    for (std::size_t i = 0; i < lifts.size(); ++i) EXPECT_NEAR(ring.at("lift_deg")[i].get<double>(), lifts[i], 1e-9);
    EXPECT_GT(summary["blow_by"]["mean_kg_per_s"].get<double>(), plain["blow_by"]["mean_kg_per_s"].get<double>());
}
