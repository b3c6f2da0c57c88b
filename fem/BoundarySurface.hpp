#pragma once
// The triangles of a named physical surface, each with the sign that turns its
// parametric normal into the body's outward normal (Gmsh orients a triangle by its
// geometric surface, not by the volume behind it).
#include <string>
#include <vector>

#include "fem/Mesh.hpp"

namespace flexehd::fem {

class BoundarySurface {
public:
    /// Throws std::invalid_argument if the group is unknown or not a surface, and
    /// std::runtime_error if a triangle is not a face of exactly one tetrahedron.
    BoundarySurface(const Mesh& mesh, const std::string& group);
    /// The group's triangles whose centroid lies in zLow ≤ z ≤ zHigh (m, mesh frame); throws
    /// std::invalid_argument also when there is none.
    BoundarySurface(const Mesh& mesh, const std::string& group, double zLow, double zHigh);

    const std::string& name() const { return name_; }
    const std::vector<Index>& triangles() const { return triangles_; }  ///< into mesh.surface
    const std::vector<double>& orientation() const { return sign_; }   ///< +1 / -1 per triangle
    double area() const;
    const Mesh& mesh() const { return mesh_; }

private:
    const Mesh& mesh_;
    std::string name_;
    std::vector<Index> triangles_;
    std::vector<double> sign_;
};

}  // namespace flexehd::fem
