#include "fem/ElasticityElement.hpp"

#include <Eigen/LU>

#include "fem/Quadrature.hpp"

namespace flexehd::fem {

template <ElementType T>
void ElasticityElement<T>::stiffness(const Coordinates& X, double lambda, double mu, Matrix& K) {
    K.setZero();
    const auto& rule = tetrahedronRule(T == ElementType::Tet4 ? 1 : 2);
    for (const auto& q : rule) {
        const auto dN = Shape<T>::dN(q.xi);
        const Eigen::Matrix3d J = X * dN;
        const double w = q.weight * J.determinant();
        const Eigen::Matrix<double, kNodes, 3> G = dN * J.inverse();  // physical gradients
        for (int b = 0; b < kNodes; ++b)
            for (int a = 0; a < kNodes; ++a) {
                const double dot = mu * G.row(a).dot(G.row(b));
                auto Kab = K.template block<3, 3>(3 * a, 3 * b);
                Kab.noalias() += w * (lambda * G.row(a).transpose() * G.row(b) +
                                      mu * G.row(b).transpose() * G.row(a));
                Kab.diagonal().array() += w * dot;
            }
    }
}

template <ElementType T>
void ElasticityElement<T>::mass(const Coordinates& X, double rho, Matrix& M) {
    Eigen::Matrix<double, kNodes, kNodes> m = Eigen::Matrix<double, kNodes, kNodes>::Zero();
    for (const auto& q : tetrahedronRule(T == ElementType::Tet4 ? 2 : 5)) {
        const double w = q.weight * (X * Shape<T>::dN(q.xi)).determinant();
        const auto N = Shape<T>::N(q.xi);
        m.noalias() += (w * rho) * N * N.transpose();
    }
    M.setZero();
    for (int b = 0; b < kNodes; ++b)
        for (int a = 0; a < kNodes; ++a)
            for (int i = 0; i < 3; ++i) M(3 * a + i, 3 * b + i) = m(a, b);
}

template <ElementType T>
void ElasticityElement<T>::thermalLoad(const Coordinates& X, const NodalScalar& dT, double factor,
                                       Vector& f) {
    f.setZero();
    for (const auto& q : tetrahedronRule(T == ElementType::Tet4 ? 1 : 5)) {
        const auto dN = Shape<T>::dN(q.xi);
        const Eigen::Matrix3d J = X * dN;
        const double w = q.weight * J.determinant() * factor * Shape<T>::N(q.xi).dot(dT);
        const Eigen::Matrix<double, kNodes, 3> G = dN * J.inverse();
        for (int a = 0; a < kNodes; ++a) f.template segment<3>(3 * a) += w * G.row(a).transpose();
    }
}

template struct ElasticityElement<ElementType::Tet4>;
template struct ElasticityElement<ElementType::Tet10>;

}  // namespace flexehd::fem
