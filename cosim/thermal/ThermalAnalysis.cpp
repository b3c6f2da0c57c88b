#include "cosim/thermal/ThermalAnalysis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "cosim/thermal/LinerTemperature.hpp"
#include "fem/MeshReader.hpp"

namespace flexehd::cosim {
namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Runs f, prefixing any error with "FILE: key: ".
template <typename F>
decltype(auto) withKey(const ThermalCase& c, const std::string& key, F&& f) {
    try {
        return f();
    } catch (const std::exception& e) {
        throw std::runtime_error(fmt::format("{}: {}: {}", c.file, key, e.what()));
    }
}

void requireSurface(const ThermalCase& c, const fem::Mesh& m, const std::string& key, const std::string& group) {
    withKey(c, key, [&] {
        if (m.group(group).dim != 2)  // unknown: invalid_argument listing the available groups
            throw std::invalid_argument("physical group '" + group + "' of mesh '" + m.source + "' is not a surface");
    });
}

fem::Mesh loadMesh(const ThermalCase& c, const std::string& key, const ThermalBodyMesh& spec) {
    fem::MeshOptions o;
    o.size = spec.size;
    o.order = spec.order;
    return withKey(c, key, [&] { return fem::readMesh(spec.path, o); });
}

}  // namespace

ThermalResult runThermalAnalysis(const ThermalCase& c, const std::function<void(const std::string&)>& progress) {
    auto say = [&](const std::string& s) {
        if (progress) progress(s);
    };
    ThermalResult out;
    if (c.piston) {
        const auto t0 = std::chrono::steady_clock::now();
        const PistonThermalCase& pc = *c.piston;
        auto& r = out.piston.emplace();
        say(fmt::format("piston: reading mesh {}", pc.mesh.path));
        r.mesh = loadMesh(c, "piston.mesh", pc.mesh);
        const fem::Mesh& m = r.mesh;
        for (const auto& b : pc.convection) requireSurface(c, m, "piston.convection." + b.group, b.group);
        for (const auto& g : pc.surface) requireSurface(c, m, "piston.surface", g);
        // The ring belt's profile: the groups given, or the default where the mesh has it.
        const bool ringBelt = !pc.ringBelt.empty() && (pc.ringBeltGiven || m.hasGroup(pc.ringBelt.front()));
        if (ringBelt)
            for (const auto& g : pc.ringBelt) requireSurface(c, m, "piston.ring_belt", g);
        withKey(c, "piston.support", [&] { m.group(pc.support); });
        say(fmt::format("piston: {} nodes, {} {} elements; steady conduction with {} convection boundaries",
                        m.numNodes(), m.volume.size(), fem::name(m.volume.type), pc.convection.size()));
        const fem::SteadyHeatConduction heat(m, pc.conductivity, pc.convection);
        if (!pc.parameters.empty()) {
            say(fmt::format("piston: calibrating {} parameter(s) to {} templug(s)", pc.parameters.size(),
                            pc.templugs.size()));
            fem::CalibrationOptions opt;
            opt.tolerance = pc.tolerance;
            r.calibration = withKey(c, "piston.calibration", [&] {
                return fem::ThermalCalibration(heat, pc.parameters, pc.templugs, opt).run();
            });
            r.parameters = r.calibration->parameters;
            r.temperature = r.calibration->temperature;
            say(fmt::format("piston: calibration RMS residual {:.3g} K (was {:.3g} K), {} iterations{}",
                            r.calibration->rms, r.calibration->initialRms, r.calibration->iterations,
                            r.calibration->matched ? "" : " — NOT MATCHED"));
        } else {
            r.parameters = heat.nominal();
            r.temperature = withKey(c, "piston.convection", [&] { return heat.solve(r.parameters); });
        }
        r.heatFlow = heat.boundaryHeatFlow(r.parameters, r.temperature);
        say(fmt::format("piston: T = {:.1f} … {:.1f} K; thermoelastic solve ({} DOFs)", r.temperature.minCoeff(),
                        r.temperature.maxCoeff(), 3 * m.numNodes()));
        r.deformation = withKey(c, "piston.support", [&] {
            return fem::solveThermalDeformation(m, pc.material, pc.expansion, r.temperature, c.referenceTemperature,
                                                {{}, pc.support});
        });
        r.table = withKey(c, "piston.surface", [&] {
            return CylindricalSurfaceSampler(m, pc.surface).sample(r.deformation.displacement, c.axialNodes,
                                                                    c.circumferentialNodes);
        });
        if (ringBelt) {
            r.ringBelt = withKey(c, "piston.ring_belt", [&] {
                const CylindricalSurfaceSampler belt(m, pc.ringBelt);
                const int rows = std::max(
                    c.axialNodes, int(std::ceil((belt.zMax() - belt.zMin()) / kRingBeltRowSpacing - 1e-9)) + 1);
                return axialProfile(belt.sampleScalar(r.temperature, rows, c.circumferentialNodes));
            });
            say(fmt::format("piston: ring-belt surface temperature over z = {:.4f} … {:.4f} m: {:.1f} … {:.1f} K "
                            "({} rows)",
                            r.ringBelt->axial.front(), r.ringBelt->axial.back(),
                            *std::min_element(r.ringBelt->values.begin(), r.ringBelt->values.end()),
                            *std::max_element(r.ringBelt->values.begin(), r.ringBelt->values.end()),
                            r.ringBelt->axial.size()));
        } else if (!pc.ringBelt.empty()) {
            say(fmt::format("piston: the mesh has no group '{}': thermal.h5 gets no ring-belt temperature profile "
                            "(piston.ring_belt names the ring belt's outer surface)",
                            pc.ringBelt.front()));
        }
        r.seconds = secondsSince(t0);
    }
    if (c.liner) {
        const auto t0 = std::chrono::steady_clock::now();
        const LinerThermalCase& lc = *c.liner;
        auto& r = out.liner.emplace();
        say(fmt::format("liner: reading mesh {}", lc.mesh.path));
        r.mesh = loadMesh(c, "liner.mesh", lc.mesh);
        const fem::Mesh& m = r.mesh;
        for (const auto& g : lc.surface) requireSurface(c, m, "liner.surface", g);
        for (const auto& h : lc.held) withKey(c, "liner.support.held", [&] { m.group(h.group); });
        withKey(c, "liner.support.reference", [&] { m.group(lc.reference); });
        r.temperature = linerTemperature(m, lc.radii, lc.stations);
        if (!(r.temperature.minCoeff() > 0.0))
            throw std::runtime_error(fmt::format(
                "{}: liner.thermocouples: the radial extrapolation gives {:.1f} K somewhere in the wall; check the radii "
                "and temperatures",
                c.file, r.temperature.minCoeff()));
        say(fmt::format("liner: {} nodes; T = {:.1f} … {:.1f} K from {} thermocouple station(s); thermoelastic solve",
                        m.numNodes(), r.temperature.minCoeff(), r.temperature.maxCoeff(), lc.stations.size()));
        r.deformation = withKey(c, "liner.support", [&] {
            return fem::solveThermalDeformation(m, lc.material, lc.expansion, r.temperature, c.referenceTemperature,
                                                {lc.held, lc.reference});
        });
        r.table = withKey(c, "liner.surface", [&] {
            return CylindricalSurfaceSampler(m, lc.surface).sample(r.deformation.displacement, c.axialNodes,
                                                                    c.circumferentialNodes);
        });
        r.seconds = secondsSince(t0);
    }
    return out;
}

}  // namespace flexehd::cosim
