#include "fem/SurfaceElement.hpp"

#include <Eigen/Geometry>

#include "fem/Quadrature.hpp"

namespace flexehd::fem {
namespace {
template <ElementType T>
Eigen::Vector3d parametricNormal(const Eigen::Matrix<double, 3, Shape<T>::kNodes>& X,
                                 const Eigen::Vector3d& xi) {
    const Eigen::Matrix<double, 3, 2> t = X * Shape<T>::dN(xi);
    return t.col(0).cross(t.col(1));
}
// Products N_a N_b are degree 2 / 4 for TRI3 / TRI6: exact on flat triangles; on curved
// TRI6 the area element adds a smooth factor that the degree-4 rule integrates well.
template <ElementType T>
const QuadratureRule& rule() {
    return triangleRule(T == ElementType::Tri3 ? 2 : 4);
}
}  // namespace

template <ElementType T>
double SurfaceElement<T>::area(const Coordinates& X) {
    double a = 0.0;
    for (const auto& q : rule<T>()) a += q.weight * parametricNormal<T>(X, q.xi).norm();
    return a;
}

template <ElementType T>
void SurfaceElement<T>::massLike(const Coordinates& X, double h, Matrix& H) {
    H.setZero();
    for (const auto& q : rule<T>()) {
        const auto N = Shape<T>::N(q.xi);
        H.noalias() += (q.weight * h * parametricNormal<T>(X, q.xi).norm()) * N * N.transpose();
    }
}

template <ElementType T>
void SurfaceElement<T>::flux(const Coordinates& X, double qf, Vector& f) {
    f.setZero();
    for (const auto& q : rule<T>())
        f += (q.weight * qf * parametricNormal<T>(X, q.xi).norm()) * Shape<T>::N(q.xi);
}

template <ElementType T>
void SurfaceElement<T>::pressure(const Coordinates& X, double p, double sign, NodalVector& f) {
    f.setZero();
    for (const auto& q : rule<T>()) {
        const Eigen::Vector3d n = (-p * sign * q.weight) * parametricNormal<T>(X, q.xi);
        const auto N = Shape<T>::N(q.xi);
        for (int a = 0; a < kNodes; ++a) f.template segment<3>(3 * a) += N(a) * n;
    }
}

template <ElementType T>
void SurfaceElement<T>::pressure(const Coordinates& X, const Vector& p, double sign, NodalVector& f) {
    f.setZero();
    for (const auto& q : rule<T>()) {
        const auto N = Shape<T>::N(q.xi);
        const Eigen::Vector3d n = (-N.dot(p) * sign * q.weight) * parametricNormal<T>(X, q.xi);
        for (int a = 0; a < kNodes; ++a) f.template segment<3>(3 * a) += N(a) * n;
    }
}

template struct SurfaceElement<ElementType::Tri3>;
template struct SurfaceElement<ElementType::Tri6>;

}  // namespace flexehd::fem
