#pragma once
// LoadMapping: conservative transfer of film pressure from the lubrication grid to the nodes
// of a structural surface (seed paper §3.1;
// docs/mapping.md).
//
// The grid pressure is bilinear on each grid cell of the parameter plane (z, θ). The nodal
// forces on the body are the consistent loads
//     F_j = −∫ p N_j n_out dA,   n_out = σ (cos θ, sin θ, 0),   dA = R dz dθ,
// with R the grid radius and σ = +1 when the body lies inside the cylinder (piston skirt),
// σ = −1 when it lies outside (liner bore: the film pushes the liner outward). N_j are the
// triangle's shape functions on the straight parameter-plane image of its vertices (affine
// map, so N_j is polynomial in (z, θ)). The integral is evaluated on the common refinement:
// each triangle image is clipped against the grid cells it overlaps (Sutherland–Hodgman),
// and each convex piece is fan-triangulated and integrated with a collapsed (Duffy)
// Gauss–Legendre rule. Its order is chosen from the grid's cell width so that the truncation
// of cos θ / sin θ is below 1e-17: the polynomial part (bilinear × quadratic = degree 4) is
// exact and the force and the moment about any point on the axis equal those of the bilinear
// source field on the ideal cylinder to round-off. Built once; applying is one sparse product.
// Optionally the same for the tangential (shear) tractions along e_z and e_θ.
#include <string>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "fem/BoundarySurface.hpp"
#include "fem/Mesh.hpp"
#include "lube/FilmGrid.hpp"

namespace flexehd::cosim {

struct LoadMappingOptions {
    /// Axial position of the grid in the body frame: body z = grid z + axialOffset (m).
    /// 0 for the piston (grid fixed to it); the piston position for the liner.
    double axialOffset = 0.0;
    /// Largest accepted relative spread (max − min) / mean of the surface-node radii.
    double radiusTolerance = 1e-3;
    /// Also build the shear-traction operators (axialShear(), circumferentialShear()).
    bool shear = false;
};

/// What the setup found; the geometric (faceting) error is reported, not corrected.
/// How many triangles of a body's cylindrical surface face away from the axis (the body inside
/// the cylinder: a skirt) and towards it (the body outside: a bore), from their outward normals.
struct CylinderSides {
    int away = 0;
    int towards = 0;
};
CylinderSides cylinderSides(const fem::Mesh& mesh, const fem::BoundarySurface& surface);

struct LoadMappingStats {
    double surfaceRadius = 0.0;   ///< mean radius of the surface nodes (m)
    double radiusSpread = 0.0;    ///< (max − min) / mean of the node radii
    double outward = 0.0;         ///< σ: +1 body inside the cylinder (skirt), −1 outside (bore)
    double gridArea = 0.0;        ///< R × parameter area of the grid (m²)
    double coveredArea = 0.0;     ///< R × parameter area of grid ∩ surface (m²)
    int fragments = 0;            ///< convex pieces of the common refinement
    int quadratureOrder = 0;      ///< Gauss–Legendre points per direction of the collapsed rule
    /// Σ_t |∫_t n dA (curved FE triangle) − ∫_t n dA (cylinder of radius surfaceRadius over the
    /// triangle's parameter image)| / surface area: how far the FE surface is from the
    /// cylinder the mapping integrates on.
    double facetingError = 0.0;
    /// Largest distance (m) of a TRI6 mid-node's (z, R θ) image from the midpoint of its edge's
    /// vertex images; the affine parameter map assumes it is zero.
    double midNodeOffset = 0.0;
};

class LoadMapping {
public:
    /// Throws std::invalid_argument naming the surface if it is unknown, not cylindrical about
    /// z within options.radiusTolerance, faces the film from both sides, or does not overlap
    /// the grid; std::runtime_error if a triangle spans half a turn or more.
    LoadMapping(const fem::Mesh& mesh, const std::string& surface, const lube::FilmGrid& grid,
                const LoadMappingOptions& options = {});

    /// 3 × mesh nodes rows (dof = 3 node + component, the body's numbering) × grid nodes.
    const Eigen::SparseMatrix<double>& matrix() const { return A_; }
    /// Nodal forces on the body (N) of nodal grid pressures p (Pa, gauge: pass p − ambient).
    Eigen::VectorXd apply(const Eigen::VectorXd& p) const;
    void apply(const Eigen::VectorXd& p, Eigen::VectorXd& forces) const;

    /// Shear tractions (options.shear): τ_z along e_z and τ_θ along e_θ = (−sin θ, cos θ, 0),
    /// Pa, the traction the film exerts on the body, bilinear on the grid cells like p:
    ///     F_j = ∫ N_j τ_z e_z dA,   F_j = ∫ N_j τ_θ e_θ dA,
    /// on the same common refinement and rule (exact force; same shapes as matrix()).
    /// Empty (0 × 0) unless options.shear.
    const Eigen::SparseMatrix<double>& axialShear() const { return Sz_; }
    const Eigen::SparseMatrix<double>& circumferentialShear() const { return St_; }
    /// Nodal forces of both shear fields: Sz τ_z + Sθ τ_θ (either may be empty: skipped).
    Eigen::VectorXd applyShear(const Eigen::VectorXd& tauZ, const Eigen::VectorXd& tauTheta) const;

    const LoadMappingStats& stats() const { return stats_; }
    const std::string& surface() const { return surface_; }

private:
    std::string surface_;
    Eigen::SparseMatrix<double> A_, Sz_, St_;
    LoadMappingStats stats_;
};

}  // namespace flexehd::cosim
