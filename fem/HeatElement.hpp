#pragma once
// Steady heat conduction on a tetrahedron: K_ab = k ∫ ∇N_a·∇N_b dV (degree 0 / 2
// integrand for TET4 / TET10: 1- and 4-point rules).
#include <Eigen/Core>

#include "fem/ShapeFunctions.hpp"

namespace flexehd::fem {

template <ElementType T>
struct HeatElement {
    static constexpr int kNodes = Shape<T>::kNodes;
    using Coordinates = Eigen::Matrix<double, 3, kNodes>;
    using Matrix = Eigen::Matrix<double, kNodes, kNodes>;
    static void conductivity(const Coordinates& X, double k, Matrix& K);
};

extern template struct HeatElement<ElementType::Tet4>;
extern template struct HeatElement<ElementType::Tet10>;

}  // namespace flexehd::fem
