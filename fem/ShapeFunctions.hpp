#pragma once
// Lagrange shape functions of the simplex elements, in Gmsh node order, written in
// barycentric coordinates: linear N_i = L_i; quadratic vertices L_i(2L_i - 1), edge
// mid-nodes 4 L_i L_j (Zienkiewicz & Taylor, Vol. 1, §6.8).
#include <Eigen/Core>

#include "fem/ElementType.hpp"

namespace flexehd::fem {

template <ElementType T>
struct Shape;

namespace detail {
// Barycentrics of a simplex of dimension D from reference coordinates, and their
// (constant) reference gradients: L_0 = 1 - sum(xi), L_k = xi_k.
template <int D>
inline Eigen::Matrix<double, D + 1, 1> barycentric(const Eigen::Vector3d& xi) {
    Eigen::Matrix<double, D + 1, 1> L;
    L(0) = 1.0 - xi.head<D>().sum();
    L.template tail<D>() = xi.head<D>();
    return L;
}
template <int D>
inline Eigen::Matrix<double, D + 1, D> barycentricGradient() {
    Eigen::Matrix<double, D + 1, D> g;
    g.row(0).setConstant(-1.0);
    g.template bottomRows<D>().setIdentity();
    return g;
}

template <int D, int NV, int NE>
struct QuadraticSimplex {
    static constexpr int kNodes = NV + NE;
    using Values = Eigen::Matrix<double, kNodes, 1>;
    using Gradients = Eigen::Matrix<double, kNodes, D>;
    template <typename Edges>
    static Values N(const Eigen::Vector3d& xi, const Edges& edges) {
        const auto L = barycentric<D>(xi);
        Values n;
        for (int v = 0; v < NV; ++v) n(v) = L(v) * (2.0 * L(v) - 1.0);
        for (int e = 0; e < NE; ++e) n(NV + e) = 4.0 * L(edges[e][0]) * L(edges[e][1]);
        return n;
    }
    template <typename Edges>
    static Gradients dN(const Eigen::Vector3d& xi, const Edges& edges) {
        const auto L = barycentric<D>(xi);
        const auto g = barycentricGradient<D>();
        Gradients d;
        for (int v = 0; v < NV; ++v) d.row(v) = (4.0 * L(v) - 1.0) * g.row(v);
        for (int e = 0; e < NE; ++e) {
            const int i = edges[e][0], j = edges[e][1];
            d.row(NV + e) = 4.0 * (L(j) * g.row(i) + L(i) * g.row(j));
        }
        return d;
    }
};
}  // namespace detail

template <>
struct Shape<ElementType::Tet4> {
    static constexpr int kNodes = 4, kDim = 3;
    using Values = Eigen::Matrix<double, 4, 1>;
    using Gradients = Eigen::Matrix<double, 4, 3>;
    static Values N(const Eigen::Vector3d& xi) { return detail::barycentric<3>(xi); }
    static Gradients dN(const Eigen::Vector3d&) { return detail::barycentricGradient<3>(); }
};

template <>
struct Shape<ElementType::Tet10> {
    static constexpr int kNodes = 10, kDim = 3;
    using Q = detail::QuadraticSimplex<3, 4, 6>;
    using Values = Q::Values;
    using Gradients = Q::Gradients;
    static Values N(const Eigen::Vector3d& xi) { return Q::N(xi, kTet10Edges); }
    static Gradients dN(const Eigen::Vector3d& xi) { return Q::dN(xi, kTet10Edges); }
};

template <>
struct Shape<ElementType::Tri3> {
    static constexpr int kNodes = 3, kDim = 2;
    using Values = Eigen::Matrix<double, 3, 1>;
    using Gradients = Eigen::Matrix<double, 3, 2>;
    static Values N(const Eigen::Vector3d& xi) { return detail::barycentric<2>(xi); }
    static Gradients dN(const Eigen::Vector3d&) { return detail::barycentricGradient<2>(); }
};

template <>
struct Shape<ElementType::Tri6> {
    static constexpr int kNodes = 6, kDim = 2;
    using Q = detail::QuadraticSimplex<2, 3, 3>;
    using Values = Q::Values;
    using Gradients = Q::Gradients;
    static Values N(const Eigen::Vector3d& xi) { return Q::N(xi, kTri6Edges); }
    static Gradients dN(const Eigen::Vector3d& xi) { return Q::dN(xi, kTri6Edges); }
};

/// Reference coordinates of the nodes of a tetrahedron type (Gmsh order), 3 x nodes.
Eigen::Matrix3Xd referenceNodes(ElementType t);

}  // namespace flexehd::fem
