// `flexehd reduce`: Craig–Bampton reduced body of a mesh, written as an HDF5 file
// (docs/reduced-body-format.md) for the co-simulation.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include "cosim/cli/CliSupport.hpp"
#include "cosim/cli/Commands.hpp"
#include "cosim/coupling/MemoryBudget.hpp"
#include "fem/MeshReader.hpp"
#include "modal/CraigBamptonReducer.hpp"
#include "modal/ModalDamping.hpp"
#include "modal/ModalSuperposition.hpp"
#include "modal/ReducedBodyFile.hpp"

namespace flexehd::cli {
namespace {

struct ReduceArgs {
    MeshArguments mesh;
    std::string out;
    fem::ElasticMaterial material{0, 0, 0};
    std::vector<std::string> interfaces, dampingBands;
    modal::ReductionSettings settings;
    bool json = false;
};

// A lower bound of the peak memory of `reduce` for a mesh of `nodes` nodes (bytes): 20 kB per node
// and 24 B per node and normal mode, below the 27–30 kB per 10-node-tetrahedron node measured
// on meshes/piston.geo at 0.0065, 0.004 and 0.0025 m with 20 modes (docs/modal.md, "Command line").
double reduceMemoryEstimateBytes(double nodes, int modes) { return nodes * (20e3 + 24.0 * std::max(0, modes)); }

// Before Gmsh meshes a .geo: the expected size as a progress line, and a refusal when reducing
// that mesh cannot fit in the memory this process can still get.
void checkMeshEstimate(const fem::MeshEstimate& e, const MeshArguments& mesh, int modes) {
    spdlog::info("meshing {} at size {:.3g} m: about {:.3g} elements ({:.3g} nodes) expected", e.path, e.size,
                 e.tetrahedra, e.nodes);
    const double need = reduceMemoryEstimateBytes(e.nodes, modes);
    const std::uint64_t avail = cosim::availableMemoryBytes();
    if (avail == 0 || need <= double(avail)) return;
    const double maxNodes = double(avail) / reduceMemoryEstimateBytes(1.0, modes);
    const double smallest = fem::sizeForNodes(e.volume, e.area, maxNodes, e.order);
    const std::string sizeText = mesh.options.size > 0.0 ? fmt::format("--size {:g}", mesh.options.size)
                                                         : fmt::format("the size {:g} m of the file", e.size);
    throw std::runtime_error(fmt::format(
        "mesh '{}': {} would make about {:.2g} elements ({:.2g} nodes; volume {:.3g} m³, surface {:.3g} m²), and "
        "reducing them needs at least {} of memory; the smallest size within the memory budget of {} is about "
        "{:.2g} m",
        e.path, sizeText, e.tetrahedra, e.nodes, e.volume, e.area, cosim::formatBytes(need),
        cosim::formatBytes(double(avail)), smallest));
}

void runReduce(const ReduceArgs& a) {
    Stopwatch total;
    std::vector<modal::InterfaceSpec> specs;
    for (const auto& s : a.interfaces) specs.push_back(modal::parseInterface(s));
    for (const auto& b : a.dampingBands) modal::parseDampingBand(b);  // fail before the long work
    for (const auto& s : a.settings.supports) modal::parseSupport(s);
    for (const auto& s : a.settings.dampers) modal::parseDamper(s);
    prepareOutputFile(a.out);
    spdlog::info("reading mesh {}", a.mesh.path);
    fem::MeshOptions options = a.mesh.options;
    options.beforeMeshing = [&](const fem::MeshEstimate& e) {
        checkMeshEstimate(e, a.mesh, a.settings.normalModes);
    };
    Stopwatch meshing;
    const fem::Mesh mesh = fem::readMesh(a.mesh.path, options);
    spdlog::info("mesh: {} nodes, {} {} elements, {} DOFs ({:.1f} s)", mesh.numNodes(), mesh.volume.size(),
                 fem::name(mesh.volume.type), 3 * mesh.numNodes(), meshing.seconds());
    const auto& uniform = a.settings.pressurePatterns;
    const std::string uniformText =
        uniform.empty() ? "" : fmt::format(", uniform pressure on {}", fmt::join(uniform, ", "));
    const auto& supports = a.settings.supports;
    const std::string supportText =
        supports.empty() ? "" : fmt::format(", spring support on {} [N/m^3]", fmt::join(supports, ", "));
    const auto& dampers = a.settings.dampers;
    const std::string damperText =
        dampers.empty() ? "" : fmt::format(", damper support on {} [N*s/m^3]", fmt::join(dampers, ", "));
    spdlog::info("reducing: {} interface(s), {} normal modes{}, static correction on {} surface(s){}{}{}",
                 specs.size(), a.settings.normalModes, a.settings.cutoffHz > 0 ? " (cut-off)" : "",
                 a.settings.staticCorrection.size(), uniformText, supportText, damperText);
    modal::ReductionReport rep;
    modal::ReducedBody body = modal::CraigBamptonReducer(mesh, a.material).reduce(specs, a.settings, &rep);
    if (!a.dampingBands.empty()) {
        std::vector<modal::DampingBand> bands;
        for (const auto& b : a.dampingBands) bands.push_back(modal::parseDampingBand(b));
        modal::assignModalDamping(body, a.settings.dampingRatio, bands);
    }
    body.meshPath = a.mesh.path;
    body.meshHash = modal::fnv1a64File(a.mesh.path);
    body.meshSize = a.mesh.options.size;
    spdlog::info("basis: {} constraint + {} normal + {} inertia-relief + {} static-correction vectors ({} dependent "
                 "dropped) -> {} modes",
                 rep.constraintModes, rep.normalModes, rep.inertiaReliefModes, rep.staticCorrectionModes,
                 rep.droppedDependent, body.numModes());
    Stopwatch w;
    modal::writeReducedBody(body, a.out);
    const double writeSeconds = w.seconds();
    spdlog::info("wrote {} ({:.2f} s)", a.out, writeSeconds);

    const int rigid = static_cast<int>(std::count(body.rigidBody.begin(), body.rigidBody.end(), 1));
    if (a.json) {
        nlohmann::json doc;
        doc["mesh"] = a.mesh.path;
        doc["output"] = a.out;
        doc["dofs"] = rep.dofs;
        doc["modes"] = body.numModes();
        doc["basis"] = {{"constraint", rep.constraintModes},
                        {"normal", rep.normalModes},
                        {"inertia_relief", rep.inertiaReliefModes},
                        {"static_correction", rep.staticCorrectionModes},
                        {"dropped_dependent", rep.droppedDependent}};
        doc["pressure_patterns"] = uniform;
        doc["supports"] = supports;
        doc["dampers"] = dampers;
        doc["rigid_body_modes"] = rigid;
        doc["normal_modes_up_to_hz"] = modal::normalModesUpToHz(body);
        doc["frequencies_hz"] = std::vector<double>(body.frequenciesHz.data(),
                                                    body.frequenciesHz.data() + body.frequenciesHz.size());
        doc["timings_s"] = {{"assemble", rep.assembleSeconds},
                            {"factorize", rep.factorSeconds},
                            {"constraint_modes", rep.constraintModeSeconds},
                            {"normal_modes", rep.normalModeSeconds},
                            {"static_correction", rep.staticCorrectionSeconds},
                            {"orthonormalise", rep.orthonormaliseSeconds},
                            {"write", writeSeconds},
                            {"total", total.seconds()}};
        doc["peak_memory_mib"] = peakMemoryMiB();
        printJson(doc);
        return;
    }
    std::printf("%s -> %s: %d modes (%d constraint, %d normal, %d static correction%s), %d rigid-body\n",
                a.mesh.path.c_str(), a.out.c_str(), body.numModes(), rep.constraintModes, rep.normalModes,
                rep.staticCorrectionModes, uniformText.c_str(), rigid);
    if (!supports.empty()) fmt::print("spring supports {} [N/m^3]\n", fmt::join(supports, ", "));
    if (!dampers.empty()) fmt::print("damper supports {} [N*s/m^3]\n", fmt::join(dampers, ", "));
    std::printf("covers every fixed-interface normal mode up to %.6g Hz\n", modal::normalModesUpToHz(body));
    std::printf("%6s  %16s\n", "mode", "frequency [Hz]");
    for (int k = 0; k < body.numModes(); ++k)
        std::printf("%6d  %16.6g%s\n", k + 1, body.frequenciesHz(k), body.rigidBody[k] ? "  (rigid-body)" : "");
    std::printf("total time %.2f s, peak memory %.0f MiB\n", total.seconds(), peakMemoryMiB());
}

}  // namespace

void addReduceCommand(CLI::App& app) {
    auto a = std::make_shared<ReduceArgs>();
    a->settings.normalModes = 30;
    a->settings.axialOrder = 4;
    a->settings.circumferentialOrder = 6;
    a->settings.dampingRatio = 0.02;
    CLI::App* cmd = app.add_subcommand("reduce", "Craig–Bampton reduced body of a mesh, written to an HDF5 file");
    addMeshOptions(cmd, a->mesh);
    addMaterialOptions(cmd, a->material);
    cmd->add_option("--interface", a->interfaces,
                    "Interface node set and its 6-DOF reference node: GROUP[:rbe2|:rbe3][@x,y,z] (rbe2 rigid, "
                    "rbe3 averaging; point in m, default: centroid of the set); repeatable")
        ->required();
    cmd->add_option("--modes", a->settings.normalModes, "Fixed-interface normal modes to keep")
        ->check(wholeNumberFromTo(0, 100000));
    cmd->add_option("--cutoff", a->settings.cutoffHz, "Keep the normal modes below this frequency [Hz] instead")
        ->check(positiveNumber());
    cmd->add_option("--static-correction", a->settings.staticCorrection,
                    "Surface group with static-correction modes for pressure loads; repeatable");
    cmd->add_option("--pressure-pattern", a->settings.pressurePatterns,
                    "Surface group with one static-correction vector for a uniform pressure (e.g. crown for the "
                    "cylinder's gas pressure), or GROUP@ZLOW:ZHIGH for its part in that band of z [m]; repeatable");
    cmd->add_option("--support", a->settings.supports,
                    "Elastic (Winkler) support GROUP:K: springs of stiffness K per unit area [N/m^3] on the surface "
                    "group, in all three directions, added to the stiffness before the reduction; repeatable")
        ->type_name("GROUP:K");
    cmd->add_option("--damper", a->settings.dampers,
                    "Viscous support GROUP:C: dashpots of C per unit area [N*s/m^3] on the surface group, in all "
                    "three directions, projected on the (undamped) modes and stored with the body; a group may also "
                    "have a --support; repeatable")
        ->type_name("GROUP:C");
    cmd->add_option("--axial-order", a->settings.axialOrder, "Load patterns: Legendre degree along z")
        ->check(wholeNumberFromTo(0, 20));
    cmd->add_option("--axial-hats", a->settings.axialHats,
                    "Load patterns: this many piecewise-linear hats along z instead (travelling loads, e.g. liner)")
        ->check(wholeNumberFromTo(0, 200) & !CLI::IsMember({1}));
    cmd->add_option("--circumferential-order", a->settings.circumferentialOrder,
                    "Load patterns: highest Fourier order in the angle")
        ->check(wholeNumberFromTo(0, 40));
    cmd->add_option("--damping", a->settings.dampingRatio, "Modal damping ratio of the elastic modes, in [0, 1) [-]")
        ->check(numberFromTo(0.0, 0.999999));
    cmd->add_option("--damping-band", a->dampingBands,
                    "Damping per band FMAX:ZETA [Hz:-]: elastic modes up to FMAX get ZETA (lowest band first), "
                    "modes above all bands get --damping; repeatable");
    cmd->add_option("--out", a->out, "Reduced-body file to write (.h5)")->required();
    cmd->add_flag("--json", a->json, "Print one JSON object on stdout instead of the table");
    cmd->callback([a] {
        if (a->settings.cutoffHz > 0 && a->settings.normalModes == 30) a->settings.normalModes = 0;
        runReduce(*a);
    });
}

}  // namespace flexehd::cli
