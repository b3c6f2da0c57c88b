#pragma once
// The finite-element mesh as flexehd uses it: nodes, one block of volume elements
// (TET4 or TET10), one block of boundary triangles (TRI3 or TRI6), named physical
// groups. Node indices are compact (0..n-1); Gmsh's tags are kept for messages.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fem/ElementType.hpp"

namespace flexehd::fem {

using Index = std::int32_t;

/// Elements of one type; column e of `nodes` holds the node indices of element e.
struct ElementBlock {
    ElementType type = ElementType::Tet4;
    Eigen::Matrix<Index, Eigen::Dynamic, Eigen::Dynamic> nodes;  ///< nodesPerElement x count
    std::vector<std::size_t> tags;  ///< Gmsh element tags, for error messages
    Index size() const { return static_cast<Index>(nodes.cols()); }
};

/// A named physical group: `elements` index into the volume block (dim 3) or the
/// surface block (dim 2).
struct PhysicalGroup {
    std::string name;
    int dim = 3;
    std::vector<Index> elements;
};

class Mesh {
public:
    Eigen::Matrix3Xd nodes;               ///< coordinates, m
    std::vector<std::size_t> nodeTags;    ///< Gmsh node tags
    ElementBlock volume;                  ///< TET4 or TET10
    ElementBlock surface;                 ///< TRI3 or TRI6 (those in physical surfaces)
    std::map<std::string, PhysicalGroup> groups;
    std::string source;                   ///< file the mesh came from

    Index numNodes() const { return static_cast<Index>(nodes.cols()); }
    int order() const { return fem::order(volume.type); }

    bool hasGroup(const std::string& name) const { return groups.count(name) != 0; }
    /// The group, or std::invalid_argument listing the available names.
    const PhysicalGroup& group(const std::string& name) const;
    /// Sorted, unique node indices of the elements of a group.
    std::vector<Index> groupNodes(const std::string& name) const;
    /// Names of all groups, comma separated (for messages).
    std::string groupNames() const;
    /// Volume by quadrature of the element Jacobians (m^3).
    double volumeMeasure() const;

    /// Checks element orientation and shape: throws std::runtime_error naming the
    /// first inverted or degenerate element (Gmsh tag, Jacobian determinant).
    void checkElements() const;
};

}  // namespace flexehd::fem
