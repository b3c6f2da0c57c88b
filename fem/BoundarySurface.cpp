#include "fem/BoundarySurface.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include <Eigen/Geometry>

#include "fem/SurfaceElement.hpp"

namespace flexehd::fem {
namespace {
using Face = std::array<Index, 3>;
struct FaceHash {
    std::size_t operator()(const Face& f) const {
        std::size_t h = std::size_t(f[0]) * 0x9E3779B97F4A7C15ull;
        h ^= std::size_t(f[1]) + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
        h ^= std::size_t(f[2]) + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
        return h;
    }
};
Face sorted(Face f) {
    std::sort(f.begin(), f.end());
    return f;
}
}  // namespace

BoundarySurface::BoundarySurface(const Mesh& mesh, const std::string& group)
    : BoundarySurface(mesh, group, -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()) {}

BoundarySurface::BoundarySurface(const Mesh& mesh, const std::string& group, double zLow, double zHigh)
    : mesh_(mesh), name_(group) {
    const PhysicalGroup& g = mesh.group(group);
    if (g.dim != 2)
        throw std::invalid_argument("physical group '" + group + "' of mesh '" + mesh.source +
                                    "' is a volume; a surface group is needed here");
    for (Index t : g.elements) {
        const double z = (mesh.nodes(2, mesh.surface.nodes(0, t)) + mesh.nodes(2, mesh.surface.nodes(1, t)) +
                          mesh.nodes(2, mesh.surface.nodes(2, t))) / 3.0;
        if (z >= zLow && z <= zHigh) triangles_.push_back(t);
    }
    if (triangles_.empty() && !g.elements.empty())
        throw std::invalid_argument("surface group '" + group + "' of mesh '" + mesh.source +
                                    "' has no triangle with its centroid at " + std::to_string(zLow) +
                                    " <= z <= " + std::to_string(zHigh) + " m");
    // Which tetrahedron has each triangle as a face, and its vertex opposite that face.
    std::unordered_map<Face, std::pair<int, Index>, FaceHash> faces;  // (tets found, opposite)
    faces.reserve(triangles_.size() * 2);
    for (Index t : triangles_)
        faces.emplace(sorted({mesh.surface.nodes(0, t), mesh.surface.nodes(1, t), mesh.surface.nodes(2, t)}),
                      std::make_pair(0, Index(-1)));
    static constexpr int kFaces[4][4] = {{1, 2, 3, 0}, {0, 2, 3, 1}, {0, 1, 3, 2}, {0, 1, 2, 3}};
    for (Index e = 0; e < mesh.volume.size(); ++e)
        for (const auto& f : kFaces) {
            auto it = faces.find(sorted({mesh.volume.nodes(f[0], e), mesh.volume.nodes(f[1], e),
                                         mesh.volume.nodes(f[2], e)}));
            if (it == faces.end()) continue;
            ++it->second.first;
            it->second.second = mesh.volume.nodes(f[3], e);
        }
    sign_.resize(triangles_.size());
    for (std::size_t k = 0; k < triangles_.size(); ++k) {
        const Index t = triangles_[k];
        const Eigen::Vector3d x0 = mesh.nodes.col(mesh.surface.nodes(0, t));
        const Eigen::Vector3d x1 = mesh.nodes.col(mesh.surface.nodes(1, t));
        const Eigen::Vector3d x2 = mesh.nodes.col(mesh.surface.nodes(2, t));
        const auto& [count, opposite] =
            faces.at(sorted({mesh.surface.nodes(0, t), mesh.surface.nodes(1, t), mesh.surface.nodes(2, t)}));
        if (count != 1)
            throw std::runtime_error("triangle " + std::to_string(mesh.surface.tags[t]) + " of surface '" +
                                     group + "' in mesh '" + mesh.source + "' is a face of " +
                                     std::to_string(count) + " tetrahedra; expected a boundary face");
        const Eigen::Vector3d outward = (x0 + x1 + x2) / 3.0 - mesh.nodes.col(opposite);
        sign_[k] = (x1 - x0).cross(x2 - x0).dot(outward) > 0.0 ? 1.0 : -1.0;
    }
}

double BoundarySurface::area() const {
    double a = 0.0;
    const int n = nodesPerElement(mesh_.surface.type);
    Eigen::Matrix3Xd X(3, n);
    for (Index t : triangles_) {
        for (int i = 0; i < n; ++i) X.col(i) = mesh_.nodes.col(mesh_.surface.nodes(i, t));
        a += mesh_.surface.type == ElementType::Tri3
                 ? SurfaceElement<ElementType::Tri3>::area(X)
                 : SurfaceElement<ElementType::Tri6>::area(X);
    }
    return a;
}

}  // namespace flexehd::fem
