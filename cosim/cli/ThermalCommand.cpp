// `flexehd thermal THERMAL.yaml`: temperatures and thermal displacements of piston and liner
// (docs/thermal.md) → DIR/piston.vtu, DIR/liner.vtu (ParaView), DIR/thermal.h5 (read by
// `flexehd run`), DIR/summary.json.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "cosim/thermal/ThermalAnalysis.hpp"
#include "cosim/thermal/ThermalCaseFile.hpp"
#include "cosim/thermal/ThermalResults.hpp"
#include "cosim/cli/CliSupport.hpp"
#include "cosim/cli/Commands.hpp"
#include "fem/AtomicFile.hpp"

namespace flexehd::cli {
namespace {

namespace fs = std::filesystem;

struct ThermalArgs {
    std::string casePath;
    std::string out;
    bool json = false;
};

void runThermal(const ThermalArgs& a) {
    Stopwatch total;
    const cosim::ThermalCase c = cosim::readThermalCaseFile(a.casePath);
    const std::string dir = !a.out.empty() ? a.out : !c.outputDirectory.empty() ? c.outputDirectory : "thermal";
    createOutputFolder(dir);  // before the solves, with the reason in words
    const cosim::ThermalResult r = cosim::runThermalAnalysis(c, [](const std::string& s) { spdlog::info("{}", s); });

    const nlohmann::json doc = cosim::writeThermalResults(dir, a.casePath, c, r, total);
    spdlog::info("wrote {}/thermal.h5, summary.json and the .vtu files", dir);

    if (a.json) {
        printJson(doc);
        return;
    }
    if (r.piston) {
        const auto& p = *r.piston;
        std::printf("piston: T %.1f … %.1f K, skirt radial growth %.1f … %.1f µm (mean %.1f µm)\n",
                    p.temperature.minCoeff(), p.temperature.maxCoeff(), 1e6 * double(doc["piston"]["radial_displacement"]["min_m"]),
                    1e6 * double(doc["piston"]["radial_displacement"]["max_m"]),
                    1e6 * double(doc["piston"]["radial_displacement"]["mean_m"]));
        if (p.calibration) {
            const auto& cal = *p.calibration;
            std::printf("calibration: RMS residual %.2f K (nominal %.2f K), %s\n", cal.rms, cal.initialRms,
                        cal.matched ? "matched" : cal.message.c_str());
            for (std::size_t k = 0; k < c.piston->parameters.size(); ++k)
                std::printf("  %-40s %12.5g%s\n", c.piston->parameters[k].label().c_str(), cal.values(Eigen::Index(k)),
                            cal.atBound[k] ? "  (at bound)" : "");
            std::printf("  %-20s %10s %10s %10s\n", "templug", "measured", "computed", "residual");
            for (std::size_t i = 0; i < c.piston->templugs.size(); ++i)
                std::printf("  %-20s %10.1f %10.1f %+10.2f K\n", c.piston->templugs[i].name.c_str(),
                            c.piston->templugs[i].temperature, cal.computed(Eigen::Index(i)),
                            cal.residuals(Eigen::Index(i)));
        }
    }
    if (r.liner)
        std::printf("liner: T %.1f … %.1f K, bore radial growth %.1f … %.1f µm\n", r.liner->temperature.minCoeff(),
                    r.liner->temperature.maxCoeff(), 1e6 * double(doc["liner"]["radial_displacement"]["min_m"]),
                    1e6 * double(doc["liner"]["radial_displacement"]["max_m"]));
    std::printf("output: %s (thermal.h5, summary.json, .vtu), total %.2f s\n", dir.c_str(), total.seconds());
    if (r.piston && r.piston->calibration && !r.piston->calibration->matched)
        spdlog::warn("calibration: {}", r.piston->calibration->message);
}

}  // namespace

void addThermalCommand(CLI::App& app) {
    auto a = std::make_shared<ThermalArgs>();
    CLI::App* cmd = app.add_subcommand(
        "thermal", "Temperatures and thermal displacements of piston and liner (thermal.h5 for `flexehd run`)");
    cmd->add_option("case", a->casePath, "Thermal case file (YAML, SI units: m, K; docs/thermal.md)")->required();
    cmd->add_option("--out", a->out, "Output directory (default: output.directory of the case, else ./thermal)");
    cmd->add_flag("--json", a->json, "Print one JSON object on stdout (the summary) instead of the text report");
    cmd->callback([a] { runThermal(*a); });
}

}  // namespace flexehd::cli
