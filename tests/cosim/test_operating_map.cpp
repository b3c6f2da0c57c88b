// flexehd run over the engine's operating map: the small engine of SmallEngineCase (rigid piston
// and liner, 24 × 72 grid, one cycle) at 1000 … 7000 rpm, motored, part and full load. Every
// point must run its cycle; the trends are checked against physics, not against the code's own
// output:
//  * the hydrodynamic friction rises with the sliding speed — the cycle's friction work per
//    cycle (Couette shear ∝ η U / h) grows with speed at every load;
//  * the slap at firing TDC (the peak kinetic energy of the secondary motion between 340° and
//    420°, where the gas force changes the side the rod pushes on) rises with the load where
//    the gas force dominates the net axial force there: peak gas force at least 4 × the TDC
//    inertia force (1 + r/l) m r ω². At higher speed the inertia force, which pulls the piston
//    up at TDC, governs the side-force reversal and more gas force can weaken it (seen here at
//    5500 and 7000 rpm, a real effect, not asserted either way);
//  * the contact share (contact force impulse / side force impulse over the cycle) falls with
//    speed once the film builds up (from the speed of its largest value on, which is not the top
//    speed);
//  * the lateral shift of the pin axis stays within the clearance plus the skirt profile's
//    largest drop plus the worst interference of the step plus the step's largest elastic change
//    of film thickness (flexible piston; nothing else lets the skirt move further);
//  * the contact load split is consistent with the reported gap: a hard-contact force only
//    where the minimum film thickness is negative (the surfaces overlap), never more than the
//    whole contact force.
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/results/CycleMetrics.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "CliRunner.hpp"
#include "SmallEngineCase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>

using namespace flexehd;
using namespace flexehd::cosim;

namespace {

enum class Load { Motored, Part, Full };

// The small engine's pressure trace for a load: motored = compression only (peak 1.6 MPa at
// TDC), part = SmallEngineCase's firing trace (peak 3.5 MPa), full = its pressure above 1 bar
// times 1.6.
EngineCase mapCase(double rpm, Load load) {
    EngineCase c = test::smallCase();
    c.engine.speedRpm = rpm;
    if (load != Load::Part) {
        for (auto& s : c.cylinderPressure) {
            if (load == Load::Full) {
                s.pressure = 1e5 + 1.6 * (s.pressure - 1e5);
            } else {
                const double x = (s.crankDeg - 360.0) / 30.0;
                s.pressure = 1e5 + 1.5e6 * std::exp(-x * x);
            }
        }
    }
    return c;
}

struct Point {
    CycleMetrics metrics;
    double peakGas = 0.0, inertia = 0.0;
    double firingSlap = 0.0;  // J, peak kinetic energy of the secondary motion in 340–420°
    double contactShare = 0.0;  // ∫|contact force| dt / ∫|side force| dt over the cycle
};

using MapPoints = std::map<std::pair<int, Load>, Point>;

// The cycle's metrics, the peak gas force, the reciprocating inertia force m r ω² (1 + λ) and
// the firing slap of one map point.
Point measure(const EngineCase& c, const PistonSimulation& sim, const std::vector<StepRecord>& steps) {
    const double volume = 0.25 * std::numbers::pi * c.engine.bore * c.engine.bore * c.engine.stroke;
    Point p;
    p.metrics = cycleMetrics(steps, sim.dynamics(), volume);
    for (const auto& s : c.cylinderPressure) p.peakGas = std::max(p.peakGas, sim.dynamics().gasForce(s.pressure));
    const double omega = c.engine.speedRpm * std::numbers::pi / 30.0;
    const double crank = 0.5 * c.engine.stroke;
    p.inertia = (c.piston.mass + c.piston.pinMass) * crank * omega * omega * (1.0 + crank / c.engine.rodLength);
    for (const StepRecord& r : steps)
        if (r.crankDeg >= 340.0 && r.crankDeg <= 420.0)
            p.firingSlap = std::max(p.firingSlap, sim.dynamics().kineticEnergy(r.lateralVelocity, r.tiltRate));
    double contact = 0.0, side = 0.0;
    for (std::size_t k = 1; k < steps.size(); ++k) {
        const double dt = steps[k].time - steps[k - 1].time;
        contact += 0.5 * dt * (std::abs(steps[k].contactForce) + std::abs(steps[k - 1].contactForce));
        side += 0.5 * dt * (std::abs(steps[k].sideForce) + std::abs(steps[k - 1].sideForce));
    }
    p.contactShare = contact / side;
    return p;
}

void printPoint(const Point& p, const std::string& load, double rpm) {
    std::printf("  %-7s %5.0f rpm: friction %.3f J, contact share %.4f, firing slap %.3e J, min film %.3f um\n",
                load.c_str(), rpm, p.metrics.frictionEnergy, p.contactShare, p.firingSlap, 1e6 * p.metrics.minFilm);
}

// The lateral shift of the pin axis stays within the clearance plus the skirt profile's largest
// drop plus the step's interference plus its largest elastic change of film thickness: nothing
// else lets the skirt move further.
void expectWithinClearance(const EngineCase& c, const std::vector<StepRecord>& steps, const std::string& point) {
    double largestDrop = 0.0;
    for (const auto& q : c.piston.profile) largestDrop = std::max(largestDrop, q.drop);
    for (const StepRecord& r : steps) {
        const double overlap = std::max(0.0, -r.minFilm);
        EXPECT_LE(std::abs(r.lateral), c.piston.clearance + largestDrop + overlap + r.elasticFilmChange + 1e-9)
            << point << " at " << r.crankDeg << " deg";
    }
}

// The contact share (cycle impulse of the contact force over that of the rod's side force)
// falls with speed where the film builds up: from the speed of its largest value on it falls
// at every step of speed, and that largest value is not at the top speed. Below it, the side
// force (inertia ∝ ω²) can grow faster than the film's capacity, so the share may rise there.
void expectContactShareFallsOnceTheFilmBuildsUp(const MapPoints& map, const std::vector<double>& speeds, Load load,
                                                const std::string& name) {
    std::size_t peak = 0;
    for (std::size_t i = 1; i < speeds.size(); ++i)
        if (map.at(std::pair(int(i), load)).contactShare > map.at(std::pair(int(peak), load)).contactShare) peak = i;
    EXPECT_LT(peak + 1, speeds.size()) << name << " load: the contact share peaks at the top speed";
    for (std::size_t i = peak + 1; i < speeds.size(); ++i) {
        const double before = map.at(std::pair(int(i - 1), load)).contactShare;
        const double now = map.at(std::pair(int(i), load)).contactShare;
        EXPECT_TRUE(now < before || (now == 0.0 && before == 0.0))
            << name << " load: contact share " << now << " at " << speeds[i] << " rpm vs " << before << " at "
            << speeds[i - 1] << " rpm";
    }
}

// Friction work per cycle rises with speed at the load.
void expectFrictionRisesWithSpeed(const MapPoints& map, const std::vector<double>& speeds, Load load,
                                  const std::string& name) {
    for (std::size_t i = 1; i < speeds.size(); ++i)
        EXPECT_GT(map.at(std::pair(int(i), load)).metrics.frictionEnergy,
                  map.at(std::pair(int(i - 1), load)).metrics.frictionEnergy)
            << name << " load: friction work per cycle at " << speeds[i] << " vs " << speeds[i - 1] << " rpm";
}

// Where the gas force dominates the inertia (peak ≥ 4×), the firing slap grows with the load;
// returns the number of speeds checked.
int expectSlapGrowsWithLoad(const MapPoints& map, const std::vector<double>& speeds) {
    int gasDriven = 0;
    for (std::size_t i = 0; i < speeds.size(); ++i) {
        const Point& motored = map.at(std::pair(int(i), Load::Motored));
        const Point& part = map.at(std::pair(int(i), Load::Part));
        const Point& full = map.at(std::pair(int(i), Load::Full));
        if (part.peakGas < 4.0 * part.inertia) continue;
        ++gasDriven;
        EXPECT_GT(part.firingSlap, motored.firingSlap) << speeds[i] << " rpm";
        EXPECT_GT(full.firingSlap, part.firingSlap) << speeds[i] << " rpm";
    }
    return gasDriven;
}

}  // namespace

TEST(OperatingMap, RigidRunsConvergeWithPhysicalTrends) {
    const std::vector<double> speeds{1000, 2500, 4000, 5500, 7000};
    const std::map<Load, std::string> names{{Load::Motored, "motored"}, {Load::Part, "part"}, {Load::Full, "full"}};
    MapPoints map;
    for (const auto& [load, name] : names)
        for (std::size_t i = 0; i < speeds.size(); ++i) {
            const EngineCase c = mapCase(speeds[i], load);
            PistonSimulation sim(c);
            std::vector<StepRecord> steps;
            ASSERT_NO_THROW(steps = sim.run()) << name << " load at " << speeds[i] << " rpm";
            expectWithinClearance(c, steps, name + " " + std::to_string(int(speeds[i])) + " rpm");
            for (const StepRecord& r : steps) {
                if (r.hardContactForce != 0.0) {
                    EXPECT_LT(r.minFilm, 0.0) << name << " " << speeds[i] << " rpm at " << r.crankDeg << " deg";
                }
                EXPECT_LE(std::abs(r.hardContactForce), std::abs(r.contactForce) * (1 + 1e-12) + 1e-12);
            }
            map[std::pair(int(i), load)] = measure(c, sim, steps);
            printPoint(map.at(std::pair(int(i), load)), name, speeds[i]);
        }
    for (const auto& [load, name] : names) {
        expectFrictionRisesWithSpeed(map, speeds, load, name);
        expectContactShareFallsOnceTheFilmBuildsUp(map, speeds, load, name);
    }
    EXPECT_GE(expectSlapGrowsWithLoad(map, speeds), 2);  // the check must have run
}

namespace {
std::string reduceMapPiston(const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    const std::string file = (dir / "piston.h5").string();
    const auto red = test::reduceSmallPiston(file);
    EXPECT_EQ(red.status, 0) << red.err;
    return file;
}
}  // namespace

// The small flexible piston (SmallEngineCase's coarse 12 × 40 grid, 8 modes, coupling.method
// newton, the rigid film thickness's rate in the squeeze term) over the map: each point runs its
// cycle or, where the quasi-static skirt loses its equilibrium in the film (docs/coupling.md §1:
// measured here at 4000 rpm, part and full load), stops with that diagnosis — not the generic
// advice to shorten the step, which cannot help there. Friction work rises with speed over the
// points that run.
TEST(OperatingMap, FlexiblePistonRunsOrNamesTheLostEquilibrium) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("flexehd_map_" + std::to_string(::getpid()));
    const std::string file = reduceMapPiston(dir);
    int lost = 0;
    for (const Load load : {Load::Part, Load::Full}) {
        double previous = 0.0;
        for (const double rpm : {1000.0, 4000.0, 7000.0}) {
            EngineCase c = mapCase(rpm, load);
            c.grid = {12, 40};
            c.pistonBody = test::smallFlexibleCase(file).pistonBody;
            c.coupling.elasticSqueeze = false;
            PistonSimulation sim(c);
            std::vector<StepRecord> steps;
            try {
                steps = sim.run();
            } catch (const std::exception& e) {
                EXPECT_NE(std::string(e.what()).find("quasi-static equilibrium in the film is lost"), std::string::npos)
                    << (load == Load::Part ? "part" : "full") << " load at " << rpm << " rpm: " << e.what();
                ++lost;
                continue;
            }
            const double friction = measure(c, sim, steps).metrics.frictionEnergy;
            EXPECT_GT(friction, previous) << rpm << " rpm";
            previous = friction;
        }
    }
    EXPECT_LT(lost, 6) << "no point of the map ran";
    std::filesystem::remove_all(dir);
}

// The same map with the default model, the elastic deformation rate in the squeeze term
// (coupling.elastic_squeeze): every point runs its cycle; friction work rises with speed at each
// load, and where the gas force dominates the inertia the firing slap grows with the load.
TEST(OperatingMap, FlexiblePistonWithElasticSqueezeRunsConverge) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("flexehd_map_sq_" + std::to_string(::getpid()));
    const std::string file = reduceMapPiston(dir);
    const std::vector<double> speeds{1000, 4000, 7000};
    const std::map<Load, std::string> names{{Load::Motored, "motored"}, {Load::Part, "part"}, {Load::Full, "full"}};
    MapPoints map;
    for (const auto& [load, name] : names) {
        for (std::size_t i = 0; i < speeds.size(); ++i) {
            EngineCase c = mapCase(speeds[i], load);
            c.grid = {12, 40};
            c.pistonBody = test::smallFlexibleCase(file).pistonBody;
            c.coupling.elasticSqueeze = true;
            PistonSimulation sim(c);
            std::vector<StepRecord> steps;
            try {
                steps = sim.run();
            } catch (const std::exception& e) {
                FAIL() << name << " load at " << speeds[i] << " rpm: " << e.what();
            }
            expectWithinClearance(c, steps, name + " " + std::to_string(int(speeds[i])) + " rpm");
            map[std::pair(int(i), load)] = measure(c, sim, steps);
            printPoint(map.at(std::pair(int(i), load)), name, speeds[i]);
        }
        expectFrictionRisesWithSpeed(map, speeds, load, name);
    }
    EXPECT_GE(expectSlapGrowsWithLoad(map, speeds), 1);  // the check must have run
    std::filesystem::remove_all(dir);
}

// The partitioned iteration against the coupled Newton method, an independent solver of the same
// step equations (rigid film rate in the squeeze term, which both support), on the example
// engine's piston (20 modes + skirt correction, 48 × 144 grid) at 3000 rpm through 0–120°: the
// film there stiffens with sliding speed until the motion and the modes pull on each other
// nearly as hard as the structure resists (docs/coupling.md §1). Both run the span; the motion
// agrees to the error the step control admits (time.lateral_tolerance and the tilt tolerance per
// step, 20 × that over the span) and the friction work to 1 %.
TEST(OperatingMap, PartitionedCouplingMatchesNewtonAtHighSpeed) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("flexehd_map_part_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string file = (dir / "piston.h5").string();
    const auto red = test::reduceExamplePiston(file);
    ASSERT_EQ(red.status, 0) << red.err;
    CaseFileOptions options;
    options.checkBodyFiles = false;
    EngineCase c = readCaseFile(std::string(FLEXEHD_SOURCE_DIR) + "/examples/engine86/case.yaml", options);
    c.pistonBody.file = file;
    c.engine.speedRpm = 3000.0;
    c.time.startDeg = 0.0;
    c.coupling.elasticSqueeze = false;
    CycleMetrics m[2];
    for (const int method : {0, 1}) {
        c.coupling.method = method == 0 ? CouplingMethod::Newton : CouplingMethod::Partitioned;
        PistonSimulation sim(c);
        std::vector<StepRecord> steps;
        ASSERT_NO_THROW(steps = sim.run({}, 120.0)) << (method ? "partitioned" : "newton");
        m[method] = cycleMetrics(steps, sim.dynamics(), 1.0);
    }
    const double de = 20.0 * c.time.lateralTolerance, db = 20.0 * c.time.tiltTolerance;
    std::printf("  newton vs partitioned: lateral %.3f..%.3f vs %.3f..%.3f um, tilt %.4f..%.4f vs %.4f..%.4f mrad, "
                "friction %.5g vs %.5g J\n",
                1e6 * m[0].lateralMin, 1e6 * m[0].lateralMax, 1e6 * m[1].lateralMin, 1e6 * m[1].lateralMax,
                1e3 * m[0].tiltMin, 1e3 * m[0].tiltMax, 1e3 * m[1].tiltMin, 1e3 * m[1].tiltMax, m[0].frictionEnergy,
                m[1].frictionEnergy);
    EXPECT_NEAR(m[1].lateralMin, m[0].lateralMin, de);
    EXPECT_NEAR(m[1].lateralMax, m[0].lateralMax, de);
    EXPECT_NEAR(m[1].tiltMin, m[0].tiltMin, db);
    EXPECT_NEAR(m[1].tiltMax, m[0].tiltMax, db);
    EXPECT_NEAR(m[1].frictionEnergy, m[0].frictionEnergy, 0.01 * m[0].frictionEnergy);
    std::filesystem::remove_all(dir);
}

// The mass-conserving film over the map (3 points from 1000 rpm full load to 7000 rpm motored,
// one cycle each), flooded and on a 3 µm liner layer, rigid (24 × 72 grid) and with the small
// flexible piston (12 × 40): every run converges through its cycle, at every point and body the
// starved film, carrying less oil, runs thinner (its minimum film below the flooded one's), and
// the flexible pin axis stays within the clearance bound above. The viscous friction work is
// printed, not asserted: on the smaller wetted area it is lower at 1000 rpm, but from 4000 rpm the
// thinner starved film's shear (∝ η U / h) outweighs the area (measured up to 2.2× the flooded
// work at 7000 rpm, flexible).
TEST(OperatingMap, MassConservingFilmFloodedAndStarvedRunsOverTheMap) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("flexehd_map_mc_" + std::to_string(::getpid()));
    const std::string file = reduceMapPiston(dir);
    const std::vector<std::pair<double, Load>> points{{1000.0, Load::Full}, {4000.0, Load::Part}, {7000.0, Load::Motored}};
    for (const bool flexible : {false, true}) {
        for (const auto& [rpm, load] : points) {
            double minFilm[2] = {0.0, 0.0};
            for (const int starved : {0, 1}) {
                EngineCase c = mapCase(rpm, load);
                c.lubricant.cavitation = CavitationModel::MassConserving;
                if (starved) {
                    c.lubricant.supply.model = OilSupplyModel::LinerLayer;
                    c.lubricant.supply.layer = {{0.0, 3e-6}};
                }
                if (flexible) {
                    c.grid = {12, 40};
                    c.pistonBody = test::smallFlexibleCase(file).pistonBody;
                    c.coupling.maxIterations = CouplingSpec::kFlexiblePasses;  // the reader's default
                }
                const std::string name = std::string(flexible ? "flexible" : "rigid") + (starved ? " starved " : " flooded ") +
                                         std::to_string(int(rpm)) + " rpm";
                PistonSimulation sim(c);
                std::vector<StepRecord> steps;
                try {
                    steps = sim.run();
                } catch (const std::exception& e) {
                    ADD_FAILURE() << name << ": " << e.what();
                    continue;
                }
                if (flexible) expectWithinClearance(c, steps, name);
                double work = 0.0;
                minFilm[starved] = 1.0;
                for (std::size_t k = 1; k < steps.size(); ++k) {
                    const double dt = steps[k].time - steps[k - 1].time;
                    work += dt * (steps[k].dissipatedPower - steps[k].boundaryFrictionPower);
                    minFilm[starved] = std::min(minFilm[starved], steps[k].minFilm);
                }
                std::printf("  %-28s %zu steps, viscous work %.4f J, min film %.3f um\n", name.c_str(), steps.size(), work,
                            1e6 * minFilm[starved]);
            }
            EXPECT_LT(minFilm[1], minFilm[0]) << (flexible ? "flexible " : "rigid ") << rpm << " rpm";
        }
    }
    std::filesystem::remove_all(dir);
}
