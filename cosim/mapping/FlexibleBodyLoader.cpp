#include "cosim/mapping/FlexibleBodyLoader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cosim/mapping/LoadMapping.hpp"
#include "fem/BoundarySurface.hpp"
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

std::string interfaceNames(const modal::ReducedBody& b) {
    std::vector<std::string> names;
    for (const auto& itf : b.interfaces) names.push_back(itf.group);
    return listOr(names);
}

// +1 when the body lies inside the cylinder of its surface (its outward normals point away from
// the axis: a skirt), −1 when outside (towards the axis: a bore), 0 when mixed or empty.
int bodySide(const fem::Mesh& mesh, const std::string& surface) {
    const CylinderSides s = cylinderSides(mesh, fem::BoundarySurface(mesh, surface));
    return s.away > 0 && s.towards == 0 ? 1 : s.towards > 0 && s.away == 0 ? -1 : 0;
}

// The largest distance (m) of the given grid nodes (on the grid's cylinder) from the nearest node
// of the body's surface group.
double farthestFromSurface(const fem::Mesh& mesh, const std::string& surface, const lube::FilmGrid& grid,
                           const std::vector<int>& nodes) {
    const std::vector<fem::Index> sn = mesh.groupNodes(surface);
    double worst = 0.0;
    for (int k : nodes) {
        const int i = k / grid.nTheta(), j = k % grid.nTheta();
        const Eigen::Vector3d x(grid.radius() * std::cos(grid.theta(j)), grid.radius() * std::sin(grid.theta(j)),
                                grid.z(i));
        double best = std::numeric_limits<double>::infinity();
        for (fem::Index n : sn) best = std::min(best, (mesh.nodes.col(n) - x).squaredNorm());
        worst = std::max(worst, std::sqrt(best));
    }
    return worst;
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
    const auto refuse = [&](const std::string& what) {
        throw std::invalid_argument(fmt::format("{}: {}.surface: {}", c.path, bodyKey(role), what));
    };
    // The piston's film surface faces away from the axis, the liner's towards it: a body of the other
    // role (a liner's bore named as the piston's surface, a skirt as the liner's) is refused.
    const modal::ReducedBody& b = body->body();
    const bool piston = side == FlexibleSurface::Side::Piston;
    if (b.mesh.hasGroup(spec.surface) && b.mesh.group(spec.surface).dim == 2) {
        const int onSide = bodySide(b.mesh, spec.surface);
        if (onSide == (piston ? -1 : 1))
            refuse(fmt::format(
                "the surface '{}' of the reduced body {} faces {} the axis, as a {}'s does; the case expects the "
                "{}'s body, whose film surface faces {} the axis (the {}); is {} the {}'s reduced body (its "
                "interfaces: {})?",
                spec.surface, spec.file, piston ? "towards" : "away from", piston ? "liner bore" : "piston skirt",
                role, piston ? "away from" : "towards", piston ? "skirt" : "bore", spec.file,
                piston ? "liner" : "piston", interfaceNames(b)));
    }
    std::unique_ptr<FlexibleSurface> surface;
    try {
        surface = std::make_unique<FlexibleSurface>(body, side, spec.surface, grid, zMin, zMax);
    } catch (const std::exception& e) {
        refuse(fmt::format("the reduced body {} cannot face the film: {}", spec.file, e.what()));
    }
    // Film nodes the surface does not reach get no elastic motion: a few at the edges are normal
    // (a warning of the run), more than kMaxOutsideFraction mean the body does not fit the case.
    const std::vector<int>& outside = surface->outsideNodes();
    const int film = grid.filmNodeCount();
    if (film > 0 && double(outside.size()) > kMaxOutsideFraction * film) {
        double zLo = std::numeric_limits<double>::infinity(), zHi = -zLo;
        for (fem::Index n : b.mesh.groupNodes(spec.surface)) {
            zLo = std::min(zLo, b.mesh.nodes(2, n));
            zHi = std::max(zHi, b.mesh.nodes(2, n));
        }
        refuse(fmt::format(
            "{} of the {} film nodes of the {}'s grid ({:.0f} %, more than {:.0f} %) lie outside the surface '{}' of "
            "the reduced body {}, up to {:.1f} mm from it: the case expects the {}'s film surface over z {:.1f} to "
            "{:.1f} mm at radius {:.2f} mm, the surface spans z {:.1f} to {:.1f} mm; is {} the {}'s reduced body, "
            "made from the mesh the case's {} geometry describes?",
            outside.size(), film, role, 100.0 * double(outside.size()) / film, 100.0 * kMaxOutsideFraction,
            spec.surface, spec.file, 1e3 * farthestFromSurface(b.mesh, spec.surface, grid, outside), role,
            1e3 * grid.z(0), 1e3 * grid.z(grid.nAxial() - 1), 1e3 * grid.radius(), 1e3 * zLo, 1e3 * zHi, spec.file,
            role, role));
    }
    return surface;
}

}  // namespace flexehd::cosim
