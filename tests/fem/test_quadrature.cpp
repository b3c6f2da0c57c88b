// Quadrature exactness against the closed-form simplex moments
//   ∫_T x^a y^b z^c dV = a! b! c! / (a+b+c+3)!,   ∫_T x^a y^b dA = a! b! / (a+b+2)!.
#include <cmath>

#include <gtest/gtest.h>

#include "fem/Quadrature.hpp"

using namespace flexehd::fem;

namespace {
double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

double integrate(const QuadratureRule& rule, int a, int b, int c) {
    double s = 0.0;
    for (const auto& q : rule) s += q.weight * std::pow(q.xi(0), a) * std::pow(q.xi(1), b) * std::pow(q.xi(2), c);
    return s;
}
}  // namespace

TEST(Quadrature, TetrahedronRulesExactToTheirDegree) {
    for (int degree : {1, 2, 5}) {
        const auto& rule = tetrahedronRule(degree);
        for (int a = 0; a <= degree; ++a)
            for (int b = 0; a + b <= degree; ++b)
                for (int c = 0; a + b + c <= degree; ++c) {
                    const double exact = factorial(a) * factorial(b) * factorial(c) / factorial(a + b + c + 3);
                    EXPECT_NEAR(integrate(rule, a, b, c), exact, 1e-14) << "degree " << degree << " monomial "
                                                                         << a << b << c;
                }
    }
}

TEST(Quadrature, TetrahedronDegreeFiveRuleIsNotExactForDegreeSix) {
    // Guards against a rule silently swapped for a higher one (or the test being vacuous).
    const double exact = factorial(6) / factorial(9);
    EXPECT_GT(std::abs(integrate(tetrahedronRule(5), 6, 0, 0) - exact), 1e-8);
}

TEST(Quadrature, TriangleRulesExactToTheirDegree) {
    for (int degree : {1, 2, 4}) {
        const auto& rule = triangleRule(degree);
        for (int a = 0; a <= degree; ++a)
            for (int b = 0; a + b <= degree; ++b) {
                const double exact = factorial(a) * factorial(b) / factorial(a + b + 2);
                EXPECT_NEAR(integrate(rule, a, b, 0), exact, 1e-14) << "degree " << degree;
            }
    }
}

TEST(Quadrature, PositiveWeights) {
    for (int d : {1, 2, 5})
        for (const auto& q : tetrahedronRule(d)) EXPECT_GT(q.weight, 0.0);
    for (int d : {1, 2, 4})
        for (const auto& q : triangleRule(d)) EXPECT_GT(q.weight, 0.0);
}
