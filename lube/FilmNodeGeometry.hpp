#pragma once
// FilmNodeGeometry: what the film integrals and their gradient (FilmIntegrals, FilmLoadGradient)
// need at one grid node — its area, the local frame e_r, e_θ, e_z and position, and the
// 3-point stencils of ∂p/∂z and (1/R) ∂p/∂θ (second order on the non-uniform axial spacing,
// periodic wrap, one-sided at open edges; docs/lube.md §5).
#include <Eigen/Core>

#include <cmath>

#include "lube/FilmGrid.hpp"

namespace flexehd::lube {

struct NodeFrame {
    double area;
    Eigen::Vector3d er, et, ez;  ///< outward normal of the inner body, +θ, +z
    Eigen::Vector3d position;    ///< (R cos θ, R sin θ, z)
};

inline NodeFrame nodeFrame(const FilmGrid& g, int i, int j) {
    const double th = g.theta(j), c = std::cos(th), s = std::sin(th), R = g.radius();
    return {g.area(g.index(i, j)), Eigen::Vector3d(c, s, 0.0), Eigen::Vector3d(-s, c, 0.0),
            Eigen::Vector3d(0.0, 0.0, 1.0), Eigen::Vector3d(R * c, R * s, g.z(i))};
}

/// A derivative as w_m p[m] + w_o p[o] + w_p p[p] (indices may repeat at open edges).
struct Stencil {
    int m, o, p;
    double wm, wo, wp;
    double apply(const Eigen::VectorXd& v) const { return wm * v[m] + wo * v[o] + wp * v[p]; }
};

inline Stencil axialStencil(const FilmGrid& g, int i, int j) {
    const int nz = g.nAxial(), k = g.index(i, j);
    if (i == 0) {
        const double d = g.z(1) - g.z(0);
        return {k, k, g.index(1, j), 0.0, -1.0 / d, 1.0 / d};
    }
    if (i == nz - 1) {
        const double d = g.z(i) - g.z(i - 1);
        return {g.index(i - 1, j), k, k, -1.0 / d, 1.0 / d, 0.0};
    }
    const double dm = g.z(i) - g.z(i - 1), dp = g.z(i + 1) - g.z(i), s = dm + dp;
    return {g.index(i - 1, j), k, g.index(i + 1, j), -(dp / dm) / s, (dp / dm - dm / dp) / s, (dm / dp) / s};
}

inline Stencil circumferentialStencil(const FilmGrid& g, int i, int j) {
    const int nt = g.nTheta(), k = g.index(i, j);
    const double ds = g.radius() * g.dTheta();
    if (g.periodic())
        return {g.index(i, (j + nt - 1) % nt), k, g.index(i, (j + 1) % nt), -0.5 / ds, 0.0, 0.5 / ds};
    if (j == 0) return {k, k, g.index(i, 1), 0.0, -1.0 / ds, 1.0 / ds};
    if (j == nt - 1) return {g.index(i, j - 1), k, k, -1.0 / ds, 1.0 / ds, 0.0};
    return {g.index(i, j - 1), k, g.index(i, j + 1), -0.5 / ds, 0.0, 0.5 / ds};
}

}  // namespace flexehd::lube
