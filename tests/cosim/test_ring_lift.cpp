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
//  - Radial collapse ("Ring collapse in a run"): a ring held on its upper flank, its groove open
//    to the crankcase below, keeps its face on the liner while the cylinder's gas exceeds the
//    crankcase's by less than 2T/b, and leaves it above: its face's opening grows as ½ a t² with
//    a = (the excess's force)/(its mass) and passes the orifice law's flow. In a run at 7000 rpm
//    motored each face opens exactly where the force balance computed from history.csv's own
//    pressure columns says.
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/casefile/PressureTable.hpp"
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
        // Rings with a hundred times their tension: no face leaves the liner (this test is of the
        // grooves; the collapse has its own).
        EngineCase c = examplePack(lift);
        for (RingSpec& r : c.rings) r.tensionPerLength *= 100.0;
        RingPackGas gas(c);
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

TEST(RingCollapse, AFaceLeavesTheLinerWhereTheGasAcrossItExceedsTwiceItsTensionOverItsWidth) {
    // The top ring alone, held on its upper flank by the inertia: its groove is open to the
    // crankcase below, so the gas behind it is the crankcase's.
    EngineCase c = examplePack(true);
    c.rings.resize(1);
    const RingSpec& ring = c.rings.front();
    const double p0 = c.engine.crankcasePressure, dt = 1e-5, upward = -2e5;
    const double threshold = 2.0 * ring.tensionPerLength / ring.height;  // Pa: T/b = ½ (p_c − p_0)
    auto run = [&](double excess, int steps) {
        RingPackGas gas(c);
        for (int i = 0; i < 200; ++i) {  // onto the upper flank, the cylinder at the crankcase's pressure
            gas.trial(dt, p0, upward);
            gas.accept();
        }
        std::vector<RingGas> around;
        for (int i = 0; i < steps; ++i) {
            around = gas.trial(dt, p0 + threshold * (1.0 + excess), upward);
            gas.accept();
        }
        return std::make_pair(around.front(), gas.blowBy());
    };
    const int steps = 200;
    const auto [closed, closedFlow] = run(-0.02, steps);
    EXPECT_DOUBLE_EQ(closed.position, ring.groove.sideClearance);
    EXPECT_EQ(closed.faceOpening, 0.0);
    const auto [open, flow] = run(0.02, steps);
    EXPECT_DOUBLE_EQ(open.position, ring.groove.sideClearance);
    EXPECT_NEAR(open.behind, 0.0, 1e-9 * p0);
    // The excess 0.02 T/b over the face's width b drives the ring's mass per unit circumference.
    const double circumference = std::numbers::pi * c.engine.bore;
    const double a = 0.02 * ring.tensionPerLength / (ring.mass / circumference), t = steps * dt;
    EXPECT_NEAR(open.faceOpening / (0.5 * a * t * t), 1.0, 0.01);
    // Blow-by: the end gap's and the face's flows (orifice law) from the cylinder to the crankcase.
    const double pc = p0 + 1.02 * threshold, cd = c.ringGas.dischargeCoefficient, T = RingGasSpec::kLandTemperature;
    const double gapFlow = orificeFlow(GasProperties{}, cd * ring.closedGap * c.ringGas.landClearance, pc, p0, T, T);
    const double faceFlow = orificeFlow(GasProperties{}, cd * circumference * open.faceOpening, pc, p0, T, T);
    std::printf("top ring on its upper flank: face closed at 0.98 x 2T/b, opened %.4g m after %.0f ms at 1.02 x "
                "(1/2 a t^2 = %.4g m); blow-by %.4g kg/s (gap %.4g, face %.4g)\n",
                open.faceOpening, 1e3 * t, 0.5 * a * t * t, flow, gapFlow, faceFlow);
    const double closedGapFlow = orificeFlow(GasProperties{}, cd * ring.closedGap * c.ringGas.landClearance,
                                             p0 + 0.98 * threshold, p0, T, T);
    EXPECT_NEAR(closedFlow, closedGapFlow, 1e-6 * closedFlow);  // the closed face passes nothing
    EXPECT_NEAR(flow, gapFlow + faceFlow, 1e-6 * flow);
}

TEST(RingCollapse, AtHighSpeedMotoredTheFacesOpenWhereTheirForceBalanceSays) {
    const std::filesystem::path dir = flexehd::test::scratchDir();
    EngineCase c = examplePack(true);
    c.engine.speedRpm = 7000.0;
    c.time.maxCycles = 1;
    c.cylinderPressureFile = std::string(FLEXEHD_SOURCE_DIR) + "/examples/engine86/cylinder_pressure_motored.csv";
    c.cylinderPressure = readPressureTable(c.cylinderPressureFile);
    c.output.directory = dir.string();
    runCase(c, {});
    std::vector<std::string> header;
    const auto rows = readHistory(dir / "history.csv", header);
    auto index = [&](const std::string& name) {
        const auto at = std::find(header.begin(), header.end(), name);
        EXPECT_NE(at, header.end()) << name;
        return static_cast<std::size_t>(at - header.begin());
    };
    std::ifstream s(dir / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(s);
    const std::size_t cylinder = index("cylinder_pressure_pa");
    int opened = 0, checked = 0;
    for (std::size_t i = 0; i < c.rings.size(); ++i) {
        const RingSpec& r = c.rings[i];
        const std::string name = "ring_" + r.name + "_";
        const std::size_t above = i == 0 ? cylinder : index("ring_" + c.rings[i - 1].name + "_gas_below_pa");
        const std::size_t behind = index(name + "gas_behind_pa"), below = index(name + "gas_below_pa");
        const std::size_t opening = index(name + "face_opening_m");
        const double width = r.lands ? 2.0 * r.lands->width : r.height;  // its running faces
        double largest = 0.0;
        for (std::size_t k = 1; k < rows.size(); ++k) {
            largest = std::max(largest, rows[k][opening]);
            if (rows[k - 1][opening] != 0.0) continue;
            // The margin at the step's start: the lands and the groove of the last step, the
            // cylinder of this one's end (docs/ring-pack.md, "Ring collapse in a run").
            const double margin = r.tensionPerLength / width + rows[k - 1][behind] -
                                  0.5 * ((i == 0 ? rows[k] : rows[k - 1])[above] + rows[k - 1][below]);
            if (std::abs(margin) < 1e-4 * r.tensionPerLength / width) continue;  // the file's 9 digits
            ++checked;
            EXPECT_EQ(rows[k][opening] > 0.0, margin < 0.0) << r.name << " at " << rows[k][1] << " deg";
            if (rows[k][opening] > 0.0) ++opened;
        }
        EXPECT_NEAR(summary.at("rings").at(r.name).at("face_opening_max_m").get<double>(), largest, 1e-8 * largest)
            << r.name;  // the file's 9 digits
        EXPECT_LE(largest, r.groove.backClearance) << r.name;
    }
    std::printf("7000 rpm motored: %d face openings over %d steps checked; largest openings top %.3g, second %.3g m\n",
                opened, checked, summary["rings"]["top"]["face_opening_max_m"].get<double>(),
                summary["rings"]["second"]["face_opening_max_m"].get<double>());
    EXPECT_GE(opened, 2);
}
