#pragma once
// Calls a template lambda with the mesh's element type as a compile-time constant, so
// element loops run on fixed-size matrices: withType(t, [&]<ElementType T>() { ... }).
#include <stdexcept>

#include <Eigen/Core>

#include "fem/ElementType.hpp"
#include "fem/Mesh.hpp"

namespace flexehd::fem {

template <typename F>
decltype(auto) withType(ElementType t, F&& f) {
    switch (t) {
        case ElementType::Tet4: return f.template operator()<ElementType::Tet4>();
        case ElementType::Tet10: return f.template operator()<ElementType::Tet10>();
        case ElementType::Tri3: return f.template operator()<ElementType::Tri3>();
        case ElementType::Tri6: return f.template operator()<ElementType::Tri6>();
    }
    throw std::logic_error("unknown element type");
}

/// Coordinates of the nodes of element e of a block as a 3 x N fixed matrix.
template <int N, typename Block, typename Nodes>
Eigen::Matrix<double, 3, N> elementCoordinates(const Nodes& nodes, const Block& block, Index e) {
    Eigen::Matrix<double, 3, N> X;
    for (int a = 0; a < N; ++a) X.col(a) = nodes.col(block.nodes(a, e));
    return X;
}

}  // namespace flexehd::fem
