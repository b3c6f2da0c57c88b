#pragma once
// A Craig–Bampton reduced elastic body: everything the co-simulation (and other tools,
// through the HDF5 file, docs/reduced-body-format.md) needs to turn modal coordinates q
// into displacements u = Φ q and nodal forces f into modal forces Φᵀ f.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fem/Material.hpp"
#include "fem/Mesh.hpp"

namespace flexehd::modal {

/// How a boundary node set enters the reduction.
enum class InterfaceKind {
    Rbe2,  ///< node set tied rigidly to one 6-DOF reference node
    Rbe3,  ///< reference node follows the weighted average motion of the node set
};

struct Interface {
    std::string group;                ///< physical group of the node set
    InterfaceKind kind = InterfaceKind::Rbe2;
    Eigen::Vector3d referencePoint = Eigen::Vector3d::Zero();  ///< m
    std::vector<fem::Index> nodes;    ///< node indices of the set
};

struct ReductionSettings {
    int normalModes = 0;           ///< fixed-interface normal modes kept (after cut-off)
    double cutoffHz = 0.0;         ///< 0: none; else keep modes below this frequency
    std::vector<std::string> staticCorrection;  ///< surfaces with residual attachment modes
    std::vector<std::string> pressurePatterns;  ///< surfaces with one uniform-pressure static-correction vector each
    /// Elastic (Winkler) supports "GROUP:K", K in N/m³: springs on the surface group added to K
    /// before the reduction (docs/modal.md, "Spring and damper supports").
    std::vector<std::string> supports;
    /// Viscous supports "GROUP:C", C in N·s/m³: dashpots on the surface group, projected on the
    /// (undamped) basis into ReducedBody::supportDamping (docs/modal.md, "Spring and damper supports").
    std::vector<std::string> dampers;
    int axialOrder = 0;            ///< load patterns: Legendre degree 0..axialOrder along z
    int axialHats = 0;             ///< if > 0: this many piecewise-linear hats along z instead
    int circumferentialOrder = 0;  ///< and Fourier orders 0..circumferentialOrder in θ
    double dampingRatio = 0.0;     ///< modal damping ratio applied to elastic modes
};

struct ReducedBody {
    // Provenance.
    std::string meshPath;
    std::string meshHash;          ///< FNV-1a 64-bit of the mesh file bytes, hex
    int elementOrder = 2;
    double meshSize = 0.0;         ///< m, 0 = the file's default
    fem::ElasticMaterial material;
    ReductionSettings settings;

    fem::Mesh mesh;                ///< nodes, tetrahedra, named surfaces (for mapping and ParaView)
    std::vector<Interface> interfaces;

    // Orthonormalised basis: Φᵀ M Φ = I, Φᵀ K Φ = diag(ω²).
    Eigen::MatrixXd shapes;           ///< 3·nodes x m, dof = 3 node + component, m per unit q
    Eigen::MatrixXd massMatrix;       ///< m x m, kg (identity to round-off)
    Eigen::MatrixXd stiffnessMatrix;  ///< m x m, N/m (diagonal ω²)
    Eigen::VectorXd frequenciesHz;    ///< m, ascending
    std::vector<int> rigidBody;       ///< m flags: 1 = rigid-body mode (ω ≈ 0)
    Eigen::VectorXd dampingRatios;    ///< m, modal damping ratio ζ (0 for rigid-body modes)
    /// m x m, N·s/m: the damper supports' dashpots projected on the basis, D_s = Φᵀ C_s Φ
    /// (symmetric, not diagonal); empty (0 x 0) without dampers. The body's damping matrix is
    /// diag(2 ζ_k √K_kk) + D_s (modal::bodyDampingMatrix).
    Eigen::MatrixXd supportDamping;
    /// Motion of each interface's reference node per unit modal coordinate:
    /// rows 6i..6i+5 = (u_x, u_y, u_z, θ_x, θ_y, θ_z) of interface i, m and rad.
    Eigen::MatrixXd interfaceMotion;

    int numModes() const { return static_cast<int>(shapes.cols()); }
};

}  // namespace flexehd::modal
