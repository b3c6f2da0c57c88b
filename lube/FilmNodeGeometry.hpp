#pragma once
// FilmNodeGeometry: what the film integrals and their gradient (FilmIntegrals, FilmLoadGradient)
// need at one grid node — its area, the local frame e_r, e_θ, e_z and position, and the
// 3-point stencils of ∂p/∂z and (1/R) ∂p/∂θ (second order on the non-uniform axial spacing,
// periodic wrap, one-sided at open edges; docs/lube.md §5), and the squares of these derivatives
// as the dissipation integral needs them.
#include <Eigen/Core>

#include <cmath>

#include "lube/FilmGrid.hpp"

namespace flexehd::lube {

struct NodeFrame {
    double area;         ///< control volume (the pressure's weight)
    double surfaceArea;  ///< surface the node stands for (contact, shear; FilmGrid::surfaceArea)
    Eigen::Vector3d er, et, ez;  ///< outward normal of the inner body, +θ, +z
    Eigen::Vector3d position;    ///< (R cos θ, R sin θ, z)
};

inline NodeFrame nodeFrame(const FilmGrid& g, int i, int j) {
    const double c = g.cosTheta(j), s = g.sinTheta(j), R = g.radius();
    return {g.area(g.index(i, j)), g.surfaceArea(g.index(i, j)), Eigen::Vector3d(c, s, 0.0), Eigen::Vector3d(-s, c, 0.0),
            Eigen::Vector3d(0.0, 0.0, 1.0), Eigen::Vector3d(R * c, R * s, g.z(i))};
}

/// A derivative as w_m p[m] + w_o p[o] + w_p p[p] (indices may repeat at open edges).
struct Stencil {
    int m, o, p;
    double wm, wo, wp;
    double apply(const Eigen::VectorXd& v) const { return wm * v[m] + wo * v[o] + wp * v[p]; }
};

/// The one-sided differences at an open edge and the second-order 3-point difference with
/// node spacings dm (to m) and dp (to p).
inline Stencil forwardDifference(int o, int p, double d) { return {o, o, p, 0.0, -1.0 / d, 1.0 / d}; }
inline Stencil backwardDifference(int m, int o, double d) { return {m, o, o, -1.0 / d, 1.0 / d, 0.0}; }
inline Stencil threePointDifference(int m, int o, int p, double dm, double dp) {
    const double s = dm + dp;
    return {m, o, p, -(dp / dm) / s, (dp / dm - dm / dp) / s, (dm / dp) / s};
}

inline Stencil axialStencil(const FilmGrid& g, int i, int j) {
    const int nz = g.nAxial(), k = g.index(i, j);
    if (i == 0) return forwardDifference(k, g.index(1, j), g.z(1) - g.z(0));
    if (i == nz - 1) return backwardDifference(g.index(i - 1, j), k, g.z(i) - g.z(i - 1));
    return threePointDifference(g.index(i - 1, j), k, g.index(i + 1, j), g.z(i) - g.z(i - 1), g.z(i + 1) - g.z(i));
}

/// (1/R) ∂p/∂θ: the non-uniform 3-point stencil when a neighbour is an arc end's Void column
/// (at FilmGrid::faceAngle, where the pressure is ambient), central otherwise.
inline Stencil circumferentialStencil(const FilmGrid& g, int i, int j) {
    const int nt = g.nTheta(), k = g.index(i, j);
    const double R = g.radius();
    if (!g.periodic() && j == 0) return forwardDifference(k, g.index(i, 1), R * g.faceAngle(0));
    if (!g.periodic() && j == nt - 1) return backwardDifference(g.index(i, j - 1), k, R * g.faceAngle(j - 1));
    const int jm = (j + nt - 1) % nt, jp = (j + 1) % nt;
    const double dm = R * g.faceAngle(jm), dp = R * g.faceAngle(j);
    if (dm == dp) return {g.index(i, jm), k, g.index(i, jp), -0.5 / dp, 0.0, 0.5 / dp};
    return threePointDifference(g.index(i, jm), k, g.index(i, jp), dm, dp);
}

/// A squared derivative over a node's control volume: the squares of the one-sided differences
/// to m (spacing dm) and to p (spacing dp), weighted by the parts wm and wp of the surface the
/// node stands for on each side. Second order where the field is smooth, like the square of the
/// 3-point difference, and also where the derivative jumps at the node (film reformation after
/// a cavitated zone), where the square of the central difference would take (½ jump)² for the
/// mean of the squares.
inline double squaredDerivative(double vm, double vo, double vp, double dm, double dp, double wm, double wp) {
    const double gm = (vo - vm) / dm, gp = (vp - vo) / dp;
    return (wm * gm * gm + wp * gp * gp) / (wm + wp);
}

/// (∂p/∂z)² at node (i, j): one-sided at the open axial edges.
inline double axialDerivativeSquared(const FilmGrid& g, int i, int j, const Eigen::VectorXd& v) {
    const int nz = g.nAxial();
    if (i == 0 || i == nz - 1) {
        const double d = axialStencil(g, i, j).apply(v);
        return d * d;
    }
    const double dm = g.z(i) - g.z(i - 1), dp = g.z(i + 1) - g.z(i);
    return squaredDerivative(v[g.index(i - 1, j)], v[g.index(i, j)], v[g.index(i + 1, j)], dm, dp, dm, dp);
}

/// ((1/R) ∂p/∂θ)² at node (i, j): one-sided at the ends of an open arc; a column cut by an arc
/// end weights the side towards the end by the strip it covers there.
inline double circumferentialDerivativeSquared(const FilmGrid& g, int i, int j, const Eigen::VectorXd& v) {
    const int nt = g.nTheta();
    if (!g.periodic() && (j == 0 || j == nt - 1)) {
        const double d = circumferentialStencil(g, i, j).apply(v);
        return d * d;
    }
    const int jm = (j + nt - 1) % nt, jp = (j + 1) % nt;
    const double R = g.radius(), below = g.coveredWidthBelow(j);
    return squaredDerivative(v[g.index(i, jm)], v[g.index(i, j)], v[g.index(i, jp)], R * g.faceAngle(jm),
                             R * g.faceAngle(j), below, g.coveredAngularWidth(j) - below);
}

}  // namespace flexehd::lube
