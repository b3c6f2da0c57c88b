#pragma once
// Element types flexehd supports, in Gmsh's node ordering (Gmsh reference manual,
// "Node ordering"): vertices first, then edge mid-nodes.
#include <string_view>

namespace flexehd::fem {

enum class ElementType { Tri3, Tri6, Tet4, Tet10 };

constexpr int nodesPerElement(ElementType t) {
    switch (t) {
        case ElementType::Tri3: return 3;
        case ElementType::Tri6: return 6;
        case ElementType::Tet4: return 4;
        case ElementType::Tet10: return 10;
    }
    return 0;
}

constexpr int dimension(ElementType t) {
    return (t == ElementType::Tet4 || t == ElementType::Tet10) ? 3 : 2;
}

constexpr int order(ElementType t) {
    return (t == ElementType::Tri6 || t == ElementType::Tet10) ? 2 : 1;
}

constexpr std::string_view name(ElementType t) {
    switch (t) {
        case ElementType::Tri3: return "TRI3";
        case ElementType::Tri6: return "TRI6";
        case ElementType::Tet4: return "TET4";
        case ElementType::Tet10: return "TET10";
    }
    return "?";
}

/// Edge mid-node k of a TET10 sits between vertices kTet10Edges[k-4][0] and [1]
/// (Gmsh order: 01, 12, 20, 30, 32, 31). VTK's quadratic tetra orders the last two
/// edges 13, 23, i.e. Gmsh nodes 8 and 9 are swapped there.
inline constexpr int kTet10Edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};
/// TRI6 mid-nodes: edges 01, 12, 20 (same in Gmsh and VTK).
inline constexpr int kTri6Edges[3][2] = {{0, 1}, {1, 2}, {2, 0}};

}  // namespace flexehd::fem
