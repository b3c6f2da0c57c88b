#include "fem/ElasticityAssembler.hpp"

#include <stdexcept>

#include "fem/ElasticityElement.hpp"
#include "fem/ElementDispatch.hpp"
#include "fem/SurfaceElement.hpp"

namespace flexehd::fem {

ElasticityAssembler::ElasticityAssembler(const Mesh& mesh)
    : mesh_(mesh), pattern_(mesh.volume, mesh.numNodes(), 3) {}

SparseMatrix ElasticityAssembler::stiffness(const ElasticMaterial& material) const {
    material.validate();
    SparseMatrix K = pattern_.zeroMatrix();
    const double lambda = material.lambda(), mu = material.mu();
    withType(mesh_.volume.type, [&]<ElementType T>() {
        if constexpr (dimension(T) == 3) {
            using El = ElasticityElement<T>;
            typename El::Matrix Ke;
            for (Index e = 0; e < mesh_.volume.size(); ++e) {
                El::stiffness(elementCoordinates<El::kNodes>(mesh_.nodes, mesh_.volume, e), lambda, mu, Ke);
                pattern_.add(K, &mesh_.volume.nodes(0, e), El::kNodes, Ke);
            }
        }
    });
    return K;
}

SparseMatrix ElasticityAssembler::mass(double density) const {
    if (!(density > 0.0)) throw std::invalid_argument("density must be > 0 kg/m^3");
    SparseMatrix M = pattern_.zeroMatrix();
    withType(mesh_.volume.type, [&]<ElementType T>() {
        if constexpr (dimension(T) == 3) {
            using El = ElasticityElement<T>;
            typename El::Matrix Me;
            for (Index e = 0; e < mesh_.volume.size(); ++e) {
                El::mass(elementCoordinates<El::kNodes>(mesh_.nodes, mesh_.volume, e), density, Me);
                pattern_.add(M, &mesh_.volume.nodes(0, e), El::kNodes, Me);
            }
        }
    });
    return M;
}

Eigen::VectorXd ElasticityAssembler::thermalLoad(const ElasticMaterial& material, double expansion,
                                                 const Eigen::VectorXd& temperature,
                                                 double referenceTemperature) const {
    material.validate();
    if (temperature.size() != mesh_.numNodes())
        throw std::invalid_argument("thermal load: " + std::to_string(temperature.size()) +
                                    " nodal temperatures given, mesh has " +
                                    std::to_string(mesh_.numNodes()) + " nodes");
    Eigen::VectorXd f = Eigen::VectorXd::Zero(numDofs());
    const double factor = material.thermalStressFactor() * expansion;
    withType(mesh_.volume.type, [&]<ElementType T>() {
        if constexpr (dimension(T) == 3) {
            using El = ElasticityElement<T>;
            typename El::Vector fe;
            typename El::NodalScalar dT;
            for (Index e = 0; e < mesh_.volume.size(); ++e) {
                for (int a = 0; a < El::kNodes; ++a)
                    dT(a) = temperature(mesh_.volume.nodes(a, e)) - referenceTemperature;
                El::thermalLoad(elementCoordinates<El::kNodes>(mesh_.nodes, mesh_.volume, e), dT, factor, fe);
                for (int a = 0; a < El::kNodes; ++a)
                    f.segment<3>(3 * mesh_.volume.nodes(a, e)) += fe.template segment<3>(3 * a);
            }
        }
    });
    return f;
}

Eigen::VectorXd ElasticityAssembler::pressureLoad(const BoundarySurface& surface, double pressure) const {
    return pressureLoad(surface, Eigen::VectorXd::Constant(mesh_.numNodes(), pressure));
}

Eigen::VectorXd ElasticityAssembler::pressureLoad(const BoundarySurface& surface,
                                                  const Eigen::VectorXd& nodalPressure) const {
    if (nodalPressure.size() != mesh_.numNodes())
        throw std::invalid_argument("pressure load on '" + surface.name() + "': " +
                                    std::to_string(nodalPressure.size()) + " nodal values for " +
                                    std::to_string(mesh_.numNodes()) + " nodes");
    Eigen::VectorXd f = Eigen::VectorXd::Zero(numDofs());
    withType(mesh_.surface.type, [&]<ElementType T>() {
        if constexpr (dimension(T) == 2) {
            using El = SurfaceElement<T>;
            typename El::NodalVector fe;
            typename El::Vector pe;
            for (std::size_t k = 0; k < surface.triangles().size(); ++k) {
                const Index t = surface.triangles()[k];
                for (int a = 0; a < El::kNodes; ++a) pe(a) = nodalPressure(mesh_.surface.nodes(a, t));
                El::pressure(elementCoordinates<El::kNodes>(mesh_.nodes, mesh_.surface, t), pe,
                             surface.orientation()[k], fe);
                for (int a = 0; a < El::kNodes; ++a)
                    f.segment<3>(3 * mesh_.surface.nodes(a, t)) += fe.template segment<3>(3 * a);
            }
        }
    });
    return f;
}

}  // namespace flexehd::fem
