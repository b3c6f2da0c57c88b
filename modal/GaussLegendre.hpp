#pragma once
// Gauss–Legendre quadrature on [0, 1]: the n nodes are the roots of the Legendre polynomial P_n
// (mapped from [−1, 1]), found by Newton's method, and the weights 1/((1 − t²) P_n'(t)²)
// (Abramowitz & Stegun, Handbook of Mathematical Functions, 1964, 25.4.29). The rule integrates
// polynomials of degree ≤ 2n − 1 exactly; for a function analytic in an ellipse about the
// interval its error falls geometrically with n (Davis & Rabinowitz, Methods of Numerical
// Integration, 2nd ed., 1984, §4.6).
#include <vector>

namespace flexehd::modal {

struct QuadratureRule {
    std::vector<double> nodes;    ///< in (0, 1), descending
    std::vector<double> weights;  ///< sum to 1
};

/// The n-point rule on [0, 1]; throws std::invalid_argument for n < 1.
QuadratureRule gaussLegendre(int n);

}  // namespace flexehd::modal
