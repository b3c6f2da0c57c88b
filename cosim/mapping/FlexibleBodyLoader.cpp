#include "cosim/mapping/FlexibleBodyLoader.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "modal/ReducedBodyFile.hpp"

namespace flexehd::cosim {
namespace {

std::string listOr(const std::vector<std::string>& names) {
    return names.empty() ? std::string("none") : fmt::format("{}", fmt::join(names, ", "));
}

std::vector<std::string> groupsOfDimension(const modal::ReducedBody& b, int dim) {
    std::vector<std::string> names;
    for (const auto& [name, g] : b.mesh.groups)
        if (g.dim == dim) names.push_back(name);
    return names;
}

std::string bodyKey(const std::string& role) { return "bodies." + role; }

std::shared_ptr<const FlexibleBody> loadFlexibleBody(const EngineCase& c, const BodySpec& spec, const std::string& role) {
    auto fail = [&](const std::string& sub, const std::string& what) {
        throw std::invalid_argument(fmt::format("{}: {}.{}: {}", c.path, bodyKey(role), sub, what));
    };
    modal::ReducedBody body;
    try {
        body = modal::readReducedBody(spec.file);
    } catch (const std::exception& e) {
        fail("file", e.what());
    }
    const std::vector<std::string> surfaces = groupsOfDimension(body, 2);
    if (!body.mesh.hasGroup(spec.surface)) {
        fail("surface", fmt::format("'{}' is not a physical group of the reduced body {} (its surface groups: {})",
                                    spec.surface, spec.file, listOr(surfaces)));
    }
    if (body.mesh.group(spec.surface).dim != 2)
        fail("surface", fmt::format("'{}' of the reduced body {} is a volume group; the film needs a surface group "
                                    "(its surface groups: {})",
                                    spec.surface, spec.file, listOr(surfaces)));
    std::vector<std::string> interfaces;
    for (const auto& itf : body.interfaces) interfaces.push_back(itf.group);
    for (const std::string& h : spec.interfaces)
        if (std::find(interfaces.begin(), interfaces.end(), h) == interfaces.end())
            fail("interface", fmt::format("'{}' is not an interface of the reduced body {} (its interfaces: {})", h,
                                          spec.file, listOr(interfaces)));
    try {
        return std::make_shared<const FlexibleBody>(std::move(body), spec.interfaces);
    } catch (const std::exception& e) {
        fail("surface", fmt::format("the reduced body {} cannot face the film: {}", spec.file, e.what()));
    }
    return nullptr;  // not reached
}

}  // namespace

CaseBodies loadCaseBodies(const EngineCase& c) {
    CaseBodies b;
    if (c.pistonBody.model == BodyModel::Flexible) b.piston = loadFlexibleBody(c, c.pistonBody, "piston");
    if (c.linerBody.model == BodyModel::Flexible) b.liner = loadFlexibleBody(c, c.linerBody, "liner");
    return b;
}

std::unique_ptr<FlexibleSurface> facingSurface(const EngineCase& c, std::shared_ptr<const FlexibleBody> body,
                                               const BodySpec& spec, const std::string& role,
                                               FlexibleSurface::Side side, const lube::FilmGrid& grid, double zMin,
                                               double zMax) {
    try {
        return std::make_unique<FlexibleSurface>(std::move(body), side, spec.surface, grid, zMin, zMax);
    } catch (const std::exception& e) {
        throw std::invalid_argument(fmt::format("{}: {}.surface: the reduced body {} cannot face the film: {}", c.path,
                                                bodyKey(role), spec.file, e.what()));
    }
}

}  // namespace flexehd::cosim
