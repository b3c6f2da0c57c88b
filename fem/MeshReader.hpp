#pragma once
// Mesh import through the Gmsh SDK: .msh (format 2.2 and 4.1) read as stored, .geo
// meshed on load. Everything a later step needs (nodes, tetrahedra, boundary triangles
// of the physical surfaces, physical groups by name) is copied into a fem::Mesh, so no
// other part of flexehd talks to Gmsh.
#include <functional>
#include <string>

#include "fem/Mesh.hpp"

namespace flexehd::fem {

/// What meshing a .geo file is expected to give, estimated from its geometry before meshing:
/// tetrahedra ≈ V / (h³/(6√2)) · kV + triangles · kF, boundary triangles ≈ A / (√3 h²/4) · kA,
/// nodes from Euler's relation for a tetrahedral mesh (docs/meshes.md, "Estimate before meshing").
struct MeshEstimate {
    std::string path;
    double size = 0.0;        ///< m, the element size the file will be meshed at (Mesh.MeshSizeMax)
    int order = 2;            ///< element order of the nodes counted
    double volume = 0.0;      ///< m³ of the 3-D entities (OpenCASCADE: exact; built-in kernel: bounding boxes)
    double area = 0.0;        ///< m² of their boundary
    double tetrahedra = 0.0;  ///< expected volume elements
    double triangles = 0.0;   ///< expected boundary triangles
    double nodes = 0.0;       ///< expected nodes at `order`
};

/// The estimate for a geometry of `volume` (m³) and boundary `area` (m²) meshed at `size` (m).
MeshEstimate estimateMesh(double volume, double area, double size, int order);

/// The smallest size (m) at which estimateMesh(volume, area, size, order).nodes ≤ maxNodes.
double sizeForNodes(double volume, double area, double maxNodes, int order);

struct MeshOptions {
    /// Element order: 1 or 2; 0 keeps a .msh file's order and meshes a .geo at order 2
    /// (slender solids need second-order tetrahedra).
    int order = 0;
    /// Target element size for .geo files in m, 0 = the file's default. Sets the
    /// file's `size` parameter (onelab "Parameters/size") and caps Mesh.MeshSizeMax.
    double size = 0.0;
    /// Run the element orientation/shape check (Mesh::checkElements) after loading.
    bool checkElements = true;
    /// .geo only: called with the estimate after the geometry is built and before Gmsh meshes
    /// it (a progress line; throw to refuse a size too fine to mesh).
    std::function<void(const MeshEstimate&)> beforeMeshing;
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
