#pragma once
// MovingGridMapping: load and deformation mapping between a film grid that slides axially
// along a structure (the piston grid along the liner bore) and that structure, without
// rebuilding the operators for every position (docs/mapping.md).
//
// Setup, once: a structure-fixed grid G with the moving grid's θ nodes and uniform axial
// spacing h over [zMin, zMax] (body frame), its LoadMapping A_G and DeformationMapping D_G.
// Per call, for the axial offset s (body z = grid z + s):
//  * loads: each θ column of the grid pressure (piecewise linear in z on the shifted grid
//    nodes, zero outside) is replaced by its L2 projection onto the hats ψ_k of G:
//    M c = b, b_k = ∫ ψ_k p dz (exact: Simpson on the merged breakpoints, where both factors
//    are linear), M the hats' Gram matrix (tridiagonal, Thomas algorithm). 1 and z lie in
//    span{ψ_k}, so ∫ c·{1, z} dz = ∫ p·{1, z} dz per column: with the θ layout unchanged and
//    A_G exact for bilinear fields, the total force and the moment about any point on the
//    axis (x, y components) equal those of the moving grid's bilinear source to round-off.
//    M⁻¹ is dense but decays by 2 − √3 ≈ 0.27 per row: the solve is restricted to the rows the
//    grid overlaps plus 30 on each side (truncation 0.27³⁰ ≈ 1e-17), so a call costs
//    O(grid + window · nθ) plus the window's columns of A_G.
//  * deformation: u_r on G (the window's rows of D_G.radial()) is interpolated to the shifted
//    grid rows by cubic Hermite in z with central-difference slopes (one-sided 3-point at the
//    ends of G): C¹ in z, exact for quadratics, so quadratics in (z, s) are reproduced like
//    by the Clough–Tocher operator itself.
//  * modal (setModes): Φᵀ A_G M_G⁻¹ and D_G Φ pre-multiplied once (M_G the Gram matrix of all
//    of G's hats: the modal force needs only the rows the shifted grid overlaps, no window
//    padding), optionally restricted to the θ columns that carry film (the panels of a masked
//    skirt grid): per call O(overlap rows × active columns × modes).
//  * shear (MovingGridOptions::shear): the axial and circumferential tractions τ_z, τ_θ
//    (bilinear on the moving grid like p) take the same projection, then G's shear operators
//    (LoadMapping::axialShear(), circumferentialShear()); the total friction force (axial and
//    circumferential) and the moment of τ_θ about any point on the axis (x, y) are conserved
//    like the pressure's. Modal: Φᵀ S_G pre-multiplied by setModes.
// What is not conserved: the distribution of the load over nodes differs from the direct
// LoadMapping at offset s (the projection smooths the field at scale h); virtual work is exact
// only for displacements linear in z on each θ column.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "cosim/mapping/DeformationMapping.hpp"
#include "cosim/mapping/LoadMapping.hpp"
#include "fem/Mesh.hpp"
#include "lube/FilmGrid.hpp"

namespace flexehd::cosim {

struct MovingGridOptions {
    /// Largest accepted relative spread of the surface-node radii (as LoadMappingOptions).
    double radiusTolerance = 1e-3;
    /// Also build the shear-traction operators on G (shearLoads(), modalShearForce()).
    bool shear = false;
};

class MovingGridMapping {
public:
    /// `grid`: the moving grid (its z nodes relative to the offset, its θ layout). G spans
    /// [zMin, zMax] in the body frame with fixedRows ≥ 3 uniform rows. Throws like LoadMapping
    /// and DeformationMapping for G.
    MovingGridMapping(const fem::Mesh& mesh, const std::string& surface, const lube::FilmGrid& grid,
                      double zMin, double zMax, int fixedRows, double radiusTolerance = 1e-3);
    /// The same, with options (shear operators).
    MovingGridMapping(const fem::Mesh& mesh, const std::string& surface, const lube::FilmGrid& grid,
                      double zMin, double zMax, int fixedRows, const MovingGridOptions& options);

    /// Nodal forces on the body (3 · mesh nodes, N) of grid pressures p (Pa, gauge) with the
    /// grid at axial offset s. Throws std::out_of_range if the shifted grid leaves [zMin, zMax].
    Eigen::VectorXd loads(const Eigen::VectorXd& p, double offset) const;
    void loads(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& forces) const;
    /// Nodal forces on the body (3 · mesh nodes, N) of the shear tractions at the moving grid's
    /// nodes, τ_z along e_z and τ_θ along e_θ = (−sin θ, cos θ, 0) (Pa, the traction the film
    /// exerts on this body: on the liner, opposite to the piston's), with the grid at offset s.
    /// Either may be empty (skipped). Throws std::logic_error unless built with options.shear,
    /// std::invalid_argument for a wrong size, std::out_of_range like loads().
    Eigen::VectorXd shearLoads(const Eigen::VectorXd& tauZ, const Eigen::VectorXd& tauTheta, double offset) const;
    void shearLoads(const Eigen::VectorXd& tauZ, const Eigen::VectorXd& tauTheta, double offset,
                    Eigen::VectorXd& forces) const;
    bool hasShear() const { return load_.axialShear().size() != 0; }
    /// Radial displacement (m, positive away from the axis) at the moving grid's nodes of the
    /// body displacement u (3 · mesh nodes) with the grid at axial offset s.
    Eigen::VectorXd radialDisplacement(const Eigen::VectorXd& u, double offset) const;
    void radialDisplacement(const Eigen::VectorXd& u, double offset, Eigen::VectorXd& ur) const;
    /// Modal variant: pre-multiplies the body's mode shapes Φ (3 · mesh nodes × modes) into the
    /// fixed operators once, Φᵀ A_G M_G⁻¹ (modes × G nodes; M_G the Gram matrix of G's hats) and
    /// D_G Φ (G nodes × modes); a call then costs O(overlap × modes) beyond the same transfer /
    /// interpolation. `columns`: the θ columns of the moving grid that carry film (ascending;
    /// empty = all). The modal products then skip the other columns: modalForce ignores p there
    /// (it must be zero there — ambient gauge pressure, no film — for the result to equal the
    /// unrestricted one), modalRadialDisplacement returns 0 there. Throws std::invalid_argument
    /// for a wrong number of dofs or a column out of range / not ascending.
    void setModes(const Eigen::MatrixXd& shapes, std::vector<int> columns = {});
    /// The θ columns the modal products use (all after setModes without columns).
    const std::vector<int>& modalColumns() const { return columns_; }
    /// Modal forces Φᵀ f of grid pressures p at offset s (requires setModes). Equals Φᵀ loads(p, s)
    /// to round-off (the full Gram matrix instead of the window's: a difference ≈ 0.27³⁰).
    Eigen::VectorXd modalForce(const Eigen::VectorXd& p, double offset) const;
    void modalForce(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& out) const;
    /// Modal forces of k pressure fields at once (grid nodes × k → modes × k; one matrix product).
    void modalForces(const Eigen::MatrixXd& P, double offset, Eigen::MatrixXd& out) const;
    /// The radial displacement per unit modal coordinate at offset s (grid nodes × modes): the
    /// columns of modalRadialDisplacement for the unit vectors, at the cost of one of them per mode.
    void modalRadialShapes(double offset, Eigen::MatrixXd& ur) const;
    /// Modal forces Φᵀ f of the shear tractions at offset s (requires setModes and options.shear).
    Eigen::VectorXd modalShearForce(const Eigen::VectorXd& tauZ, const Eigen::VectorXd& tauTheta,
                                    double offset) const;
    /// Radial displacement at the moving grid's nodes of modal coordinates q (requires setModes);
    /// 0 on the columns setModes left out.
    Eigen::VectorXd modalRadialDisplacement(const Eigen::VectorXd& q, double offset) const;
    void modalRadialDisplacement(const Eigen::VectorXd& q, double offset, Eigen::VectorXd& ur) const;
    /// The projected pressure on G (for inspection and tests): G nodes, zero off the window.
    Eigen::VectorXd fixedPressure(const Eigen::VectorXd& p, double offset) const;

    const lube::FilmGrid& fixedGrid() const { return fixed_; }
    const LoadMapping& fixedLoad() const { return load_; }
    const DeformationMapping& fixedDeformation() const { return def_; }

private:
    struct Window {
        int k0 = 0, rows = 0;
    };
    using Transfer = Eigen::SparseMatrix<double, Eigen::RowMajor>;
    // Throws std::invalid_argument unless `count` pressures fit the moving grid.
    void requirePressures(Eigen::Index count) const;
    // c (rows × nθ, row-major, G rows k0..k0+rows−1) = M⁻¹ b for the grid at offset s.
    Window project(const Eigen::VectorXd& p, double offset, Eigen::VectorXd& c) const;
    // The window and T(k, i) = ∫ ψ_k φ_i dz (window rows × moving rows) at offset s.
    Window transfer(double offset, Transfer& T) const;
    // The first and last window rows T reaches (last < first: none) — the G rows the grid overlaps.
    static std::pair<int, int> overlapRows(const Window& w, const Transfer& T);
    // c = M⁻¹ T f for one nodal field f of the moving grid (`what` names it in errors).
    void solve(const Window& w, const Transfer& T, const Eigen::VectorXd& f, const char* what,
               Eigen::VectorXd& c) const;
    // Σ over the non-empty fields of op.middleCols(window) · c (op: A_G-like, columns = G nodes).
    template <typename Op>
    void applyShear(const Op& opZ, const Op& opTheta, const Eigen::VectorXd& tauZ, const Eigen::VectorXd& tauTheta,
                    double offset, Eigen::VectorXd& out) const;
    void checkOffset(double offset) const;
    // Hermite weights of G's rows base[i] .. base[i] + 3 for each moving row; rows r0 .. r1 used.
    void interpolation(double offset, std::vector<std::array<double, 4>>& weights, std::vector<int>& base,
                       int& r0, int& r1) const;
    // ur (moving grid) from uG, the radial displacement on G's rows r0 .. (row-major, nθ wide).
    void interpolate(const std::vector<std::array<double, 4>>& weights, const std::vector<int>& base, int r0,
                     const Eigen::VectorXd& uG, Eigen::VectorXd& ur) const;

    std::vector<double> z_;  // moving grid rows
    int nTheta_;
    double h_;
    lube::FilmGrid fixed_;
    LoadMapping load_;
    DeformationMapping def_;
    std::vector<int> columns_;     // θ columns of the modal products (setModes)
    Eigen::MatrixXd modalLoad_;    // Φᵀ A_G M_G⁻¹ on the columns: modes × (G rows · columns), row-major layout
    Eigen::MatrixXd modalShapes_;  // D_G Φ on the columns: (G rows · columns) × modes
    Eigen::MatrixXd modalShearZ_, modalShearTheta_;  // Φᵀ S_z,G and Φᵀ S_θ,G (with shear)
};

}  // namespace flexehd::cosim
