// `flexehd modes`: natural frequencies and mode shapes of an elastic body, written for
// ParaView (one .vtu per mode, a .pvd whose time steps are the mode numbers).
#include <cstdio>
#include <memory>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "cosim/coupling/MemoryBudget.hpp"
#include "cosim/results/ModeShapeExport.hpp"
#include "cosim/cli/CliSupport.hpp"
#include "cosim/cli/Commands.hpp"
#include "fem/MeshReader.hpp"
#include "fem/ModalAnalysis.hpp"

namespace flexehd::cli {
namespace {

struct ModesArgs {
    MeshArguments mesh;
    fem::ElasticMaterial material;
    std::vector<std::string> fix;
    int count = 12;
    double shift = 0.0;
    std::string out;
    bool json = false;
};

void runModes(const ModesArgs& a) {
    Stopwatch total;
    spdlog::info("reading mesh {}", a.mesh.path);
    Stopwatch t;
    const fem::Mesh mesh = fem::readMesh(a.mesh.path, a.mesh.options);
    const double readSeconds = t.seconds();
    spdlog::info("mesh: {} nodes, {} {} elements ({:.2f} s)", mesh.numNodes(), mesh.volume.size(),
                 fem::name(mesh.volume.type), readSeconds);

    std::vector<fem::FixedGroup> fixed;
    for (const auto& s : a.fix) {
        fixed.push_back(fem::parseFixedGroup(s));
        mesh.group(fixed.back().group);  // unknown group: error listing the available ones
    }
    fem::EigenmodeOptions opt;
    opt.count = a.count;
    opt.shift = a.shift;
    const Eigen::Index dofs = 3 * Eigen::Index(mesh.numNodes());
    const double basisBytes = 8.0 * double(dofs) * double(fem::lanczosBasisSize(dofs, a.count));
    if (const std::uint64_t avail = cosim::availableMemoryBytes(); avail > 0 && 2.0 * basisBytes > double(avail))
        throw std::runtime_error(fmt::format(
            "--count {}: the Lanczos basis for {} modes of {} DOFs needs at least {} of memory (twice {} vectors of "
            "{} values); {} are available: ask for fewer modes",
            a.count, a.count, dofs, cosim::formatBytes(2.0 * basisBytes), fem::lanczosBasisSize(dofs, a.count), dofs,
            cosim::formatBytes(double(avail))));
    if (!a.out.empty()) createOutputFolder(a.out);  // before the solve, with the reason in words
    spdlog::info("assembling and solving for {} modes ({} DOFs, Lanczos basis {} vectors, {})", a.count, dofs,
                 fem::lanczosBasisSize(dofs, a.count), cosim::formatBytes(basisBytes));
    opt.progress = [](int solves, double seconds) {
        spdlog::info("  Lanczos: {} solves, {:.0f} s so far", solves, seconds);
    };
    const fem::ModalAnalysis result = fem::analyseModes(mesh, a.material, fixed, opt);
    spdlog::info("assembly {:.2f} s, factorization {:.2f} s, Lanczos {:.2f} s ({} restarts, {} solves)",
                 result.assembleSeconds, result.modes.factorSeconds, result.modes.solveSeconds,
                 result.modes.iterations, result.modes.operations);

    nlohmann::json files = nlohmann::json::array();
    double writeSeconds = 0.0;
    if (!a.out.empty()) {
        Stopwatch w;
        for (const auto& name : cosim::writeModeShapes(a.out, mesh, result.modes.shapes,
                                                       result.frequenciesHz(), result.modes.eigenvalues))
            files.push_back(name);
        spdlog::info("wrote {} mode shapes and {}/modes.pvd", result.modes.shapes.cols(), a.out);
        writeSeconds = w.seconds();
    }

    const Eigen::VectorXd f = result.frequenciesHz();
    const int rigid = result.rigidBodyModes();
    if (a.json) {
        nlohmann::json doc;
        doc["mesh"] = a.mesh.path;
        doc["element_type"] = std::string(fem::name(mesh.volume.type));
        doc["nodes"] = mesh.numNodes();
        doc["elements"] = mesh.volume.size();
        doc["dofs"] = result.dofs;
        doc["free_dofs"] = result.freeDofs;
        doc["material"] = {{"E_pa", a.material.E}, {"nu", a.material.nu}, {"rho_kg_m3", a.material.rho}};
        doc["fixed"] = a.fix;
        doc["frequencies_hz"] = std::vector<double>(f.data(), f.data() + f.size());
        doc["eigenvalues_rad2_s2"] =
            std::vector<double>(result.modes.eigenvalues.data(), result.modes.eigenvalues.data() + f.size());
        doc["rigid_body_modes"] = rigid;
        doc["shift_rad2_s2"] = result.modes.shift;
        doc["lanczos_restarts"] = result.modes.iterations;
        doc["timings_s"] = {{"read_mesh", readSeconds},
                            {"assemble", result.assembleSeconds},
                            {"factorize", result.modes.factorSeconds},
                            {"eigensolve", result.modes.solveSeconds},
                            {"write", writeSeconds},
                            {"total", total.seconds()}};
        doc["peak_memory_mib"] = peakMemoryMiB();
        if (!a.out.empty()) doc["output"] = {{"directory", a.out}, {"files", files}};
        printJson(doc);
    } else {
        std::printf("%s: %d nodes, %d %s elements, %d DOFs (%d free)\n", a.mesh.path.c_str(), int(mesh.numNodes()),
                    int(mesh.volume.size()), std::string(fem::name(mesh.volume.type)).c_str(), int(result.dofs),
                    int(result.freeDofs));
        std::printf("%6s  %16s\n", "mode", "frequency [Hz]");
        for (Eigen::Index k = 0; k < f.size(); ++k)
            std::printf("%6d  %16.6g%s\n", int(k + 1), f(k), k < rigid ? "  (rigid-body)" : "");
        std::printf("total time %.2f s, peak memory %.0f MiB\n", total.seconds(), peakMemoryMiB());
    }
}

}  // namespace

void addModesCommand(CLI::App& app) {
    auto a = std::make_shared<ModesArgs>();
    a->material = {0.0, 0.0, 0.0};
    CLI::App* cmd = app.add_subcommand("modes", "Natural frequencies and mode shapes of an elastic body");
    addMeshOptions(cmd, a->mesh);
    addMaterialOptions(cmd, a->material);
    cmd->add_option("--fix", a->fix,
                    "Physical group to hold, all components (GROUP) or some (GROUP:xy); repeatable. "
                    "None: free body, six rigid-body modes included");
    cmd->add_option("--count", a->count, "Number of modes, lowest first")->check(wholeNumberFromTo(1, 10000));
    cmd->add_option("--shift", a->shift,
                    "Spectral shift sigma [(rad/s)^2], below the lowest eigenvalue (default: automatic)");
    cmd->add_option("--out", a->out, "Directory for mode_NNN.vtu and modes.pvd (ParaView)");
    cmd->add_flag("--json", a->json, "Print one JSON object on stdout instead of the table");
    cmd->callback([a] { runModes(*a); });
}

}  // namespace flexehd::cli
