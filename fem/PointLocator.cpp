#include "fem/PointLocator.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "fem/ElementDispatch.hpp"
#include "fem/ShapeFunctions.hpp"

namespace flexehd::fem {

double PointLocation::interpolate(const Eigen::VectorXd& nodal) const {
    double v = 0.0;
    for (std::size_t a = 0; a < nodes.size(); ++a) v += weights(Eigen::Index(a)) * nodal(nodes[a]);
    return v;
}

PointLocator::PointLocator(const Mesh& mesh) : mesh_(mesh) {
    lower_ = mesh.nodes.rowwise().minCoeff();
    const Eigen::Vector3d upper = mesh.nodes.rowwise().maxCoeff();
    const Eigen::Vector3d extent = (upper - lower_).cwiseMax(1e-12);
    // About one element per bucket: n_b ≈ elements, cells as cubic as the box allows.
    const double cellSize = std::cbrt(extent.prod() / std::max<double>(1.0, mesh.volume.size()));
    for (int d = 0; d < 3; ++d) {
        dims_(d) = std::clamp(int(std::ceil(extent(d) / cellSize)), 1, 256);
        cell_(d) = extent(d) / dims_(d);
    }
    buckets_.resize(std::size_t(dims_.prod()));
    for (Index e = 0; e < mesh.volume.size(); ++e) {
        Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
        for (int a = 0; a < mesh.volume.nodes.rows(); ++a) {
            lo = lo.cwiseMin(mesh.nodes.col(mesh.volume.nodes(a, e)));
            hi = hi.cwiseMax(mesh.nodes.col(mesh.volume.nodes(a, e)));
        }
        Eigen::Vector3i i0, i1;
        for (int d = 0; d < 3; ++d) {
            i0(d) = std::clamp(int(std::floor((lo(d) - lower_(d)) / cell_(d))), 0, dims_(d) - 1);
            i1(d) = std::clamp(int(std::floor((hi(d) - lower_(d)) / cell_(d))), 0, dims_(d) - 1);
        }
        for (int i = i0(0); i <= i1(0); ++i)
            for (int j = i0(1); j <= i1(1); ++j)
                for (int k = i0(2); k <= i1(2); ++k) buckets_[std::size_t((k * dims_(1) + j) * dims_(0) + i)].push_back(e);
    }
}

std::vector<Index> PointLocator::candidates(const Eigen::Vector3d& x) const {
    Eigen::Vector3i c;
    for (int d = 0; d < 3; ++d) {
        const double t = (x(d) - lower_(d)) / cell_(d);
        // Points a little outside the box may still be within a curved element's tolerance.
        if (t < -1e-6 || t > dims_(d) + 1e-6) return {};
        c(d) = std::clamp(int(std::floor(t)), 0, dims_(d) - 1);
    }
    return buckets_[std::size_t((c(2) * dims_(1) + c(1)) * dims_(0) + c(0))];
}

std::optional<PointLocation> PointLocator::locate(const Eigen::Vector3d& x) const {
    constexpr double kTol = 1e-9;
    std::optional<PointLocation> best;
    double bestViolation = 1e300;
    withType(mesh_.volume.type, [&]<ElementType T>() {
        if constexpr (dimension(T) == 3) {
            using S = Shape<T>;
            for (Index e : candidates(x)) {
                const auto X = elementCoordinates<S::kNodes>(mesh_.nodes, mesh_.volume, e);
                // Start from the straight (vertex) tetrahedron's barycentrics ...
                Eigen::Matrix3d J0;
                for (int d = 0; d < 3; ++d) J0.col(d) = X.col(d + 1) - X.col(0);
                Eigen::Vector3d xi = J0.partialPivLu().solve(x - X.col(0));
                // ... and correct for curved TET10 edges by Newton on x(ξ) = x.
                for (int it = 0; it < 20 && S::kNodes > 4; ++it) {
                    const Eigen::Vector3d r = X * S::N(xi) - x;
                    const Eigen::Matrix3d J = X * S::dN(xi);
                    const Eigen::Vector3d dxi = J.partialPivLu().solve(r);
                    xi -= dxi;
                    if (dxi.norm() < 1e-14) break;
                }
                const double violation = std::max({-xi(0), -xi(1), -xi(2), xi.sum() - 1.0});
                if (violation > kTol || violation >= bestViolation) continue;
                bestViolation = violation;
                PointLocation loc;
                loc.element = e;
                loc.reference = xi;
                const auto N = S::N(xi);
                loc.weights = N;
                loc.nodes.assign(&mesh_.volume.nodes(0, e), &mesh_.volume.nodes(0, e) + S::kNodes);
                best = std::move(loc);
                if (violation <= 0.0) break;  // strictly inside
            }
        }
    });
    return best;
}

double PointLocator::distanceToNearestNode(const Eigen::Vector3d& x) const {
    return std::sqrt((mesh_.nodes.colwise() - x).colwise().squaredNorm().minCoeff());
}

}  // namespace flexehd::fem
