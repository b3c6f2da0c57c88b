#pragma once
// FilmLinearization: the derivative of the film pressure with respect to the film thickness h
// and its rate ∂h/∂t at a solution p of the cavitation problem (ReynoldsSystem), with the
// cavitated set held — the generalized Jacobian a semismooth Newton method on a coupled
// problem needs (docs/coupling.md §3). With w(p, h, ḣ) = A(h) p − b(h, ḣ):
//
//   free Film nodes F (p above the bound):  A_FF δp_F = −(∂w/∂h δh + ∂w/∂ḣ δḣ)_F
//   cavitated Film nodes, Fixed and Void:   δp = 0
//
// ∂w/∂ḣ is diagonal (the squeeze term A_k ρ_k ḣ_k of seed eq. 1, exact by linearity); ∂w/∂h
// (Poiseuille h_f³, Couette h_f) is taken by finite differences on a distance-2 colouring of the
// grid (ColouredDifference) — a node's row depends on h at the node and its four neighbours, so
// nodes three grid steps apart can be perturbed together: about 8 assemblies per linearisation,
// not one per node.
// A_FF, the free rows and columns only, is factorized once per linearisation (CHOLMOD simplicial; its pattern
// analysed again when the free set changes); any number of (δh, δḣ) columns are then answered by
// one multi-column solve of the free rows' size.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "lube/FilmGrid.hpp"
#include "lube/FilmState.hpp"
#include "lube/GridColouring.hpp"
#include "lube/ReynoldsSystem.hpp"

namespace flexehd::lube {

class FilmLinearization {
public:
    explicit FilmLinearization(const FilmGrid& grid);
    ~FilmLinearization();
    FilmLinearization(FilmLinearization&&) noexcept;
    FilmLinearization& operator=(FilmLinearization&&) noexcept;

    /// Linearises at the solution p (Pa) of the film state with nodal density ρ (kg/m³) and
    /// viscosity η (Pa·s) held (a pressure-dependent lubricant's ∂ρ/∂p, ∂η/∂p are left out);
    /// pLower is the cavitation bound p_cav (−∞: no bound, every Film node is free).
    void linearize(const FilmState& film, const Eigen::VectorXd& density, const Eigen::VectorXd& viscosity,
                   const Eigen::VectorXd& p, double pLower);

    /// δp (N × k, Pa) for k columns of thickness changes δh (m) and rate changes
    /// δḣ = dhdtScale · dhdt (m/s); either matrix may be empty (0 × 0) for none.
    Eigen::MatrixXd pressureChange(const Eigen::MatrixXd& dh, const Eigen::MatrixXd& dhdt,
                                   double dhdtScale = 1.0) const;

    /// Film nodes held at the bound (cavitated) in the last linearisation.
    int cavitatedNodes() const { return cavitated_; }
    /// Number of colours of the distance-2 colouring (assemblies per linearisation).
    int colours() const { return colouring_.colours; }

private:
    struct Factor;
    const FilmGrid* grid_;
    GridColouring colouring_;
    std::unique_ptr<Factor> factor_;
    SparseMatrix dwdh_;        // ∂w/∂h: free rows × grid nodes
    Eigen::VectorXd dwdhdt_;   // diagonal ∂w/∂ḣ of the free rows
    std::vector<int> freeIndex_;  // the free rows (grid node numbers, ascending)
    int cavitated_ = 0;
};

}  // namespace flexehd::lube
