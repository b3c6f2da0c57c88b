#include "fem/Quadrature.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace flexehd::fem {
namespace {

// Adds the points of a symmetric orbit given by barycentric coordinates; the reference
// coordinates are the last three barycentrics (the first is 1 - xi - eta - zeta).
void addTetOrbit(QuadratureRule& rule, std::array<double, 4> bary, double w) {
    std::sort(bary.begin(), bary.end());
    do {
        rule.push_back({Eigen::Vector3d(bary[1], bary[2], bary[3]), w});
    } while (std::next_permutation(bary.begin(), bary.end()));
}

void addTriOrbit(QuadratureRule& rule, std::array<double, 3> bary, double w) {
    std::sort(bary.begin(), bary.end());
    do {
        rule.push_back({Eigen::Vector3d(bary[1], bary[2], 0.0), w});
    } while (std::next_permutation(bary.begin(), bary.end()));
}

QuadratureRule makeTet(int points) {
    QuadratureRule r;
    if (points == 1) {
        addTetOrbit(r, {0.25, 0.25, 0.25, 0.25}, 1.0 / 6.0);
    } else if (points == 4) {
        const double a = 0.1381966011250105, b = 1.0 - 3.0 * a;  // (5 - sqrt 5) / 20
        addTetOrbit(r, {a, a, a, b}, 1.0 / 24.0);
    } else {
        // 14-point, degree 5 (weights for reference volume 1/6).
        const double a = 0.0927352503108912, b = 0.3108859192633006;
        const double c = 0.4544962958743504, d = 0.5 - c;
        addTetOrbit(r, {a, a, a, 1.0 - 3.0 * a}, 0.01224884051939366);
        addTetOrbit(r, {b, b, b, 1.0 - 3.0 * b}, 0.01878132095300264);
        addTetOrbit(r, {c, c, d, d}, 0.007091003462846911);
    }
    return r;
}

QuadratureRule makeTri(int points) {
    QuadratureRule r;
    if (points == 1) {
        addTriOrbit(r, {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0}, 0.5);
    } else if (points == 3) {
        addTriOrbit(r, {1.0 / 6.0, 1.0 / 6.0, 2.0 / 3.0}, 1.0 / 6.0);
    } else {
        // Dunavant degree 4 (weights normalised to area 1, halved for the reference area).
        const double a = 0.445948490915965, b = 0.091576213509771;
        addTriOrbit(r, {a, a, 1.0 - 2.0 * a}, 0.5 * 0.223381589678011);
        addTriOrbit(r, {b, b, 1.0 - 2.0 * b}, 0.5 * 0.109951743655322);
    }
    return r;
}

}  // namespace

const QuadratureRule& tetrahedronRule(int degree) {
    static const QuadratureRule r1 = makeTet(1), r4 = makeTet(4), r14 = makeTet(14);
    if (degree < 0 || degree > 5)
        throw std::invalid_argument("tetrahedronRule: degree " + std::to_string(degree) +
                                    " not available (0..5)");
    return degree <= 1 ? r1 : degree == 2 ? r4 : r14;
}

const QuadratureRule& triangleRule(int degree) {
    static const QuadratureRule r1 = makeTri(1), r3 = makeTri(3), r6 = makeTri(6);
    if (degree < 0 || degree > 4)
        throw std::invalid_argument("triangleRule: degree " + std::to_string(degree) +
                                    " not available (0..4)");
    return degree <= 1 ? r1 : degree == 2 ? r3 : r6;
}

}  // namespace flexehd::fem
