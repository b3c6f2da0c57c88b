#pragma once
// Finds the tetrahedron that contains a point and the element's shape-function values
// there, so a nodal field can be interpolated at arbitrary points (templug positions):
// T(x) = Σ_a N_a(ξ) T_a, with ξ solving x(ξ) = Σ_a N_a(ξ) x_a (Newton on curved TET10,
// exact barycentrics on TET4). Candidates come from a uniform bucket grid of element
// bounding boxes, so a lookup touches a handful of elements.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "fem/Mesh.hpp"

namespace flexehd::fem {

struct PointLocation {
    Index element = -1;
    Eigen::Vector3d reference;   ///< ξ in the reference tetrahedron
    std::vector<Index> nodes;    ///< the element's nodes
    Eigen::VectorXd weights;     ///< N_a(ξ), sum 1

    /// Σ_a N_a f(node_a) for a nodal scalar field.
    double interpolate(const Eigen::VectorXd& nodal) const;
};

class PointLocator {
public:
    explicit PointLocator(const Mesh& mesh);

    /// The element containing x (within a relative tolerance of 1e-9 of the element size
    /// in reference coordinates), or nothing if x lies outside the mesh.
    std::optional<PointLocation> locate(const Eigen::Vector3d& x) const;
    /// Distance from x to the nearest mesh node, m (for messages about points outside).
    double distanceToNearestNode(const Eigen::Vector3d& x) const;

private:
    std::vector<Index> candidates(const Eigen::Vector3d& x) const;
    const Mesh& mesh_;
    Eigen::Vector3d lower_, cell_;
    Eigen::Vector3i dims_;
    std::vector<std::vector<Index>> buckets_;
};

}  // namespace flexehd::fem
