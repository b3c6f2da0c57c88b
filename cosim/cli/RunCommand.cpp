// `flexehd run CASE.yaml`: the case file with the command line's overrides, run by
// cosim::runCase into its results directory; the cycle figures printed.
#include <csignal>
#include <filesystem>
#include <memory>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "cosim/casefile/CaseFile.hpp"
#include "cosim/cli/CliSupport.hpp"
#include "cosim/cli/Commands.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "cosim/run/CaseRun.hpp"

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

// The case file with the command line's overrides.
cosim::EngineCase caseOf(const RunArgs& a) {
    cosim::CaseFileOptions options;
    options.rigidBodies = a.rigid;
    cosim::EngineCase c = cosim::readCaseFile(a.casePath, options);
    if (!a.out.empty()) c.output.directory = std::filesystem::absolute(a.out).string();
    if (a.cycles > 0) c.time.maxCycles = a.cycles;
    return c;
}

void printResult(const cosim::CaseRunResult& r, const std::string& dir) {
    const nlohmann::json& doc = r.summary;
    fmt::print("lateral {:+.1f} .. {:+.1f} um, tilt {:+.3f} .. {:+.3f} mrad, {}friction {:.1f} W mean (FMEP {:.3f} kPa), "
               "min film {:.2f} um, {} cycle{}{} in {:.1f} s\n",
               doc.value("lateral_min_m", 0.0) * 1e6, doc.value("lateral_max_m", 0.0) * 1e6,
               doc.value("tilt_min_rad", 0.0) * 1e3, doc.value("tilt_max_rad", 0.0) * 1e3,
               doc.contains("rings") ? "skirt " : "", doc.value("friction_power_mean_w", 0.0),
               doc.value("fmep_pa", 0.0) * 1e-3,
               doc.value("min_film_m", 0.0) * 1e6, r.cycles, r.cycles == 1 ? "" : "s",
               r.cycles < 2  ? " (periodicity not checked: it needs two cycles)"
               : r.periodic ? " (periodic)"
                            : " (NOT periodic within the tolerance)",
               r.seconds);
    if (doc.contains("rings")) {  // the ring pack: each ring's friction and the assembly's FMEP
        std::string rings;
        for (const auto& [name, ring] : doc["rings"].items())
            rings += fmt::format("{}{} {:.1f} W", rings.empty() ? "" : ", ", name,
                                 ring.value("friction_power_mean_w", 0.0));
        fmt::print("rings: {} mean; piston assembly FMEP {:.3f} kPa\n", rings, doc.value("fmep_total_pa", 0.0) * 1e-3);
    }
    fmt::print("results: {}\n", dir);
    if (r.cycles >= 2 && !r.periodic && doc.contains("periodicity_error_by_sector")) {  // where the cycles differ
        std::string sectors;
        for (const auto& k : doc["periodicity_error_by_sector"])
            sectors += fmt::format("{}{:g}-{:g} {:.2g}", sectors.empty() ? "" : ", ", k["from_deg"].get<double>(),
                                   k["to_deg"].get<double>(), k["error_m"].get<double>() * 1e6);
        fmt::print("the last two cycles differ by (um, per crank-angle range in deg): {}\n", sectors);
    }
    if (doc.contains("cycle_to_cycle")) {  // not periodic: how much the cycles after the first differ
        const nlohmann::json& cc = doc["cycle_to_cycle"];
        const auto& cycles = cc["cycles"];
        fmt::print("cycles {}-{}: friction {:.1f} +- {:.2g} W (mean +- std), min film {:.2f} .. {:.2f} um, lateral "
                   "{:+.1f} .. {:+.1f} um (cycle_to_cycle in summary.json)\n",
                   cycles.front().get<int>(), cycles.back().get<int>(), cc["friction_power_mean_w"]["mean"].get<double>(),
                   cc["friction_power_mean_w"]["std"].get<double>(), cc["min_film_m"]["min"].get<double>() * 1e6,
                   cc["min_film_m"]["max"].get<double>() * 1e6, cc["lateral_min_m"]["min"].get<double>() * 1e6,
                   cc["lateral_max_m"]["max"].get<double>() * 1e6);
    }
}

// SIGINT or SIGTERM during a run: the run stops before its next step and writes its summary.
volatile std::sig_atomic_t g_signal = 0;
extern "C" void onRunSignal(int signal) { g_signal = signal; }

void runCommand(const RunArgs& a) {
    const cosim::EngineCase c = caseOf(a);
    createOutputFolder(c.output.directory);
    cosim::RunLog log;
    if (!a.quiet) log.info = [](const std::string& s) { fmt::print(stderr, "{}\n", s); };
    log.warn = [](const std::string& s) { spdlog::warn("{}", s); };
    log.interrupted = [] { return static_cast<int>(g_signal); };
    std::signal(SIGINT, onRunSignal);
    std::signal(SIGTERM, onRunSignal);
    cosim::CaseRunResult r;
    try {
        r = cosim::runCase(c, log);
    } catch (const cosim::RunInterrupted& e) {
        fmt::print(stderr, "flexehd: {}\n", e.what());
        setExitCode(128 + e.signal());
        return;
    }
    if (a.json) printJson(r.summary);
    else if (!a.quiet) printResult(r, c.output.directory);
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
        runCommand(*a);
    });
}

}  // namespace flexehd::cli
