#pragma once
// Integrals over a boundary triangle (TRI3 / TRI6, possibly curved) embedded in 3-D.
// With x(ξ, η) the mapped point, n dA = (∂x/∂ξ × ∂x/∂η) dξ dη; `sign` = ±1 turns that
// into the outward normal of the body (see BoundarySurface).
#include <Eigen/Core>

#include "fem/ShapeFunctions.hpp"

namespace flexehd::fem {

template <ElementType T>
struct SurfaceElement {
    static constexpr int kNodes = Shape<T>::kNodes;
    using Coordinates = Eigen::Matrix<double, 3, kNodes>;
    using Matrix = Eigen::Matrix<double, kNodes, kNodes>;
    using Vector = Eigen::Matrix<double, kNodes, 1>;
    using NodalVector = Eigen::Matrix<double, 3 * kNodes, 1>;

    static double area(const Coordinates& X);
    /// ∫ h N_a N_b dA: convection (Robin) matrix.
    static void massLike(const Coordinates& X, double h, Matrix& H);
    /// ∫ q N_a dA: consistent nodal values of a uniform flux density q.
    static void flux(const Coordinates& X, double q, Vector& f);
    /// -p ∫ N_a n dA (outward n = sign × the parametric normal): nodal forces of a uniform
    /// pressure p acting on the body.
    static void pressure(const Coordinates& X, double p, double sign, NodalVector& f);
    /// The same for a pressure interpolated from nodal values p(ξ) = Σ N_a p_a.
    static void pressure(const Coordinates& X, const Vector& p, double sign, NodalVector& f);
};

extern template struct SurfaceElement<ElementType::Tri3>;
extern template struct SurfaceElement<ElementType::Tri6>;

}  // namespace flexehd::fem
