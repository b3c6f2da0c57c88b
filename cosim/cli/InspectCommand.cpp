// `flexehd inspect FILE.h5`: what a reduced-body file holds, without reading it with
// another tool — provenance, material, mesh, interfaces, settings and the modes.
#include <algorithm>
#include <filesystem>
#include <memory>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include "cosim/cli/CliSupport.hpp"
#include "cosim/cli/Commands.hpp"
#include "modal/ModalSuperposition.hpp"
#include "modal/ReducedBodyFile.hpp"

namespace flexehd::cli {
namespace {

struct InspectArgs {
    std::string file;
    bool json = false;
};

std::vector<double> toVector(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

const char* kindName(modal::InterfaceKind kind) { return kind == modal::InterfaceKind::Rbe2 ? "rbe2" : "rbe3"; }

/// Largest deviation of M_r from the identity: the basis is meant to be M-orthonormal.
double massIdentityError(const modal::ReducedBody& b) {
    if (b.massMatrix.size() == 0) return 0.0;
    return (b.massMatrix - Eigen::MatrixXd::Identity(b.massMatrix.rows(), b.massMatrix.cols())).cwiseAbs().maxCoeff();
}

// The frequencies with every interface held (the run holds a body's interfaces: the piston's pin
// bore, the liner's seats or its block's base).
Eigen::VectorXd heldFrequencies(const modal::ReducedBody& b) {
    std::vector<int> all(b.interfaces.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    return modal::heldFrequenciesHz(b, all);
}

nlohmann::json toJson(const std::string& file, const modal::ReducedBody& b) {
    const fem::Mesh& mesh = b.mesh;
    nlohmann::json groups = nlohmann::json::array();
    for (const auto& [name, g] : mesh.groups)
        groups.push_back({{"name", name}, {"dimension", g.dim}, {"elements", g.elements.size()}});
    nlohmann::json interfaces = nlohmann::json::array();
    for (const auto& itf : b.interfaces)
        interfaces.push_back({{"group", itf.group},
                              {"kind", kindName(itf.kind)},
                              {"reference_point_m", {itf.referencePoint.x(), itf.referencePoint.y(), itf.referencePoint.z()}},
                              {"nodes", itf.nodes.size()}});
    const auto& s = b.settings;
    nlohmann::json doc;
    doc["file"] = file;
    doc["file_size_bytes"] = std::filesystem::file_size(file);
    doc["format"] = modal::kReducedBodyFormat;
    doc["format_version"] = modal::kReducedBodyFormatVersion;
    doc["units"] = modal::kReducedBodyUnits;
    doc["source_mesh"] = {{"path", b.meshPath},
                          {"hash_fnv1a64", b.meshHash},
                          {"element_order", b.elementOrder},
                          {"mesh_size_m", b.meshSize}};
    doc["material"] = {{"E_pa", b.material.E}, {"nu", b.material.nu}, {"rho_kg_m3", b.material.rho}};
    doc["mesh"] = {{"nodes", mesh.numNodes()},
                   {"dofs", 3 * mesh.numNodes()},
                   {"element_type", std::string(fem::name(mesh.volume.type))},
                   {"elements", mesh.volume.size()},
                   {"surface_element_type", std::string(fem::name(mesh.surface.type))},
                   {"surface_triangles", mesh.surface.size()},
                   {"groups", groups}};
    doc["interfaces"] = interfaces;
    doc["settings"] = {{"normal_modes", s.normalModes},
                       {"cutoff_hz", s.cutoffHz},
                       {"static_correction", s.staticCorrection},
                       {"pressure_patterns", s.pressurePatterns},
                       {"supports", s.supports},
                       {"dampers", s.dampers},
                       {"axial_order", s.axialOrder},
                       {"axial_hats", s.axialHats},
                       {"circumferential_order", s.circumferentialOrder},
                       {"damping_ratio", s.dampingRatio}};
    doc["modes"] = b.numModes();
    doc["rigid_body_modes"] = std::count(b.rigidBody.begin(), b.rigidBody.end(), 1);
    doc["frequencies_hz"] = toVector(b.frequenciesHz);
    doc["damping_ratios"] = toVector(b.dampingRatios);
    doc["rigid_body"] = b.rigidBody;
    // The damper supports' projected dashpots D_s (N s/m): its diagonal, one per mode; empty without dampers.
    doc["support_damping_diagonal"] = toVector(Eigen::VectorXd(b.supportDamping.diagonal()));
    doc["mass_identity_error"] = massIdentityError(b);
    doc["held_frequencies_hz"] = b.interfaces.empty() ? std::vector<double>() : toVector(heldFrequencies(b));
    doc["normal_modes_up_to_hz"] = modal::normalModesUpToHz(b);
    return doc;
}

// "every interface held: 251 modes, 1897.9 to 1.2e+05 Hz, the first 1897.9, 1898, … Hz"
void printHeldFrequencies(const Eigen::VectorXd& held) {
    if (held.size() == 0) return;
    std::vector<std::string> first;
    for (Eigen::Index k = 0; k < std::min<Eigen::Index>(6, held.size()); ++k) first.push_back(fmt::format("{:.6g}", held(k)));
    fmt::print("held         every interface held: {} modes, {:.6g} to {:.6g} Hz, the first {}{} Hz\n", held.size(),
               held(0), held(held.size() - 1), fmt::join(first, ", "), held.size() > 6 ? ", …" : "");
}

// "covered      every fixed-interface normal mode up to 8902.6 Hz (--modes 30): the range a
// vibration record (acoustics.up_to_hz) may ask for" (docs/modal.md, "Command line").
void printCoveredRange(const modal::ReducedBody& b) {
    const auto& s = b.settings;
    const std::string how = s.cutoffHz > 0.0 ? fmt::format("--cutoff {:g}", s.cutoffHz)
                                             : fmt::format("--modes {}", s.normalModes);
    fmt::print("covered      every fixed-interface normal mode up to {:.6g} Hz ({}): the range a vibration record "
               "(acoustics.up_to_hz) may ask for\n",
               modal::normalModesUpToHz(b), how);
}

std::string listOrNone(const std::vector<std::string>& names) {
    return names.empty() ? std::string("none") : fmt::format("{}", fmt::join(names, ", "));
}

/// The static-correction vectors the basis carries, in one line (docs/modal.md, "The basis"):
/// e.g. "inertia relief (pin_bore), static correction skirt (axial order 4, circumferential
/// order 6), uniform pressure crown".
std::string loadPatternsText(const modal::ReducedBody& b) {
    const auto& s = b.settings;
    std::vector<std::string> parts, held;
    for (const auto& itf : b.interfaces) held.push_back(itf.group);
    if (!held.empty()) parts.push_back(fmt::format("inertia relief ({})", fmt::join(held, ", ")));
    if (!s.staticCorrection.empty()) {
        const std::string axial = s.axialHats > 0 ? fmt::format("{} axial hats", s.axialHats)
                                                  : fmt::format("axial order {}", s.axialOrder);
        parts.push_back(fmt::format("static correction {} ({}, circumferential order {})",
                                    fmt::join(s.staticCorrection, ", "), axial, s.circumferentialOrder));
    }
    if (!s.pressurePatterns.empty())
        parts.push_back(fmt::format("uniform pressure {}", fmt::join(s.pressurePatterns, ", ")));
    return parts.empty() ? std::string("none") : fmt::format("{}", fmt::join(parts, ", "));
}

void printSummary(const std::string& file, const modal::ReducedBody& b) {
    const fem::Mesh& mesh = b.mesh;
    const auto& s = b.settings;
    fmt::print("{} ({}, format version {}, units {})\n", file, modal::kReducedBodyFormat,
               modal::kReducedBodyFormatVersion, modal::kReducedBodyUnits);
    fmt::print("source mesh  {} (FNV-1a 64 {}), order {}, size {}\n", b.meshPath, b.meshHash, b.elementOrder,
               b.meshSize > 0.0 ? fmt::format("{:g} m", b.meshSize) : std::string("file default"));
    fmt::print("material     E = {:g} Pa, nu = {:g}, rho = {:g} kg/m^3\n", b.material.E, b.material.nu, b.material.rho);
    fmt::print("mesh         {} nodes, {} {} elements, {} {} surface triangles\n", mesh.numNodes(), mesh.volume.size(),
               fem::name(mesh.volume.type), mesh.surface.size(), fem::name(mesh.surface.type));
    for (const auto& [name, g] : mesh.groups)
        fmt::print("  group      {} ({}, {} {})\n", name, g.dim == 3 ? "volume" : "surface", g.elements.size(),
                   g.dim == 3 ? "tetrahedra" : "triangles");
    if (b.interfaces.empty()) fmt::print("interfaces   none\n");
    for (std::size_t i = 0; i < b.interfaces.size(); ++i) {
        const auto& itf = b.interfaces[i];
        fmt::print("interface {}  {} {}, reference point ({:g}, {:g}, {:g}) m, {} nodes\n", i, itf.group,
                   kindName(itf.kind), itf.referencePoint.x(), itf.referencePoint.y(), itf.referencePoint.z(),
                   itf.nodes.size());
    }
    const std::string axial = s.axialHats > 0 ? fmt::format("{} axial hats", s.axialHats)
                                              : fmt::format("axial order {}", s.axialOrder);
    fmt::print("settings     {} normal modes, cut-off {}, static correction {} ({}, circumferential order {}), "
               "pressure patterns {}, damping ratio {:g}\n",
               s.normalModes, s.cutoffHz > 0.0 ? fmt::format("{:g} Hz", s.cutoffHz) : std::string("none"),
               listOrNone(s.staticCorrection), axial, s.circumferentialOrder, listOrNone(s.pressurePatterns),
               s.dampingRatio);
    fmt::print("load patterns  {}\n", loadPatternsText(b));
    if (!s.supports.empty()) fmt::print("supports     {} (GROUP:K, N/m^3)\n", fmt::join(s.supports, ", "));
    if (!s.dampers.empty())
        fmt::print("dampers      {} (GROUP:C, N*s/m^3), projected on the modes: largest |D_s| {:.4g} N*s/m\n",
                   fmt::join(s.dampers, ", "), b.supportDamping.size() > 0 ? b.supportDamping.cwiseAbs().maxCoeff() : 0.0);
    const auto rigid = std::count(b.rigidBody.begin(), b.rigidBody.end(), 1);
    fmt::print("modes        {} ({} rigid-body), max |M_r - I| = {:.2g}\n", b.numModes(), rigid, massIdentityError(b));
    if (!b.interfaces.empty()) printHeldFrequencies(heldFrequencies(b));
    printCoveredRange(b);
    fmt::print("{:>6}  {:>16}  {:>13}\n", "mode", "frequency [Hz]", "damping ratio");
    for (int k = 0; k < b.numModes(); ++k)
        fmt::print("{:>6}  {:>16.6g}  {:>13.4g}{}\n", k + 1, b.frequenciesHz(k), b.dampingRatios(k),
                   b.rigidBody[std::size_t(k)] ? "  (rigid-body)" : "");
}

void runInspect(const InspectArgs& a) {
    spdlog::info("reading {}", a.file);
    Stopwatch t;
    const modal::ReducedBody body = modal::readReducedBody(a.file);
    spdlog::info("read {} modes on {} nodes ({:.2f} s)", body.numModes(), body.mesh.numNodes(), t.seconds());
    if (a.json)
        printJson(toJson(a.file, body));
    else
        printSummary(a.file, body);
}

}  // namespace

void addInspectCommand(CLI::App& app) {
    auto a = std::make_shared<InspectArgs>();
    CLI::App* cmd = app.add_subcommand("inspect", "Summary of a reduced-body file (.h5)");
    cmd->add_option("file", a->file, "Reduced-body file written by flexehd reduce")->required();
    cmd->add_flag("--json", a->json, "Print one JSON object on stdout instead of the summary");
    cmd->callback([a] { runInspect(*a); });
}

}  // namespace flexehd::cli
