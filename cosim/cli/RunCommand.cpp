// `flexehd run CASE.yaml`: the co-simulation of the piston's secondary motion over the engine
// cycle (docs/coupling.md), writing a results directory (docs/results-format.md): history.csv
// line by line, summary.json, the VTK series of the final cycle and the bodies' mode shapes.
#include <filesystem>
#include <memory>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "cosim/CaseFile.hpp"
#include "cosim/CycleMetrics.hpp"
#include "cosim/FieldSeriesWriter.hpp"
#include "cosim/HistoryWriter.hpp"
#include "cosim/ModeShapeExport.hpp"
#include "cosim/PistonSimulation.hpp"
#include "cosim/cli/CliSupport.hpp"
#include "cosim/cli/Commands.hpp"
#include "fem/AtomicFile.hpp"

#include <fstream>
#include <numbers>

namespace flexehd::cli {
namespace {

struct RunArgs {
    std::string casePath;
    std::string out;
    bool rigid = false;
    int cycles = 0;
    bool json = false;
    bool quiet = false;
};

Eigen::VectorXd pistonDisplacement(const cosim::FlexibleSurface& piston, const cosim::Snapshot& s, double pinOffset,
                                   Eigen::VectorXd& elastic) {
    // Rigid secondary motion about the pin axis (pinOffset, ·, 0): Δx = e + z β, Δz = −(x − c) β.
    const Eigen::Matrix3Xd& X = piston.body().mesh.nodes;
    elastic = piston.displacement(s.pistonModal);
    Eigen::VectorXd u = elastic;
    for (Eigen::Index j = 0; j < X.cols(); ++j) {
        u[3 * j] += s.lateral + X(2, j) * s.tilt;
        u[3 * j + 2] += -(X(0, j) - pinOffset) * s.tilt;
    }
    return u;
}

nlohmann::json summaryJson(const cosim::EngineCase& c, const cosim::PistonSimulation& sim,
                           const std::vector<cosim::StepRecord>& cycle, double outputSeconds, double outputInRun,
                           double totalSeconds,
                           const std::string& status, const std::string& message) {
    nlohmann::json d;
    d["status"] = status;
    if (!message.empty()) d["message"] = message;
    d["case"] = c.path;
    d["name"] = c.name;
    d["bodies"] = {{"piston", c.pistonBody.model == cosim::BodyModel::Flexible ? "flexible" : "rigid"},
                   {"liner", c.linerBody.model == cosim::BodyModel::Flexible ? "flexible" : "rigid"}};
    const auto& st = sim.statistics();
    if (cycle.size() >= 2) {
        const double volume = 0.25 * std::numbers::pi * c.engine.bore * c.engine.bore * c.engine.stroke;
        const cosim::CycleMetrics m = cosim::cycleMetrics(cycle, sim.dynamics(), volume);
        d["cycle"] = cycle.back().cycle;
        d["friction_power_mean_w"] = m.frictionPowerMean;
        d["boundary_friction_power_mean_w"] = m.boundaryFrictionPowerMean;
        d["friction_energy_per_cycle_j"] = m.frictionEnergy;
        d["fmep_pa"] = m.fmep;
        d["slap_kinetic_energy_max_j"] = m.slapEnergyMax;
        d["slap_kinetic_energy_max_crank_deg"] = m.slapEnergyDeg;
        d["lateral_min_m"] = m.lateralMin;
        d["lateral_max_m"] = m.lateralMax;
        d["tilt_min_rad"] = m.tiltMin;
        d["tilt_max_rad"] = m.tiltMax;
        d["min_film_m"] = m.minFilm;
        d["min_film_crank_deg"] = m.minFilmDeg;
        d["max_pressure_pa"] = m.maxPressure;
        d["contact_force_max_n"] = m.contactForceMax;
        d["hard_contact_force_max_n"] = m.hardContactForceMax;
        d["side_force_max_n"] = m.sideForceMax;
    }
    // The undeformed film with the piston centred: the hot running clearance with a thermal file.
    nlohmann::json centred;
    for (const auto& [name, deg] : {std::pair{"tdc", 0.0}, {"mid_stroke", 90.0}, {"bdc", 180.0}}) {
        const cosim::ClearanceRange r = sim.centredClearance(deg);
        centred[name] = {{"min", r.min}, {"mean", r.mean}, {"max", r.max}};
    }
    d["centred_clearance_m"] = centred;
    d["cycles"] = st.cycles;
    d["periodic"] = st.periodic;
    d["periodicity_error_m"] = st.periodicityError;
    d["periodicity_tolerance_m"] = c.time.periodicityTolerance;
    d["iterations"] = {{"steps", st.steps},
                       {"rejected_steps", st.rejectedSteps},
                       {"film_solves", st.filmSolves},
                       {"jacobians", st.jacobians},
                       {"fallback_film_solves", st.fallbackSolves},
                       {"resolved_steps", st.resolvedSteps},
                       {"film_solves_per_step_mean", st.steps > 0 ? double(st.filmSolves) / double(st.steps) : 0.0},
                       {"film_solves_per_step_max", st.maxIterations},
                       {"smallest_step_deg", st.minStepDeg}};
    d["load_mapping_conservation_error_max"] = st.worstMappingError;
    d["timings_s"] = {{"setup", st.timings.setup},
                      {"film", st.timings.film},
                      {"structure", st.timings.structure},
                      {"mapping", st.timings.mapping},
                      {"modal", st.timings.modal},
                      {"dynamics", std::max(0.0, st.timings.dynamics - outputInRun)},
                      {"output", outputSeconds + outputInRun},
                      {"total", totalSeconds}};
    return d;
}

void runCase(const RunArgs& a) {
    const Stopwatch total;
    cosim::EngineCase c = cosim::readCaseFile(a.casePath);
    if (!a.out.empty()) c.output.directory = std::filesystem::absolute(a.out).string();
    if (a.rigid) {
        c.pistonBody.model = cosim::BodyModel::Rigid;
        c.linerBody.model = cosim::BodyModel::Rigid;
    }
    if (a.cycles > 0) c.time.maxCycles = a.cycles;
    const std::string dir = c.output.directory;
    std::filesystem::create_directories(dir);
    auto log = [&](const std::string& s) {
        if (!a.quiet) fmt::print(stderr, "{}\n", s);
    };
    if (const int stale = fem::removeStaleTemporaries(dir))
        log(fmt::format("removed {} unfinished .tmp file(s) that an interrupted run left in {}", stale, dir));
    const bool anyFlexible =
        c.pistonBody.model == cosim::BodyModel::Flexible || c.linerBody.model == cosim::BodyModel::Flexible;
    log(fmt::format("flexehd run {}: piston {}, liner {}{}, grid {} x {}, {} rpm -> {}", c.path,
                    c.pistonBody.model == cosim::BodyModel::Flexible ? "flexible" : "rigid",
                    c.linerBody.model == cosim::BodyModel::Flexible ? "flexible" : "rigid",
                    !anyFlexible ? ""
                    : c.coupling.response == cosim::ElasticResponse::Dynamic ? " (modal dynamics)"
                                                                            : " (quasi-static)",
                    c.grid.axialNodes,
                    c.grid.circumferentialNodes, c.engine.speedRpm, dir));
    cosim::PistonSimulation sim(c);
    if (sim.piston()) {
        log(fmt::format("piston: {} modes from {}", sim.piston()->modes(), c.pistonBody.file));
        const std::size_t outside = sim.piston()->outsideNodes().size();
        const int film = sim.film().grid().filmNodeCount();
        if (2 * outside > std::size_t(film))
            spdlog::warn("{} of the {} skirt film nodes ({:.0f} %) lie outside the surface '{}' of {}: most of the "
                         "skirt does not deform; is {} the piston's reduced body, made from the mesh the case's "
                         "piston geometry describes?",
                         outside, film, 100.0 * double(outside) / film, c.pistonBody.surface, c.pistonBody.file,
                         c.pistonBody.file);
        else if (outside > 0)
            spdlog::warn("{} of the {} skirt film nodes lie outside the surface '{}' of {}: no elastic motion there",
                         outside, film, c.pistonBody.surface, c.pistonBody.file);
    }
    if (sim.liner()) log(fmt::format("liner: {} modes from {}", sim.liner()->modes(), c.linerBody.file));

    double outputSeconds = 0.0;  // all output; outputInRun: the part inside the step loop
    double outputInRun = 0.0;
    cosim::HistoryWriter history(dir + "/history.csv");
    cosim::FieldSeriesWriter fields(dir);
    const auto& g = sim.film().grid();
    cosim::SimulationCallbacks cb;
    cb.onStep = [&](const cosim::StepRecord& r) {
        const Stopwatch w;
        history.append(r);
        outputInRun += w.seconds();
    };
    cb.onSnapshot = [&](const cosim::Snapshot& s) {
        const Stopwatch w;
        cosim::FilmField film;
        film.grid = &g;
        film.origin = Eigen::Vector3d(0.0, 0.0, s.pinHeight);
        film.pressure = s.pressure;
        film.filmThickness = s.filmThickness;
        film.contactPressure = s.contactPressure;
        film.shearStress = s.shearStress;
        film.cavitation = s.cavitation;
        cosim::BodyField piston, liner;
        if (sim.piston()) {
            piston.mesh = &sim.piston()->body().mesh;
            piston.origin = film.origin;
            piston.displacement = pistonDisplacement(*sim.piston(), s, c.engine.pinOffset, piston.elastic);
        }
        if (sim.liner()) {
            liner.mesh = &sim.liner()->body().mesh;
            liner.origin = Eigen::Vector3d(0.0, 0.0, s.pinHeight - s.linerOffset);
            liner.displacement = sim.liner()->displacement(s.linerModal);
        }
        // Time axis: the crank angle of the written cycle, time.start_deg … start_deg + 720 (0–720
        // with the default start), so that it reads as history.csv's crank_deg.
        const cosim::SnapshotTime at{s.continuousDeg - 720.0 * (s.cycle - 1), s.crankDeg, s.cycle};
        fields.write(at, film, sim.piston() ? &piston : nullptr,
                     sim.liner() ? &liner : nullptr);
        outputInRun += w.seconds();
    };
    cb.onCycleEnd = [&](int cycle, int snapshots, bool last) {
        if (snapshots == 0) return;
        const Stopwatch w;
        fields.commit();  // the collections list this cycle from now on
        outputInRun += w.seconds();
        if (last) log(fmt::format("VTK series: the {} snapshots of cycle {} in {}/film.pvd", snapshots, cycle, dir));
    };
    cb.progress = log;
    if (c.output.modeShapes) {
        const Stopwatch w;
        for (const auto* body : {sim.piston(), sim.liner()}) {
            if (!body) continue;
            const std::string sub = dir + (body == sim.piston() ? "/modes_piston" : "/modes_liner");
            std::filesystem::create_directories(sub);
            const Stopwatch one;
            bool reused = false;
            cosim::writeModeShapes(sub, body->body().mesh, body->body().shapes, body->body().frequenciesHz,
                                   Eigen::VectorXd(), &reused);
            log(fmt::format("mode shapes of the {} ({} modes): {} {}", body == sim.piston() ? "piston" : "liner",
                            body->modes(), reused ? "unchanged, kept in" : fmt::format("written in {:.1f} s to", one.seconds()),
                            sub));
        }
        outputSeconds += w.seconds();
    }
    std::vector<cosim::StepRecord> cycle;
    std::string status = "ok", message;
    try {
        cycle = sim.run(cb);
    } catch (const std::exception& e) {
        status = "failed";
        message = e.what();
        fields.discard();  // the unfinished cycle's snapshots; the last complete cycle's stay listed
    }
    if (cycle.empty() && status == "ok") status = "failed";
    const nlohmann::json doc = summaryJson(c, sim, cycle, outputSeconds, outputInRun, total.seconds(), status, message);
    fem::writeAtomically(dir + "/summary.json", [&](const std::string& tmp) {
        std::ofstream f(tmp);
        f << doc.dump(2) << "\n";
        if (!f) throw std::runtime_error("cannot write " + tmp);
    });
    if (status != "ok") throw std::runtime_error(message + " (partial results in " + dir + ")");
    if (a.json) {
        printJson(doc);
    } else if (!a.quiet) {
        fmt::print("lateral {:+.1f} .. {:+.1f} um, tilt {:+.3f} .. {:+.3f} mrad, friction {:.1f} W mean (FMEP {:.3f} kPa), "
                   "min film {:.2f} um, {} cycle{}{} in {:.1f} s\nresults: {}\n",
                   doc.value("lateral_min_m", 0.0) * 1e6, doc.value("lateral_max_m", 0.0) * 1e6,
                   doc.value("tilt_min_rad", 0.0) * 1e3, doc.value("tilt_max_rad", 0.0) * 1e3,
                   doc.value("friction_power_mean_w", 0.0), doc.value("fmep_pa", 0.0) * 1e-3,
                   doc.value("min_film_m", 0.0) * 1e6, sim.statistics().cycles, sim.statistics().cycles == 1 ? "" : "s",
                   sim.statistics().cycles < 2   ? " (periodicity not checked: it needs two cycles)"
                   : sim.statistics().periodic ? " (periodic)"
                                               : " (NOT periodic within the tolerance)",
                   total.seconds(),
                   dir);
    }
}

}  // namespace

void addRunCommand(CLI::App& app) {
    auto a = std::make_shared<RunArgs>();
    CLI::App* cmd = app.add_subcommand("run", "Co-simulate the piston's secondary motion over the engine cycle");
    cmd->add_option("case", a->casePath, "Case file (YAML, docs/case-file.md)")->required()->check(CLI::ExistingFile);
    cmd->add_option("--out", a->out, "Results directory (default: the case's output.directory)");
    cmd->add_flag("--rigid", a->rigid, "Rigid piston and liner (hydrodynamic run), whatever the case says");
    cmd->add_option("--cycles", a->cycles, "Cycles at most (overrides time.max_cycles)")->check(positiveWholeNumber());
    cmd->add_flag("--json", a->json, "Print summary.json on stdout");
    cmd->add_flag("--quiet", a->quiet, "No progress output");
    cmd->callback([a] {
        a->quiet = a->quiet || globalQuiet();
        runCase(*a);
    });
}

}  // namespace flexehd::cli
