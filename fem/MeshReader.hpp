#pragma once
// Mesh import through the Gmsh SDK: .msh (format 2.2 and 4.1) read as stored, .geo
// meshed on load. Everything a later step needs (nodes, tetrahedra, boundary triangles
// of the physical surfaces, physical groups by name) is copied into a fem::Mesh, so no
// other part of flexehd talks to Gmsh.
#include <string>

#include "fem/Mesh.hpp"

namespace flexehd::fem {

struct MeshOptions {
    /// Element order: 1 or 2; 0 keeps a .msh file's order and meshes a .geo at order 2
    /// (slender solids need second-order tetrahedra).
    int order = 0;
    /// Target element size for .geo files in m, 0 = the file's default. Sets the
    /// file's `size` parameter (onelab "Parameters/size") and caps Mesh.MeshSizeMax.
    double size = 0.0;
    /// Run the element orientation/shape check (Mesh::checkElements) after loading.
    bool checkElements = true;
};

/// Reads or meshes `path`. Throws std::runtime_error with the file name and the reason:
/// missing file, unsupported extension or element types, no volume elements, mixed
/// element orders, inverted or degenerate elements, Gmsh's own error messages.
Mesh readMesh(const std::string& path, const MeshOptions& options = {});

/// Writes the mesh currently described by `path` (after meshing a .geo with `options`)
/// to a .msh file of the given format version (2.2 or 4.1). Used by tests and by users
/// who want to keep a meshed .geo.
void convertMesh(const std::string& path, const std::string& out, double mshVersion,
                 const MeshOptions& options = {});

}  // namespace flexehd::fem
