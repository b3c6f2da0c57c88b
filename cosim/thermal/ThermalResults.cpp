#include "cosim/thermal/ThermalResults.hpp"
#include "cosim/io/JsonText.hpp"

#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cosim/io/VtuWriter.hpp"
#include "cosim/thermal/ThermalFileWriter.hpp"
#include "fem/AtomicFile.hpp"
#include "fem/PeakMemory.hpp"

namespace flexehd::cosim {
namespace {

namespace fs = std::filesystem;

nlohmann::json temperatureSummary(const Eigen::VectorXd& T) {
    return {{"min_k", T.minCoeff()}, {"max_k", T.maxCoeff()}, {"nodal_mean_k", T.mean()}};
}

/// Radial displacement over the sampled surface: extremes over points on the surface, and
/// the mean over θ of each axial row (on-surface points only).
nlohmann::json tableSummary(const SurfaceTable& t) {
    double lo = 1e300, hi = -1e300, sum = 0.0;
    int n = 0;
    std::vector<double> rowMean;
    for (Eigen::Index i = 0; i < t.radial.rows(); ++i) {
        double s = 0.0;
        int k = 0;
        for (Eigen::Index j = 0; j < t.radial.cols(); ++j)
            if (t.onSurface(i, j)) {
                const double u = t.radial(i, j);
                lo = std::min(lo, u), hi = std::max(hi, u), sum += u, ++n, s += u, ++k;
            }
        rowMean.push_back(k ? s / k : 0.0);
    }
    return {{"surface_mean_radius_m", t.meanRadius},
            {"min_m", n ? lo : 0.0},
            {"max_m", n ? hi : 0.0},
            {"mean_m", n ? sum / n : 0.0},
            {"axial_m", t.axial},
            {"row_mean_m", rowMean}};
}

std::vector<std::pair<std::string, double>> bodyAttributes(const ThermalBodyResult& r, double Tref) {
    return {{"temperature_min_k", r.temperature.minCoeff()},
            {"temperature_max_k", r.temperature.maxCoeff()},
            {"temperature_mean_k", r.temperature.mean()},
            {"reference_temperature_k", Tref},
            {"surface_mean_radius_m", r.table.meanRadius}};
}

}  // namespace

namespace {

// summary.json's record of the piston's templug calibration (docs/thermal.md).
nlohmann::json calibrationSummary(const PistonThermalCase& pc, const fem::CalibrationResult& cal) {
    nlohmann::json params = nlohmann::json::array(), points = nlohmann::json::array();
    for (std::size_t k = 0; k < pc.parameters.size(); ++k)
        params.push_back({{"parameter", pc.parameters[k].label()},
                          {"group", pc.parameters[k].group},
                          {"kind", pc.parameters[k].kind == fem::CalibrationParameter::Kind::HeatTransferScale
                                       ? "h_factor"
                                       : "fluid_temperature_k"},
                          {"value", cal.values(Eigen::Index(k))},
                          {"at_bound", bool(cal.atBound[k])}});
    for (std::size_t i = 0; i < pc.templugs.size(); ++i) {
        const auto& t = pc.templugs[i];
        points.push_back({{"name", t.name},
                          {"position_m", {t.position(0), t.position(1), t.position(2)}},
                          {"measured_k", t.temperature},
                          {"computed_k", cal.computed(Eigen::Index(i))},
                          {"residual_k", cal.residuals(Eigen::Index(i))}});
    }
    return {{"matched", cal.matched},
            {"message", cal.message},
            {"converged", cal.converged},
            {"iterations", cal.iterations},
            {"rms_residual_k", cal.rms},
            {"max_abs_residual_k", cal.maxAbs},
            {"initial_rms_residual_k", cal.initialRms},
            {"tolerance_k", pc.tolerance},
            {"parameters", params},
            {"templugs", points}};
}

// summary.json's record of the piston: mesh, temperatures, convection boundaries as fitted,
// calibration, support, the radial displacement table.
nlohmann::json pistonSummary(const PistonThermalCase& pc, const PistonThermalResult& p) {
    nlohmann::json j;
    j["mesh"] = pc.mesh.path;
    j["nodes"] = p.mesh.numNodes();
    j["element_type"] = std::string(fem::name(p.mesh.volume.type));
    j["temperature"] = temperatureSummary(p.temperature);
    nlohmann::json bc = nlohmann::json::object();
    for (std::size_t g = 0; g < pc.convection.size(); ++g) {
        const auto k = Eigen::Index(g);
        bc[pc.convection[g].group] = {{"h_w_m2k", p.parameters.hScale(k) * pc.convection[g].h},
                                      {"h_factor", p.parameters.hScale(k)},
                                      {"fluid_temperature_k", p.parameters.fluidTemperature(k)},
                                      {"heat_flow_w", p.heatFlow(k)}};
    }
    j["convection"] = bc;
    if (p.calibration) j["calibration"] = calibrationSummary(pc, *p.calibration);
    j["support"] = {{"reference", pc.support}, {"determinate_reaction_relative", p.deformation.determinateReaction}};
    j["radial_displacement"] = tableSummary(p.table);
    if (p.ringBelt)
        j["ring_belt"] = {{"surface", pc.ringBelt}, {"z_m", p.ringBelt->axial}, {"temperature_k", p.ringBelt->values}};
    j["seconds"] = p.seconds;
    return j;
}

// summary.json's record of the liner.
nlohmann::json linerSummary(const LinerThermalCase& lc, const ThermalBodyResult& l) {
    nlohmann::json held = nlohmann::json::array();
    for (const auto& h : lc.held) held.push_back(h.group);
    return {{"mesh", lc.mesh.path},
            {"nodes", l.mesh.numNodes()},
            {"element_type", std::string(fem::name(l.mesh.volume.type))},
            {"temperature", temperatureSummary(l.temperature)},
            {"support", {{"held", held},
                         {"reference", lc.reference},
                         {"free_rigid_modes", l.deformation.freeRigidModes},
                         {"determinate_reaction_relative", l.deformation.determinateReaction}}},
            {"radial_displacement", tableSummary(l.table)},
            {"seconds", l.seconds}};
}

}  // namespace

nlohmann::json writeThermalResults(const std::string& dir, const std::string& casePath, const ThermalCase& c,
                                   const ThermalResult& r, const fem::Stopwatch& total) {
    const fem::Stopwatch w;
    fs::create_directories(dir);
    fem::removeStaleTemporaries(dir);
    nlohmann::json doc;
    doc["case"] = casePath;
    doc["name"] = c.name;
    doc["reference_temperature_k"] = c.referenceTemperature;
    nlohmann::json files = nlohmann::json::array();
    auto vtu = [&](const std::string& name, const ThermalBodyResult& b) {
        const std::string path = (fs::path(dir) / name).string();
        writeVtu(path, b.mesh,
                 {{"temperature_k", b.temperature.transpose()},
                  {"thermal_displacement_m", b.deformation.displacement.reshaped(3, b.mesh.numNodes())}},
                 {{"reference_temperature_k", c.referenceTemperature}});
        files.push_back(name);
    };
    // The body's table for thermal.h5 with its attributes and provenance.
    auto table = [&](const ThermalBodyResult& b, const auto& bc) {
        ThermalBodyTable t;
        t.table = b.table;
        t.attributes = bodyAttributes(b, c.referenceTemperature);
        t.textAttributes = {{"mesh", bc.mesh.path}, {"surface", fmt::format("{}", fmt::join(bc.surface, ","))}};
        return t;
    };
    std::optional<ThermalBodyTable> pistonTable, linerTable;
    if (r.piston) {
        vtu("piston.vtu", *r.piston);
        pistonTable = table(*r.piston, *c.piston);
        pistonTable->ringBelt = r.piston->ringBelt;
        pistonTable->ringBeltSurface = fmt::format("{}", fmt::join(c.piston->ringBelt, ","));
        doc["piston"] = pistonSummary(*c.piston, *r.piston);
    }
    if (r.liner) {
        vtu("liner.vtu", *r.liner);
        linerTable = table(*r.liner, *c.liner);
        doc["liner"] = linerSummary(*c.liner, *r.liner);
    }
    writeThermalFile((fs::path(dir) / "thermal.h5").string(), pistonTable, linerTable);
    files.push_back("thermal.h5");
    files.push_back("summary.json");
    doc["grid"] = {{"axial_nodes", c.axialNodes}, {"circumferential_nodes", c.circumferentialNodes}};
    doc["output"] = {{"directory", dir}, {"files", files}};
    doc["timings_s"] = {{"write", w.seconds()}, {"total", total.seconds()}};
    doc["peak_memory_mib"] = fem::peakMemoryMiB();
    fem::writeTextAtomically((fs::path(dir) / "summary.json").string(), jsonText(doc, 2) + "\n");
    return doc;
}

}  // namespace flexehd::cosim
