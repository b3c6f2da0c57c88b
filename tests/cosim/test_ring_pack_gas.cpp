// The ring pack's gas in a run (docs/ring-pack.md, "The pack's gas in a run"): the lands' steady
// state at a constant cylinder pressure against the chain of equal gap flows solved by bisection;
// over a fired cycle of the example's pack, the gas the top ring's gap lets in from the cylinder is
// what the last ring's gap lets into the crankcase plus what the lands gain, step by step, from
// the run's history (a rejected step's trial would break it); the second land's pressure peaks
// below the cylinder's and after it; with the gas behind it the second ring is pressed harder; the
// blow-by in summary.json is the last ring's mean gas flow.
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "cosim/ringpack/OrificeFlow.hpp"
#include "cosim/ringpack/RingPackGas.hpp"
#include "cosim/run/CaseRun.hpp"
#include "../TestScratch.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <functional>
#include <string>
#include <vector>

using namespace flexehd::cosim;

namespace {

EngineCase examplePack(bool gas) {
    EngineCase c = readCaseFile(std::string(FLEXEHD_SOURCE_DIR) + "/examples/engine86/hd_rings.yaml");
    c.grid.axialNodes = 24;
    c.grid.circumferentialNodes = 72;
    c.time.maxCycles = 1;
    c.output.vtkEveryDeg = 0.0;
    c.ringGas.model = gas ? RingGasModel::Lands : RingGasModel::None;
    c.ringGas.ringLift = false;  // the lands' chain, every ring on its lower flank (ring lift: test_ring_lift)
    return c;
}

// The root of a decreasing function on [lo, hi] by bisection.
double root(const std::function<double(double)>& f, double lo, double hi) {
    for (int it = 0; it < 200; ++it) {
        const double m = 0.5 * (lo + hi);
        (f(m) > 0.0 ? lo : hi) = m;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

// At a constant cylinder pressure the lands settle where every gap passes the same flow. The
// independent solution: for a trial blow-by q, each land's pressure follows from the gap above it
// (the flow from the pressure above equal to q, by bisection), and q is the flow that lands the
// last gap on the crankcase pressure (bisection on q).
TEST(RingPackGas, TheLandsSettleWhereEveryGapPassesTheSameFlow) {
    const EngineCase c = examplePack(true);
    RingPackGas gas(c);
    const std::vector<double>& cda = gas.gapAreas();
    ASSERT_EQ(cda.size(), 3u);
    ASSERT_EQ(gas.landVolumes().size(), 2u);
    const double pc = 20e5, pk = c.engine.crankcasePressure, T = RingGasSpec::kLandTemperature;
    for (int i = 0; i < 200; ++i) {  // backward Euler: steps of a second, far beyond the lands' time constant
        gas.trial(1.0, pc);
        gas.accept();
    }
    const GasProperties air;
    auto flow = [&](std::size_t i, double up, double down) { return orificeFlow(air, cda[i], up, down, T, T); };
    // The pressure below gap i that passes q from `up`.
    auto below = [&](std::size_t i, double up, double q) {
        return root([&](double d) { return flow(i, up, d) - q; }, 0.0, up);
    };
    const double q = root(
        [&](double q) { return flow(2, below(1, below(0, pc, q), q), pk) - q; }, 0.0, flow(0, pc, pk));
    const double p1 = below(0, pc, q), p2 = below(1, p1, q);
    const std::vector<double> p = gas.landPressures();
    const std::vector<RingGas>& around = gas.trial(1.0, pc);
    std::printf("steady: lands %.6g, %.6g Pa (bisection %.6g, %.6g); gap flows %.6g, %.6g, %.6g kg/s (%.6g)\n", p[0],
                p[1], p1, p2, around[0].flow, around[1].flow, around[2].flow, q);
    EXPECT_NEAR(p[0], p1, 1e-6 * pc);
    EXPECT_NEAR(p[1], p2, 1e-6 * pc);
    for (const RingGas& r : around) EXPECT_NEAR(r.flow, q, 1e-6 * q);
    // What each ring sees: the pressure above it on its face and behind it, the land below it.
    EXPECT_NEAR(around[0].above + pk, pc, 1e-9 * pc);
    EXPECT_NEAR(around[1].behind + pk, p[0], 1e-6 * pc);
    EXPECT_NEAR(around[2].below, 0.0, 1e-9 * pc);
}

// Over a fired cycle: the lands' gas mass per step (p V/(R T) from the history's land pressures)
// changes by the step times the flow in through the top ring's gap less the flow out through the
// last ring's, each at the step's end (backward Euler), to the Newton tolerance.
TEST(RingPackGas, OverAFiredCycleTheLandsKeepTheirGas) {
    const EngineCase c = examplePack(true);
    const RingPackGas geometry(c);
    PistonSimulation sim(c);
    std::vector<std::vector<double>> rows;
    std::vector<std::string> names;
    for (const ContactColumn& col : sim.contactColumns()) names.push_back(col.name);
    auto column = [&](const std::string& name) {
        const auto at = std::find(names.begin(), names.end(), name);
        EXPECT_NE(at, names.end()) << name;
        return static_cast<std::size_t>(at - names.begin());
    };
    const std::size_t p1 = column("ring_top_gas_below_pa"), p2 = column("ring_second_gas_below_pa"),
                      in = column("ring_top_gas_flow_kg_per_s"), out = column("ring_oil_control_gas_flow_kg_per_s");
    const std::vector<StepRecord> r = sim.run();
    ASSERT_GT(r.size(), 100u);
    const double R = GasProperties{}.gasConstant, T = RingGasSpec::kLandTemperature;
    auto mass = [&](const StepRecord& s) {
        return (s.contactValues[p1] * geometry.landVolumes()[0] + s.contactValues[p2] * geometry.landVolumes()[1]) /
               (R * T);
    };
    double worst = 0.0, throughput = 0.0, peakLand = 0.0, peakCylinder = 0.0, landAt = 0.0, cylinderAt = 0.0;
    for (std::size_t i = 1; i < r.size(); ++i) {
        const double dt = r[i].time - r[i - 1].time;
        const double change = mass(r[i]) - mass(r[i - 1]);
        const double net = dt * (r[i].contactValues[in] - r[i].contactValues[out]);
        worst = std::max(worst, std::abs(change - net));
        throughput += dt * std::abs(r[i].contactValues[in]);
        if (r[i].contactValues[p1] > peakLand) peakLand = r[i].contactValues[p1], landAt = r[i].crankDeg;
        if (r[i].cylinderPressure > peakCylinder) peakCylinder = r[i].cylinderPressure, cylinderAt = r[i].crankDeg;
    }
    std::printf("%zu steps: worst step imbalance %.3g kg of %.3g kg through the top ring; second land peak %.4g Pa "
                "at %.1f deg, cylinder %.4g Pa at %.1f deg\n",
                r.size(), worst, throughput, peakLand, landAt, peakCylinder, cylinderAt);
    EXPECT_GT(throughput, 0.0);
    EXPECT_LT(worst, 1e-9 * throughput);
    EXPECT_LT(peakLand, peakCylinder);
    EXPECT_GT(landAt, cylinderAt);
}

// The gas of the second land behind the second ring presses it on the liner: its boundary friction
// over the fired cycle rises against the run without the lands' gas (crankcase pressure behind it).
TEST(RingPackGas, TheSecondLandsGasPressesTheSecondRing) {
    auto boundaryWork = [](bool gas) {
        PistonSimulation sim(examplePack(gas));
        std::vector<std::string> names;
        for (const ContactColumn& col : sim.contactColumns()) names.push_back(col.name);
        const auto k = static_cast<std::size_t>(
            std::find(names.begin(), names.end(), "ring_second_boundary_friction_power_w") - names.begin());
        const std::vector<StepRecord> r = sim.run();
        double work = 0.0;
        for (std::size_t i = 1; i < r.size(); ++i) work += (r[i].time - r[i - 1].time) * r[i].contactValues.at(k);
        return work;
    };
    const double without = boundaryWork(false), with = boundaryWork(true);
    std::printf("second ring's boundary friction work over the cycle: %.4g J without the lands' gas, %.4g J with\n",
                without, with);
    EXPECT_GT(with, without);
}

// summary.json's blow-by is the last ring's gas flow, its mean over the last cycle: checked against
// the trapezoidal mean of history.csv's column over that cycle (the previous cycle's last row
// opening it), in kg/s and in l/min at normal conditions (ρ_n = 101 325 / (287 × 273.15) kg/m³).
TEST(RingPackGas, TheBlowByIsTheLastRingsMeanGasFlow) {
    const std::filesystem::path dir = flexehd::test::scratchDir();
    EngineCase c = examplePack(true);
    c.time.maxCycles = 2;
    c.output.directory = dir.string();
    runCase(c, {});
    std::ifstream csv(dir / "history.csv");
    std::string line;
    std::getline(csv, line);
    std::vector<std::string> header;
    for (std::stringstream h(line); std::getline(h, line, ',');) header.push_back(line);
    auto index = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
    };
    const std::size_t cycle = index("cycle"), time = index("time_s"), flow = index("ring_oil_control_gas_flow_kg_per_s");
    ASSERT_LT(flow, header.size());
    std::vector<std::vector<double>> rows;
    while (std::getline(csv, line)) {
        if (line.empty() || line[0] == '#') continue;  // the file's comment lines
        std::vector<double> row;
        for (std::stringstream f(line); std::getline(f, line, ',');) row.push_back(std::stod(line));
        rows.push_back(row);
    }
    double mass = 0.0, span = 0.0;
    for (std::size_t i = 1; i < rows.size(); ++i)
        if (rows[i][cycle] == 2.0) {
            const double dt = rows[i][time] - rows[i - 1][time];
            mass += 0.5 * (rows[i][flow] + rows[i - 1][flow]) * dt;
            span += dt;
        }
    const double mean = mass / span;
    std::ifstream s(dir / "summary.json");
    const nlohmann::json d = nlohmann::json::parse(s);
    const double blowBy = d.at("blow_by").at("mean_kg_per_s").get<double>();
    std::printf("blow-by %.6g kg/s (history.csv %.6g), %.4g l/min\n", blowBy, mean,
                d.at("blow_by").at("mean_l_per_min").get<double>());
    EXPECT_GT(mean, 0.0);
    EXPECT_NEAR(blowBy, mean, 1e-6 * mean);
    EXPECT_EQ(blowBy, d.at("rings").at("oil_control").at("gas_flow_mean_kg_per_s").get<double>());
    const double normalDensity = 101325.0 / (287.0 * 273.15);
    EXPECT_NEAR(d.at("blow_by").at("mean_l_per_min").get<double>(), mean / normalDensity * 60e3, 1e-6 * 60e3 * mean);
}
