// `flexehd acoustics RESULTS_DIR`: the slap-noise figures of a run's liner vibration record
// (acoustics.h5, docs/acoustics.md §9) → acoustics.json, acoustics.csv, acoustics_spectrum.csv,
// acoustics_map.csv in the same directory.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cosim/cli/CliSupport.hpp"
#include "cosim/cli/Commands.hpp"
#include "cosim/results/LinerVibrationReport.hpp"

namespace flexehd::cli {
namespace {

struct AcousticsArgs {
    std::string dir;
    std::string window = "hann";
    double frameDeg = 60.0;
    bool json = false;
};

void runAcoustics(const AcousticsArgs& a) {
    cosim::LinerVibrationOptions o;
    o.window = a.window == "rectangular" ? acoustics::WindowKind::Rectangular : acoustics::WindowKind::Hann;
    o.frameDeg = a.frameDeg;
    const nlohmann::json doc = cosim::reportLinerVibration(a.dir, o);
    if (a.json) {
        printJson(doc);
        return;
    }
    const nlohmann::json& erp = doc["erp"];
    std::printf("liner surface '%s' (%d points), cycle %d: %d samples at %g Hz, %s window\n",
                doc["record"]["surface"].get<std::string>().c_str(), doc["record"]["points"].get<int>(),
                doc["record"]["cycle"].get<int>(), doc["record"]["samples"].get<int>(),
                doc["record"]["sample_rate_hz"].get<double>(), doc["record"]["window"].get<std::string>().c_str());
    std::printf("equivalent radiated power up to %g Hz: %.4g W (%s dB re 1 pW); rms normal velocity %.4g m/s\n",
                doc["record"]["up_to_hz"].get<double>(), erp["total_w"].get<double>(),
                erp["total_db"].is_null() ? "-inf" : fmt::format("{:.1f}", erp["total_db"].get<double>()).c_str(),
                doc["velocity"]["rms_m_per_s"].get<double>());
    std::printf("strongest engine orders:");
    for (std::size_t k = 0; k < std::min<std::size_t>(3, erp["orders"].size()); ++k)
        std::printf("  %g (%.4g W)", erp["orders"][k]["order"].get<double>(), erp["orders"][k]["erp_w"].get<double>());
    std::printf("\nwrote %s/acoustics.json, acoustics.csv (1/3-octave bands), acoustics_spectrum.csv, acoustics_map.csv\n",
                a.dir.c_str());
}

}  // namespace

void addAcousticsCommand(CLI::App& app) {
    auto a = std::make_shared<AcousticsArgs>();
    CLI::App* cmd = app.add_subcommand(
        "acoustics", "Slap noise of a run's liner vibration record (acoustics.h5): ERP spectrum, 1/3-octave bands, orders");
    cmd->add_option("results", a->dir, "Results directory of a run with the case's `acoustics` section")->required();
    cmd->add_option("--window", a->window, "Spectral window: hann (default) or rectangular")
        ->check(CLI::IsMember({"hann", "rectangular"}));
    cmd->add_option("--frame-deg", a->frameDeg, "Frame length of the crank-angle map [deg] (default 60)")
        ->check(CLI::Range(1.0, 720.0));
    cmd->add_flag("--json", a->json, "Print one JSON object on stdout (acoustics.json) instead of the text report");
    cmd->callback([a] { runAcoustics(*a); });
}

}  // namespace flexehd::cli
