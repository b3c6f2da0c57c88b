#pragma once
// FlexibleSurface: a reduced elastic body seen from the film (docs/coupling.md): the quasi-static
// modal response to the film pressure and the resulting change of film thickness on the grid.
//
//   q = C Φᵀ A p,   Δh = σ D_r Φ q
// with A the conservative load mapping, D_r the radial deformation mapping (the body's
// SurfaceMapping: PistonSurfaceMapping, whose grid is fixed to the body; LinerSurfaceMapping,
// along which the grid slides),
// C = N (Nᵀ K_r N)⁻¹ Nᵀ the compliance with the held interfaces' reference nodes fixed (FlexibleBody,
// shared by every surface of the body; computed once), and σ = −1 for the piston
// (outward skirt displacement closes the gap), +1 for the liner (outward bore displacement opens it).
// The products run over the grid nodes that carry film only (the non-Void nodes; for the liner the
// θ columns holding one): Void nodes get no load (ambient gauge pressure) and no elastic Δh.
// Every call costs O(film nodes × modes).

#include "cosim/mapping/FlexibleBody.hpp"
#include "cosim/mapping/SurfaceMapping.hpp"
#include "lube/FilmGrid.hpp"
#include "modal/ReducedBody.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace flexehd::cosim {

class FlexibleSurface {
public:
    enum class Side { Piston, Liner };

    /// surface: physical surface facing the film; held: interface groups held in the quasi-static
    /// response (empty = all interfaces of the body). Liner: the grid slides over liner-frame z in
    /// [zMin, zMax] (the grid's own z plus the offset). Throws naming the file, surface or group.
    FlexibleSurface(modal::ReducedBody body, Side side, const std::string& surface, const std::vector<std::string>& held,
                    const lube::FilmGrid& grid, double zMin = 0.0, double zMax = 0.0);
    /// The same in front of a body other surfaces share (its compliance computed once).
    FlexibleSurface(std::shared_ptr<const FlexibleBody> body, Side side, const std::string& surface,
                    const lube::FilmGrid& grid, double zMin = 0.0, double zMax = 0.0);

    int modes() const { return flexible_->modes(); }
    /// Quasi-static modal coordinates for the grid pressure p (Pa, gauge) at the axial offset:
    /// quasiStatic(modalForce(p)).
    void respond(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& q) const;
    /// Modal forces Φᵀ A p (N per unit modal coordinate) of the grid pressure at the offset.
    void modalForce(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& f) const;
    /// Quasi-static modal coordinates q = C f for modal forces f (held interfaces fixed).
    void quasiStatic(const Eigen::VectorXd& f, Eigen::VectorXd& q) const { flexible_->quasiStatic(f, q); }
    /// The same for the columns of F (modes × k).
    void quasiStatic(const Eigen::MatrixXd& F, Eigen::MatrixXd& Q) const { flexible_->quasiStatic(F, Q); }
    /// Film-thickness change (m) on the grid for the modal coordinates q at the axial offset
    /// (0 on Void nodes).
    void filmChange(const Eigen::VectorXd& q, double offset, Eigen::VectorXd& dh) const;
    /// modalForce of k pressure fields at once (grid nodes × k → modes × k).
    void modalForces(const Eigen::MatrixXd& P, double offset, Eigen::MatrixXd& F) const;
    void modalForces(const lube::NodeColumns& P, int gridSize, double offset, Eigen::MatrixXd& F) const;
    /// The film-thickness change per unit modal coordinate at the offset (grid nodes × modes):
    /// filmChange(e_j) in column j (0 on Void nodes).
    void filmChangeShapes(double offset, Eigen::MatrixXd& Psi) const;
    /// Nodal displacement of the whole mesh (3 · nodes, m) for q.
    Eigen::VectorXd displacement(const Eigen::VectorXd& q) const { return flexible_->displacement(q); }

    const modal::ReducedBody& body() const { return flexible_->body(); }
    /// The body with its compliance, to put in front of another grid.
    const std::shared_ptr<const FlexibleBody>& flexibleBody() const { return flexible_; }
    /// Indices (into body().interfaces) of the interfaces held in the response.
    const std::vector<int>& heldInterfaces() const { return flexible_->heldInterfaces(); }
    const std::string& surface() const { return surface_; }
    /// Grid nodes (of a piston grid) that lie outside the surface's image: no elastic motion there.
    const std::vector<int>& outsideNodes() const { return mapping_->outsideNodes(); }
    /// Resultant (force, moment about `point`; N, N·m) of the nodal forces the body receives
    /// for the grid pressure p at the offset, in the body frame.
    Eigen::Matrix<double, 6, 1> resultant(const Eigen::VectorXd& p, double offset, const Eigen::Vector3d& point) const;

private:
    std::shared_ptr<const FlexibleBody> flexible_;
    std::string surface_;
    std::unique_ptr<SurfaceMapping> mapping_;
};

}  // namespace flexehd::cosim
