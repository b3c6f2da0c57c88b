#include "cosim/run/CaseRun.hpp"
#include "cosim/io/JsonText.hpp"

#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "cosim/contact/SkirtContact.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "cosim/coupling/RunProgress.hpp"
#include "cosim/results/CycleSeries.hpp"
#include "cosim/results/FieldSeriesWriter.hpp"
#include "cosim/results/CycleMetrics.hpp"
#include "cosim/results/HistoryWriter.hpp"
#include "cosim/results/WearMapWriter.hpp"
#include "cosim/run/OutputEstimate.hpp"
#include "cosim/run/StarvedStepTolerance.hpp"
#include "cosim/run/ThermalLandTemperatures.hpp"
#include "cosim/results/ModeShapeExport.hpp"
#include "cosim/results/LinerVibrationReport.hpp"
#include "cosim/results/RunSummary.hpp"
#include "cosim/results/SurfaceVelocityRecorder.hpp"
#include "cosim/wear/SkirtWear.hpp"
#include "fem/AtomicFile.hpp"
#include "fem/Stopwatch.hpp"

namespace flexehd::cosim {
namespace {

void say(const std::function<void(const std::string&)>& f, const std::string& s) {
    if (f) f(s);
}

std::string describe(const EngineCase& c) {
    const bool anyFlexible = c.hasFlexibleBody();
    return fmt::format("flexehd run {}: piston {}, liner {}{}, grid {} x {}, {} rpm -> {}", c.path,
                       c.pistonBody.model == BodyModel::Flexible ? "flexible" : "rigid",
                       c.linerBody.model == BodyModel::Flexible ? "flexible" : "rigid",
                       !anyFlexible                                       ? ""
                       : c.coupling.response == ElasticResponse::Dynamic ? " (modal dynamics)"
                                                                         : " (quasi-static)",
                       c.grid.axialNodes, c.grid.circumferentialNodes, c.engine.speedRpm, c.output.directory);
}

// The bodies the case names, and a warning when the piston's surface misses the skirt's nodes.
void reportBodies(const EngineCase& c, const SkirtContact& skirt, const RunLog& log) {
    if (skirt.piston()) {
        say(log.info, fmt::format("piston: {} modes from {}", skirt.piston()->modes(), c.pistonBody.file));
        const std::size_t outside = skirt.piston()->outsideNodes().size();
        const int film = skirt.film().grid().filmNodeCount();
        if (outside > 0)  // more than FlexibleBodyLoader's share is refused when the body is loaded
            say(log.warn, fmt::format("{} of the {} skirt film nodes lie outside the surface '{}' of {}: no elastic "
                                      "motion there",
                                      outside, film, c.pistonBody.surface, c.pistonBody.file));
    }
    if (skirt.liner()) say(log.info, fmt::format("liner: {} modes from {}", skirt.liner()->modes(), c.linerBody.file));
}

// The piston mesh's displacement at a snapshot: the rigid secondary motion about the pin axis
// (pinOffset, ·, 0), Δx = e + z β, Δz = −(x − c) β, plus the elastic part (also returned).
Eigen::VectorXd pistonDisplacement(const FlexibleSurface& piston, const Snapshot& s, double pinOffset,
                                   Eigen::VectorXd& elastic) {
    const Eigen::Matrix3Xd& X = piston.body().mesh.nodes;
    elastic = piston.displacement(s.pistonModal);
    Eigen::VectorXd u = elastic;
    for (Eigen::Index j = 0; j < X.cols(); ++j) {
        u[3 * j] += s.lateral + X(2, j) * s.tilt;
        u[3 * j + 2] += -(X(0, j) - pinOffset) * s.tilt;
    }
    return u;
}

// A snapshot as the film and body fields of the VTK series.
void writeSnapshot(FieldSeriesWriter& fields, const EngineCase& c, const SkirtContact& skirt, const Snapshot& s) {
    FilmField film;
    film.grid = &skirt.film().grid();
    film.origin = Eigen::Vector3d(0.0, 0.0, s.pinHeight);
    film.pressure = s.pressure;
    film.filmThickness = s.filmThickness;
    film.contactPressure = s.contactPressure;
    film.shearStress = s.shearStress;
    film.cavitation = s.cavitation;
    film.filmFraction = s.filmFraction;
    BodyField piston, liner;
    if (skirt.piston()) {
        piston.mesh = &skirt.piston()->body().mesh;
        piston.origin = film.origin;
        piston.displacement = pistonDisplacement(*skirt.piston(), s, c.engine.pinOffset, piston.elastic);
    }
    if (skirt.liner()) {
        liner.mesh = &skirt.liner()->body().mesh;
        liner.origin = Eigen::Vector3d(0.0, 0.0, s.pinHeight - s.linerOffset);
        liner.displacement = skirt.liner()->displacement(s.linerModal);
    }
    // Time axis: the crank angle of the written cycle, time.start_deg … start_deg + 720 (0–720
    // with the default start), so that it reads as history.csv's crank_deg.
    const SnapshotTime at{s.continuousDeg - 720.0 * (s.cycle - 1), s.crankDeg, s.cycle};
    LinerOilField oil;
    if (s.linerOil.size()) {
        oil.grid = film.grid;
        oil.origin = Eigen::Vector3d(0.0, 0.0, s.pinHeight - s.linerOffset);
        oil.z = &s.linerOilZ;
        oil.thickness = s.linerOil;
    }
    fields.write(at, film, skirt.piston() ? &piston : nullptr, skirt.liner() ? &liner : nullptr,
                 s.linerOil.size() ? &oil : nullptr);
}

// DIR/modes_piston, DIR/modes_liner (unchanged files are kept); returns the seconds taken.
double writeBodyModes(const std::string& dir, const SkirtContact& skirt, const RunLog& log) {
    const fem::Stopwatch w;
    for (const auto* body : {skirt.piston(), skirt.liner()}) {
        if (!body) continue;
        const std::string sub = dir + (body == skirt.piston() ? "/modes_piston" : "/modes_liner");
        std::filesystem::create_directories(sub);
        const fem::Stopwatch one;
        bool reused = false;
        writeModeShapes(sub, body->body().mesh, body->body().shapes, body->body().frequenciesHz, Eigen::VectorXd(),
                        &reused);
        say(log.info, fmt::format("mode shapes of the {} ({} modes): {} {}", body == skirt.piston() ? "piston" : "liner",
                                  body->modes(),
                                  reused ? "unchanged, kept in" : fmt::format("written in {:.1f} s to", one.seconds()),
                                  sub));
    }
    return w.seconds();
}

void writeSummary(const std::string& dir, const nlohmann::json& doc) {
    fem::writeTextAtomically(dir + "/summary.json", jsonText(doc, 2) + "\n");
}

// The thinnest film's region spanned by fewer than 4 grid nodes (a journal bearing's load is then
// 5-35 % low, docs/lube.md section 8): the minimum film and the contact force there depend on the
// grid. A warning naming the grid key to raise.
void warnUnresolvedFilm(const CycleMetrics& m, const RunLog& log) {
    constexpr int kFewestNodes = 4;
    const auto warn = [&](int nodes, double deg, const char* along, const char* key) {
        if (nodes <= 0 || nodes >= kFewestNodes) return;
        say(log.warn, fmt::format("the thinnest film's region (h within max(h_min, sigma) of h_min) is spanned by only "
                                  "{} grid node(s) {} at {:.1f} deg: the minimum film and the contact force there "
                                  "depend on the grid (summary.json min_film_region_nodes; docs/lube.md section 8); "
                                  "raise grid.{}",
                                  nodes, along, deg, key));
    };
    warn(m.minFilmNodesCircumferential, m.minFilmNodesCircumferentialDeg, "around the bore", "circumferential_nodes");
    warn(m.minFilmNodesAxial, m.minFilmNodesAxialDeg, "along the skirt", "axial_nodes");
}

// The run's files as an observer of it: history.csv row by row, the VTK series snapshot by
// snapshot, each cycle's series committed at its end; the seconds they take inside the run.
class RunFiles final : public RunObserver {
public:
    RunFiles(const EngineCase& c, const SkirtContact& skirt, HistoryWriter& history, FieldSeriesWriter& fields,
             const RunLog& log)
        : c_(c), skirt_(skirt), history_(history), fields_(fields), log_(log) {}

    void recorded(const StepRecord& row) override {
        const fem::Stopwatch w;
        history_.append(row);
        seconds_ += w.seconds();
    }
    void snapshotTaken(const Snapshot& s) override {
        const fem::Stopwatch w;
        writeSnapshot(fields_, c_, skirt_, s);
        seconds_ += w.seconds();
    }
    void cycleEnded(const CycleEnd& e) override {
        const fem::Stopwatch w;
        fields_.commit();  // the collections list this cycle from now on (none: an earlier run's series goes)
        seconds_ += w.seconds();
        if (e.snapshots == 0) return;
        if (e.last)
            say(log_.info, fmt::format("VTK series: the {} snapshots of cycle {} in {}/film.pvd", e.snapshots, e.cycle,
                                       c_.output.directory));
    }
    /// Seconds spent writing inside the run.
    double seconds() const { return seconds_; }

private:
    const EngineCase& c_;
    const SkirtContact& skirt_;  // whose film the field series shows
    HistoryWriter& history_;
    FieldSeriesWriter& fields_;
    const RunLog& log_;
    double seconds_ = 0.0;
};

// The names of the contacts' own history columns.
std::vector<std::string> columnNames(const std::vector<ContactColumn>& columns) {
    std::vector<std::string> names;
    for (const ContactColumn& col : columns) names.push_back(col.name);
    return names;
}

// With `acoustics`: the liner's surface velocity recorded each cycle into acoustics.h5.
void recordLinerVibration(const EngineCase& c, PistonSimulation& sim, const std::string& dir, const RunLog& log,
                          std::optional<SurfaceVelocityRecorder>& recorder) {
    const int offset = sim.pistonBody() ? sim.pistonBody()->modes() : 0;
    const FlexibleBody& liner = *sim.linerBody();
    sim.addObserver(recorder.emplace(c, liner.body(), liner.heldInterfaces(), offset, dir + "/acoustics.h5"));
    say(log.info, fmt::format("acoustics: the liner's surface '{}' ({} points, {:.4g} m^2) sampled at {:g} Hz for "
                              "the range up to {:g} Hz; steps of at most {:.4g} deg (time.max_step_deg)",
                              c.acoustics.surface, recorder->areas().size(), recorder->areas().sum(),
                              recorder->sampleRate(), c.acoustics.upToHz, c.time.maxStepDeg));
}

// The case as the run uses it: the lands' gas temperatures from the thermal file where the case
// leaves them to it (its message on the log: info, or a warning when the file has no profile).
EngineCase caseForRun(const EngineCase& given, const RunLog& log) {
    EngineCase c = given;
    if (const auto lands = thermalLandTemperatures(given)) {
        if (lands->temperatures.empty()) {
            say(log.warn, lands->message);
        } else {
            c.ringGas.landTemperatures = lands->temperatures;
            say(log.info, lands->message);
        }
    }
    return c;
}

}  // namespace

CaseRunResult runCase(const EngineCase& given, const RunLog& log, const std::vector<ContactBuilder>& contacts) {
    const fem::Stopwatch total;
    const std::string dir = given.output.directory;
    std::filesystem::create_directories(dir);
    if (const int stale = fem::removeStaleTemporaries(dir))
        say(log.info, fmt::format("removed {} unfinished .tmp file(s) that an interrupted run left in {}", stale, dir));
    say(log.info, describe(given));
    const EngineCase c = caseForRun(given, log);
    PistonSimulation sim(c);
    for (const ContactBuilder& build : contacts) sim.addContact(build(c, sim));
    const SkirtContact& skirt = sim.contact<SkirtContact>();
    checkOutputEstimate(c, sim, dir, log.warn);  // refuses a run whose steps or files cannot fit
    if (const auto loose = looseStarvedStepTolerance(c)) say(log.warn, *loose);
    std::optional<SkirtWear> wear;
    if (SkirtWear::wanted(c)) sim.addObserver(wear.emplace(c, sim));
    std::optional<SurfaceVelocityRecorder> acoustics;
    if (c.acoustics.enabled) recordLinerVibration(c, sim, dir, log, acoustics);
    reportBodies(c, skirt, log);

    HistoryWriter history(dir + "/history.csv", sim.carriesOil(), columnNames(sim.contactColumns()));
    FieldSeriesWriter fields(dir);
    RunFiles files(c, skirt, history, fields, log);
    sim.addObserver(files);
    CycleSeries cycleSeries(c, sim.dynamics());
    sim.addObserver(cycleSeries);
    ProgressPacer pacer(c.time.maxCycles, c.time.startDeg, log.info);  // a line every ~10 s on slow steps too
    sim.addObserver(pacer);
    SimulationCallbacks cb;
    if (log.info) cb.progress = [&](const std::string& line) { pacer.linePrinted(), log.info(line); };
    cb.stopRequested = log.interrupted;
    const double outputSeconds = c.output.modeShapes ? writeBodyModes(dir, skirt, log) : 0.0;

    std::vector<StepRecord> cycle;
    std::string status = "ok", message;
    int signal = 0;
    try {
        cycle = sim.run(cb);
    } catch (const RunInterrupted& e) {
        status = "interrupted";
        message = fmt::format("{}, after {} complete cycle(s); the history holds every accepted step", e.what(),
                              sim.statistics().cycles);
        signal = e.signal();
        fields.discard();
    } catch (const std::exception& e) {
        status = "failed";
        message = e.what();
        fields.discard();  // the unfinished cycle's snapshots; the last complete cycle's stay listed
    }
    if (cycle.empty() && status == "ok") status = "failed";
    if (wear && wear->finished()) {  // the last whole cycle's
        try {
            writeWearMaps(dir, wear->grid(), wear->maps());
        } catch (const std::exception& e) {
            if (status == "ok") status = "failed";
            message += (message.empty() ? "" : "; ") + std::string(e.what());
        }
    }
    std::optional<nlohmann::json> vibration;
    if (acoustics && acoustics->cyclesWritten() > 0) {  // the last complete cycle's record
        try {
            vibration = reportLinerVibration(dir);
        } catch (const std::exception& e) {
            if (status == "ok") status = "failed";
            message += (message.empty() ? "" : "; ") + std::string(e.what());
        }
    }
    CaseRunResult result;
    RunSummaryInput summaryInput{c, sim, cycle, status, message, outputSeconds, files.seconds(), total.seconds(),
                                 wear ? &*wear : nullptr, &cycleSeries};
    summaryInput.acoustics = vibration ? &*vibration : nullptr;
    result.summary = runSummary(summaryInput);
    try {
        writeSummary(dir, result.summary);
    } catch (const std::exception& e) {  // a full disk: say what stopped the run, then that the summary is missing too
        throw std::runtime_error(message.empty() ? std::string(e.what())
                                                 : message + "; and the summary: " + e.what());
    }
    if (cycle.size() >= 2) warnUnresolvedFilm(cycleMetrics(cycle, sim.dynamics(), sweptVolume(c.engine)), log);
    if (signal) throw RunInterrupted(signal, message + " (partial results in " + dir + ", summary.json status: interrupted)");
    if (status != "ok") throw std::runtime_error(message + " (partial results in " + dir + ")");
    result.cycles = sim.statistics().cycles;
    result.periodic = sim.statistics().periodic;
    result.seconds = total.seconds();
    return result;
}

}  // namespace flexehd::cosim
