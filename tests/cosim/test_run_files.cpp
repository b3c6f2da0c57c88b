// What a mass-conserving run with wear maps writes, read back from its files (docs/results-format.md):
// history.csv's oil columns, film.pvd's film fraction, summary.json's oil and wear figures and the
// wear maps. Each file is held against another: the films' oil of every step against the flows
// through their edges and sides (the oil's conservation, docs/coupling.md §6), the summary's oil
// figures against the history's rows, the wear maxima and where they lie against the maps.
#include "cosim/run/CaseRun.hpp"
#include "cosim/results/HistoryWriter.hpp"
#include "cosim/contact/MassConservingFilm.hpp"
#include "SmallEngineCase.hpp"
#include "VtkReadBack.hpp"
#include "../TestScratch.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkStructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

using namespace flexehd;
using namespace flexehd::cosim;
namespace fs = std::filesystem;

namespace {

// The largest value of a map's array, its point's z and its angle from +x towards +y (°, 0–360).
struct MapMaximum {
    double value = -1.0, z = 0.0, thetaDeg = 0.0;
};

MapMaximum mapMaximum(const fs::path& p, const char* array) {
    const auto grid = test::readVts(p);
    vtkDataArray* a = grid->GetPointData()->GetArray(array);
    EXPECT_NE(a, nullptr) << p << " has no " << array;
    MapMaximum m;
    if (!a) return m;
    for (vtkIdType k = 0; k < a->GetNumberOfTuples(); ++k) {
        const double v = a->GetTuple1(k);
        EXPECT_TRUE(std::isfinite(v));
        if (v > m.value) {
            double x[3];
            grid->GetPoint(k, x);
            m = {v, x[2], std::fmod(std::atan2(x[1], x[0]) * 180.0 / std::numbers::pi + 360.0, 360.0)};
        }
    }
    return m;
}

double angleApart(double a, double b) {
    const double d = std::fmod(std::abs(a - b), 360.0);
    return std::min(d, 360.0 - d);
}

}  // namespace

TEST(RunFiles, AStarvedRunWithWearReadsBackConsistentlyFromItsFiles) {
    const fs::path dir = test::scratchDir();
    EngineCase c = test::smallCase();
    c.lubricant.cavitation = CavitationModel::MassConserving;
    c.lubricant.supply.model = OilSupplyModel::LinerLayer;
    c.lubricant.supply.layer = {{0.0, 1e-6}};  // thin: the skirt touches the liner, so it wears
    c.contact.pistonWearCoefficient = 1e-16;
    c.contact.linerWearCoefficient = 2e-16;
    c.output.directory = (dir / "out").string();
    c.output.vtkEveryDeg = 90.0;
    runCase(c, {});
    const fs::path out = dir / "out";

    // history.csv: every step's films' oil changes by the flows through their edges and sides
    // (backward Euler of the content, to the film solver's tolerance of the step's flow and the
    // 9 printed digits). The step's length is read from step_deg (time_s's digits resolve only
    // 1e-9 of the time since the start, 1e-5 of a step).
    const std::vector<StepRecord> r = HistoryWriter::read((out / "history.csv").string());
    ASSERT_GT(r.size(), 100u);
    const double secondsPerDegree = 1.0 / (6.0 * c.engine.speedRpm);
    double worst = 0.0, leaked = 0.0;
    for (std::size_t i = 1; i < r.size(); ++i) {
        const double dt = r[i].stepDeg * secondsPerDegree;
        const double flow = dt * (r[i].oilIn + r[i].oilOut);
        const double change = r[i].filmOil - r[i - 1].filmOil;
        const double net = dt * (r[i].oilIn - r[i].oilOut - r[i].sideLeakage);
        worst = std::max(worst, std::abs(change - net) / (10.0 * MassConservingFilm::kTolerance * flow +
                                                          2e-9 * std::max(r[i].filmOil, r[i - 1].filmOil)));
        leaked += (r[i].time - r[i - 1].time) * r[i].sideLeakage;  // as the summary sums it
        EXPECT_GE(r[i].wettedShare, 0.0);
        EXPECT_LE(r[i].wettedShare, 1.0);
        EXPECT_GT(r[i].linerOil, 0.0);
    }
    EXPECT_LT(worst, 1.0);

    // summary.json: the oil figures are the history's last cycle's.
    std::ifstream s(out / "summary.json");
    const nlohmann::json d = nlohmann::json::parse(s);
    const nlohmann::json& oil = d.at("oil");
    const StepRecord &a = r.front(), &b = r.back();
    EXPECT_NEAR(oil.at("film_volume_m3").get<double>(), b.filmOil, 1e-8 * b.filmOil);
    EXPECT_NEAR(oil.at("liner_volume_m3").get<double>(), b.linerOil, 1e-8 * b.linerOil);
    EXPECT_NEAR(oil.at("replenished_per_cycle_m3").get<double>(), b.replenishedOil - a.replenishedOil,
                1e-8 * std::abs(b.replenishedOil) + 1e-20);
    EXPECT_NEAR(oil.at("side_leakage_per_cycle_m3").get<double>(), leaked, 1e-6 * std::abs(leaked) + 1e-20);
    const double start = a.linerOil + a.filmOil, end = b.linerOil + b.filmOil;
    EXPECT_NEAR(oil.at("periodicity_error").get<double>(), std::abs(end - start) / end, 1e-6);

    // film.pvd: every snapshot has the film fraction in [0, 1], and the cavitation fraction is its
    // complement wherever the film is cavitated.
    const std::vector<test::PvdEntry> snaps = test::readPvd(out / "film.pvd");
    ASSERT_GE(snaps.size(), 4u);
    int cavitated = 0;
    for (const test::PvdEntry& f : snaps) {
        const auto grid = test::readVts(out / f.file);
        vtkDataArray* phi = grid->GetPointData()->GetArray("film_fraction");
        vtkDataArray* cav = grid->GetPointData()->GetArray("cavitation_fraction");
        ASSERT_NE(phi, nullptr) << f.file;
        ASSERT_NE(cav, nullptr) << f.file;
        ASSERT_EQ(phi->GetNumberOfTuples(), cav->GetNumberOfTuples());
        for (vtkIdType k = 0; k < phi->GetNumberOfTuples(); ++k) {
            const double p = phi->GetTuple1(k), q = cav->GetTuple1(k);
            EXPECT_GE(p, 0.0);
            EXPECT_LE(p, 1.0);
            if (q > 0.0) {
                ++cavitated;
                EXPECT_NEAR(p + q, 1.0, 1e-6) << f.file << " point " << k;
            }
        }
    }
    EXPECT_GT(cavitated, 0);

    // The wear maps: the summary's largest rates and where they lie are the maps'.
    const nlohmann::json& wear = d.at("wear");
    const MapMaximum piston = mapMaximum(out / "wear_piston.vts", "wear_rate_m_per_h");
    const MapMaximum liner = mapMaximum(out / "wear_liner.vts", "wear_rate_m_per_h");
    ASSERT_GT(piston.value, 0.0);
    ASSERT_GT(liner.value, 0.0);
    EXPECT_NEAR(wear.at("piston_rate_max_m_per_h").get<double>(), piston.value, 1e-6 * piston.value);
    EXPECT_NEAR(wear.at("piston_max_z_m").get<double>(), piston.z, 1e-9);
    EXPECT_LT(angleApart(wear.at("piston_max_theta_deg").get<double>(), piston.thetaDeg), 1e-4);
    EXPECT_NEAR(wear.at("liner_rate_max_m_per_h").get<double>(), liner.value, 1e-6 * liner.value);
    EXPECT_NEAR(wear.at("liner_max_depth_m").get<double>(), -liner.z, 1e-9);
    EXPECT_LT(angleApart(wear.at("liner_max_theta_deg").get<double>(), liner.thetaDeg), 1e-4);
}

// A run that does not become periodic reports how its cycles after the first differ: each cycle
// figure's mean, least, largest value and standard deviation. Checked against the cycles' mean
// friction power and least film thickness recomputed from history.csv (the trapezoidal rule over
// each cycle's rows, the previous cycle's last row opening it).
TEST(RunFiles, ANonPeriodicRunReportsItsCyclesMeanAndSpread) {
    const fs::path dir = test::scratchDir();
    EngineCase c = test::smallCase();
    c.time.maxCycles = 3;
    c.time.periodicityTolerance = 1e-15;  // m: no run meets it
    c.output.directory = (dir / "out").string();
    c.output.vtkEveryDeg = 0.0;
    runCase(c, {});
    const std::vector<StepRecord> r = HistoryWriter::read((dir / "out" / "history.csv").string());
    std::ifstream s(dir / "out" / "summary.json");
    const nlohmann::json d = nlohmann::json::parse(s);
    ASSERT_FALSE(d.at("periodic").get<bool>());
    ASSERT_TRUE(d.contains("cycle_to_cycle"));
    const nlohmann::json& cc = d.at("cycle_to_cycle");
    EXPECT_EQ(cc.at("cycles"), nlohmann::json::array({2, 3}));

    std::vector<double> power, film;
    for (int cycle = 2; cycle <= 3; ++cycle) {
        std::vector<const StepRecord*> rows;
        for (std::size_t i = 0; i < r.size(); ++i)
            if (r[i].cycle == cycle) {
                if (rows.empty()) rows.push_back(&r[i - 1]);  // the previous cycle's last state
                rows.push_back(&r[i]);
            }
        double energy = 0.0, least = rows.front()->minFilm;
        for (std::size_t i = 1; i < rows.size(); ++i) {
            energy += 0.5 * (rows[i]->dissipatedPower + rows[i - 1]->dissipatedPower) * (rows[i]->time - rows[i - 1]->time);
            least = std::min(least, rows[i]->minFilm);
        }
        power.push_back(energy / (rows.back()->time - rows.front()->time));
        film.push_back(least);
    }
    const double mean = 0.5 * (power[0] + power[1]), spread = 0.5 * std::abs(power[0] - power[1]);
    const nlohmann::json& p = cc.at("friction_power_mean_w");
    std::printf("friction power of cycles 2, 3: %.9g, %.9g W; summary mean %.9g std %.3g\n", power[0], power[1],
                p.at("mean").get<double>(), p.at("std").get<double>());
    EXPECT_NEAR(p.at("mean").get<double>(), mean, 1e-7 * mean);
    EXPECT_NEAR(p.at("min").get<double>(), std::min(power[0], power[1]), 1e-7 * mean);
    EXPECT_NEAR(p.at("max").get<double>(), std::max(power[0], power[1]), 1e-7 * mean);
    EXPECT_NEAR(p.at("std").get<double>(), spread, 1e-7 * mean);
    EXPECT_NEAR(cc.at("min_film_m").at("min").get<double>(), std::min(film[0], film[1]), 1e-8 * std::abs(film[0]));
    EXPECT_NEAR(cc.at("min_film_m").at("max").get<double>(), std::max(film[0], film[1]), 1e-8 * std::abs(film[0]));
    // The last cycle's figures stay where they were.
    EXPECT_NEAR(d.at("friction_power_mean_w").get<double>(), power[1], 1e-7 * mean);

    // Where the cycles differ: |Δe| + |Δβ| reach of cycle 3 against cycle 2 at the same crank
    // angle (cycle 2 interpolated linearly between its rows), the largest per 60° of crank angle,
    // and their largest the periodicity error.
    auto cycleRows = [&](int cycle, std::vector<double>& at, std::vector<const StepRecord*>& rows) {
        for (std::size_t i = 0; i < r.size(); ++i)
            if (r[i].cycle == cycle) {
                if (rows.empty()) rows.push_back(&r[i - 1]), at.push_back(0.0);  // the opening state
                rows.push_back(&r[i]);
                at.push_back(r[i].crankDeg - c.time.startDeg);
            }
    };
    std::vector<double> at2, at3;
    std::vector<const StepRecord*> rows2, rows3;
    cycleRows(2, at2, rows2);
    cycleRows(3, at3, rows3);
    const double reach = std::max(c.piston.skirtTop, -c.piston.skirtBottom);
    std::vector<double> sector(12, 0.0);
    for (std::size_t i = 0; i < rows3.size(); ++i) {
        const auto hi = std::upper_bound(at2.begin(), at2.end(), at3[i]);
        const std::size_t b = std::min<std::size_t>(hi - at2.begin(), at2.size() - 1), a = b > 0 ? b - 1 : 0;
        const double w = at2[b] > at2[a] ? std::clamp((at3[i] - at2[a]) / (at2[b] - at2[a]), 0.0, 1.0) : 0.0;
        const double e = rows2[a]->lateral + w * (rows2[b]->lateral - rows2[a]->lateral);
        const double t = rows2[a]->tilt + w * (rows2[b]->tilt - rows2[a]->tilt);
        const double crank = std::fmod(c.time.startDeg + at3[i], 720.0);
        double& s = sector[std::min<std::size_t>(11, static_cast<std::size_t>(crank / 60.0))];
        s = std::max(s, std::abs(rows3[i]->lateral - e) + std::abs(rows3[i]->tilt - t) * reach);
    }
    const nlohmann::json& bySector = d.at("periodicity_error_by_sector");
    ASSERT_EQ(bySector.size(), 12u);
    double largest = 0.0;
    for (std::size_t k = 0; k < 12; ++k) {
        EXPECT_EQ(bySector[k].at("from_deg").get<double>(), 60.0 * double(k));
        EXPECT_EQ(bySector[k].at("to_deg").get<double>(), 60.0 * double(k + 1));
        const double reported = bySector[k].at("error_m").get<double>();
        std::printf("  %3zu-%3zu deg: %.4g um (from history.csv %.4g um)\n", 60 * k, 60 * (k + 1), reported * 1e6,
                    sector[k] * 1e6);
        EXPECT_NEAR(reported, sector[k], 1e-6 * sector[k] + 1e-12);
        largest = std::max(largest, reported);
    }
    EXPECT_GT(largest, 0.0);
    EXPECT_EQ(largest, d.at("periodicity_error_m").get<double>());
}
