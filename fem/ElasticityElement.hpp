#pragma once
// Element matrices of linear isotropic elasticity on a tetrahedron:
//   K_ab,ij = ∫ [λ ∂_i N_a ∂_j N_b + μ (∂_j N_a ∂_i N_b + δ_ij ∇N_a·∇N_b)] dV,
//   M_ab,ij = ρ δ_ij ∫ N_a N_b dV,
//   f_a,i   = (3λ + 2μ) α ∫ ΔT ∂_i N_a dV        (thermal strain α ΔT on the diagonal).
// Quadrature: stiffness exact for straight-sided elements (degree 0 / 2 integrand for
// TET4 / TET10, 1- and 4-point rules); mass and thermal load degree 2 / 4 (4- and
// 14-point rules). Local DOF ordering is node-major: 3a + i.
#include <Eigen/Core>

#include "fem/ShapeFunctions.hpp"

namespace flexehd::fem {

template <ElementType T>
struct ElasticityElement {
    static constexpr int kNodes = Shape<T>::kNodes;
    static constexpr int kDofs = 3 * kNodes;
    using Coordinates = Eigen::Matrix<double, 3, kNodes>;
    using Matrix = Eigen::Matrix<double, kDofs, kDofs>;
    using Vector = Eigen::Matrix<double, kDofs, 1>;
    using NodalScalar = Eigen::Matrix<double, kNodes, 1>;

    static void stiffness(const Coordinates& X, double lambda, double mu, Matrix& K);
    static void mass(const Coordinates& X, double rho, Matrix& M);
    /// `factor` = (3λ + 2μ) α; `dT` nodal temperature rise T - T_ref.
    static void thermalLoad(const Coordinates& X, const NodalScalar& dT, double factor, Vector& f);
};

extern template struct ElasticityElement<ElementType::Tet4>;
extern template struct ElasticityElement<ElementType::Tet10>;

}  // namespace flexehd::fem
