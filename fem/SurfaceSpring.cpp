#include "fem/SurfaceSpring.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "fem/ElementDispatch.hpp"
#include "fem/SurfaceElement.hpp"

namespace flexehd::fem {

SparseMatrix surfaceSpringMatrix(const BoundarySurface& surface, double k) {
    if (!(std::isfinite(k) && k > 0.0))
        throw std::invalid_argument("spring support on '" + surface.name() +
                                    "': stiffness per area must be finite and > 0 N/m^3, got " + std::to_string(k));
    return surfaceBedMatrix(surface, k);
}

SparseMatrix surfaceDashpotMatrix(const BoundarySurface& surface, double c) {
    if (!(std::isfinite(c) && c > 0.0))
        throw std::invalid_argument("damper support on '" + surface.name() +
                                    "': damping per area must be finite and > 0 N*s/m^3, got " + std::to_string(c));
    return surfaceBedMatrix(surface, c);
}

SparseMatrix surfaceBedMatrix(const BoundarySurface& surface, double k) {
    const Mesh& mesh = surface.mesh();
    std::vector<Eigen::Triplet<double, int>> entries;
    withType(mesh.surface.type, [&]<ElementType T>() {
        if constexpr (dimension(T) == 2) {
            using El = SurfaceElement<T>;
            typename El::Matrix He;
            entries.reserve(surface.triangles().size() * El::kNodes * El::kNodes * 3);
            for (Index t : surface.triangles()) {
                El::massLike(elementCoordinates<El::kNodes>(mesh.nodes, mesh.surface, t), k, He);
                for (int a = 0; a < El::kNodes; ++a)
                    for (int b = 0; b < El::kNodes; ++b) {
                        const Index i = mesh.surface.nodes(a, t), j = mesh.surface.nodes(b, t);
                        if (i > j) continue;  // upper triangle; i == j blocks are diagonal
                        for (int c = 0; c < 3; ++c) entries.emplace_back(3 * i + c, 3 * j + c, He(a, b));
                    }
            }
        }
    });
    const int n = 3 * int(mesh.numNodes());
    SparseMatrix Ks(n, n);
    Ks.setFromTriplets(entries.begin(), entries.end());  // duplicates summed
    return Ks;
}

}  // namespace flexehd::fem
