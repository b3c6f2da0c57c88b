#pragma once
// Pressure load patterns for static-correction (residual attachment) modes. A film
// pressure on the skirt or the bore is smooth in the axial coordinate and in the angle,
// so the patterns are a tensor basis of both:
//   p_jk(z, θ) = P_j(ζ) t_k(θ),  j = 0..axialOrder, k = 0..2·circumferentialOrder,
// P_j the Legendre polynomials in ζ = 2(z - z_mid)/(z_max - z_min) ∈ [-1, 1] over the
// surface, t_0 = 1, t_{2m-1} = cos mθ, t_{2m} = sin mθ, θ = atan2(y, x) about the
// cylinder axis z (thrust side +x at θ = 0). For loads that travel along the surface
// (the piston's film on the liner bore) global polynomials cannot resolve a local band:
// `axialHats` > 0 replaces P_j by that many piecewise-linear hat functions, evenly
// spaced over [z_min, z_max] (a partition of unity).
#include <string>

#include <Eigen/Core>

#include "fem/Mesh.hpp"

namespace flexehd::modal {

/// Nodal pressures of the patterns (numNodes x count, zero off the surface), Pa per unit.
Eigen::MatrixXd surfacePressurePatterns(const fem::Mesh& mesh, const std::string& surface, int axialOrder,
                                        int circumferentialOrder, int axialHats = 0);

}  // namespace flexehd::modal
