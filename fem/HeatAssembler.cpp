#include "fem/HeatAssembler.hpp"

#include <stdexcept>

#include "fem/ElementDispatch.hpp"
#include "fem/HeatElement.hpp"
#include "fem/SurfaceElement.hpp"

namespace flexehd::fem {

HeatAssembler::HeatAssembler(const Mesh& mesh) : mesh_(mesh), pattern_(mesh.volume, mesh.numNodes(), 1) {}

SparseMatrix HeatAssembler::conductivity(double k) const {
    if (!(k > 0.0)) throw std::invalid_argument("thermal conductivity must be > 0 W/(m K)");
    SparseMatrix K = pattern_.zeroMatrix();
    withType(mesh_.volume.type, [&]<ElementType T>() {
        if constexpr (dimension(T) == 3) {
            using El = HeatElement<T>;
            typename El::Matrix Ke;
            for (Index e = 0; e < mesh_.volume.size(); ++e) {
                El::conductivity(elementCoordinates<El::kNodes>(mesh_.nodes, mesh_.volume, e), k, Ke);
                pattern_.add(K, &mesh_.volume.nodes(0, e), El::kNodes, Ke);
            }
        }
    });
    return K;
}

void HeatAssembler::addConvection(const BoundarySurface& surface, double h, double fluidTemperature,
                                  SparseMatrix& K, Eigen::VectorXd& f) const {
    if (!(h >= 0.0)) throw std::invalid_argument("heat-transfer coefficient must be >= 0 W/(m^2 K)");
    withType(mesh_.surface.type, [&]<ElementType T>() {
        if constexpr (dimension(T) == 2) {
            using El = SurfaceElement<T>;
            typename El::Matrix He;
            typename El::Vector fe;
            for (Index t : surface.triangles()) {
                const auto X = elementCoordinates<El::kNodes>(mesh_.nodes, mesh_.surface, t);
                El::massLike(X, h, He);
                El::flux(X, h * fluidTemperature, fe);
                pattern_.add(K, &mesh_.surface.nodes(0, t), El::kNodes, He);
                for (int a = 0; a < El::kNodes; ++a) f(mesh_.surface.nodes(a, t)) += fe(a);
            }
        }
    });
}

void HeatAssembler::addHeatFlux(const BoundarySurface& surface, double q, Eigen::VectorXd& f) const {
    withType(mesh_.surface.type, [&]<ElementType T>() {
        if constexpr (dimension(T) == 2) {
            using El = SurfaceElement<T>;
            typename El::Vector fe;
            for (Index t : surface.triangles()) {
                El::flux(elementCoordinates<El::kNodes>(mesh_.nodes, mesh_.surface, t), q, fe);
                for (int a = 0; a < El::kNodes; ++a) f(mesh_.surface.nodes(a, t)) += fe(a);
            }
        }
    });
}

}  // namespace flexehd::fem
