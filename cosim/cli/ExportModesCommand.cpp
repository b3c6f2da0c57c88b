// `flexehd export-modes FILE.h5 --out DIR`: the mode shapes of a reduced body as ParaView
// files (DIR/mode_NNN.vtu, DIR/modes.pvd), the same files as `flexehd modes --out`.
#include <cstdio>
#include <memory>

#include <spdlog/spdlog.h>

#include "cosim/results/ModeShapeExport.hpp"
#include "cosim/cli/CliSupport.hpp"
#include "cosim/cli/Commands.hpp"
#include "modal/ReducedBodyFile.hpp"

namespace flexehd::cli {
namespace {

struct ExportModesArgs {
    std::string file;
    std::string out;
    bool json = false;
};

void runExportModes(const ExportModesArgs& a) {
    Stopwatch total;
    spdlog::info("reading {}", a.file);
    const modal::ReducedBody body = modal::readReducedBody(a.file);
    const double readSeconds = total.seconds();

    createOutputFolder(a.out);
    Stopwatch w;
    // K_r is diag(ω²) for an orthonormalised basis, so its diagonal is the eigenvalue.
    const Eigen::VectorXd eigenvalues = body.stiffnessMatrix.diagonal();
    const std::vector<std::string> files =
        cosim::writeModeShapes(a.out, body.mesh, body.shapes, body.frequenciesHz, eigenvalues);
    const double writeSeconds = w.seconds();
    spdlog::info("wrote {} mode shapes and {}/modes.pvd ({:.2f} s)", body.numModes(), a.out, writeSeconds);

    if (a.json) {
        nlohmann::json doc;
        doc["file"] = a.file;
        doc["modes"] = body.numModes();
        doc["frequencies_hz"] = std::vector<double>(body.frequenciesHz.data(),
                                                    body.frequenciesHz.data() + body.frequenciesHz.size());
        doc["output"] = {{"directory", a.out}, {"files", files}};
        doc["timings_s"] = {{"read", readSeconds}, {"write", writeSeconds}, {"total", total.seconds()}};
        printJson(doc);
    } else {
        std::printf("%s: %d mode shapes written to %s (open modes.pvd in ParaView)\n", a.file.c_str(),
                    body.numModes(), a.out.c_str());
    }
}

}  // namespace

void addExportModesCommand(CLI::App& app) {
    auto a = std::make_shared<ExportModesArgs>();
    CLI::App* cmd = app.add_subcommand("export-modes", "Mode shapes of a reduced-body file as ParaView files");
    cmd->add_option("file", a->file, "Reduced-body file written by flexehd reduce")->required();
    cmd->add_option("--out", a->out, "Directory for mode_NNN.vtu and modes.pvd")->required();
    cmd->add_flag("--json", a->json, "Print one JSON object on stdout instead of the message");
    cmd->callback([a] { runExportModes(*a); });
}

}  // namespace flexehd::cli
