#include "fem/HeatElement.hpp"

#include <Eigen/LU>

#include "fem/Quadrature.hpp"

namespace flexehd::fem {

template <ElementType T>
void HeatElement<T>::conductivity(const Coordinates& X, double k, Matrix& K) {
    K.setZero();
    for (const auto& q : tetrahedronRule(T == ElementType::Tet4 ? 1 : 2)) {
        const auto dN = Shape<T>::dN(q.xi);
        const Eigen::Matrix3d J = X * dN;
        const Eigen::Matrix<double, kNodes, 3> G = dN * J.inverse();
        K.noalias() += (q.weight * J.determinant() * k) * G * G.transpose();
    }
}

template struct HeatElement<ElementType::Tet4>;
template struct HeatElement<ElementType::Tet10>;

}  // namespace flexehd::fem
