#pragma once
// Quadrature rules on the reference simplices. Points are barycentric-free reference
// coordinates (xi, eta[, zeta]); weights sum to the reference measure (1/2 triangle,
// 1/6 tetrahedron).
#include <vector>

#include <Eigen/Core>

namespace flexehd::fem {

struct QuadraturePoint {
    Eigen::Vector3d xi;  ///< reference coordinates (zeta = 0 on triangles)
    double weight;
};

using QuadratureRule = std::vector<QuadraturePoint>;

/// Tetrahedron rule exact for polynomials of total degree <= `degree`: 1 point (degree 1),
/// 4 points (degree 2), 14 points (degree 5, all weights positive; Walkington 2000).
/// Degrees 3 and 4 use the 14-point rule: the classical 5- and 11-point rules have a
/// negative weight, which spoils the positivity of consistent mass matrices.
const QuadratureRule& tetrahedronRule(int degree);

/// Triangle rule exact for total degree <= `degree`: 1, 3 or 6 points (degrees 1, 2, 4;
/// Dunavant 1985). Degree 3 uses the 6-point rule.
const QuadratureRule& triangleRule(int degree);

}  // namespace flexehd::fem
