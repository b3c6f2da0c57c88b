#pragma once
// Global matrices of steady heat conduction (1 DOF per node: temperature, K):
//   (K_cond + H) T = f,   K_cond = ∫ k ∇N ∇Nᵀ dV,   H = Σ_surfaces ∫ h N Nᵀ dA,
//   f = Σ_surfaces ∫ h T_fluid N dA   (convection to a fluid at T_fluid, Robin condition).
#include <Eigen/Core>

#include "fem/BoundarySurface.hpp"
#include "fem/SparsityPattern.hpp"

namespace flexehd::fem {

class HeatAssembler {
public:
    explicit HeatAssembler(const Mesh& mesh);

    Index numDofs() const { return pattern_.numDofs(); }
    /// Conductivity matrix for conductivity k (W/(m K)).
    SparseMatrix conductivity(double k) const;
    /// Adds convection with coefficient h (W/(m^2 K)) to a fluid at `fluidTemperature` (K)
    /// on a boundary surface: H into `K` (a matrix from conductivity()), h T_fluid into `f`.
    void addConvection(const BoundarySurface& surface, double h, double fluidTemperature,
                       SparseMatrix& K, Eigen::VectorXd& f) const;
    /// Adds a uniform heat flux density q (W/m^2, positive into the body) on a surface.
    void addHeatFlux(const BoundarySurface& surface, double q, Eigen::VectorXd& f) const;

private:
    const Mesh& mesh_;
    SparsityPattern pattern_;
};

}  // namespace flexehd::fem
