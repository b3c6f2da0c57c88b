#pragma once
// Steady heat conduction with convective (Robin) boundaries on named surface groups,
// set up once and solved for any scaling of the boundary parameters (docs/thermal.md §1):
//   (K + Σ_g s_g h_g H_g) T = Σ_g s_g h_g T_g b_g,
//   K = ∫ k ∇N ∇Nᵀ dV,  H_g = ∫_Γg N Nᵀ dA,  b_g = ∫_Γg N dA,
// with h_g the heat-transfer coefficient (W/(m² K)) and T_g the fluid temperature (K) of
// group g, s_g a dimensionless factor on h_g (1 = as given). Boundaries not listed are
// adiabatic. All matrices share one sparsity pattern, so K(s) is a sum of value arrays.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fem/Mesh.hpp"
#include "fem/SparsityPattern.hpp"

namespace flexehd::fem {

/// Convection on one physical surface group.
struct ConvectionBoundary {
    std::string group;
    double h = 0.0;                 ///< heat-transfer coefficient, W/(m² K), >= 0
    double fluidTemperature = 0.0;  ///< K, > 0
};

/// Boundary parameters of one solve: a factor on each boundary's h and its fluid
/// temperature, in the order the boundaries were given.
struct ConvectionParameters {
    Eigen::VectorXd hScale;            ///< s_g, dimensionless
    Eigen::VectorXd fluidTemperature;  ///< T_g, K
};

class SteadyHeatConduction {
public:
    /// Throws std::invalid_argument naming the group or value when a group is unknown or
    /// not a surface, listed twice, h < 0, T_fluid <= 0, or k <= 0.
    SteadyHeatConduction(const Mesh& mesh, double conductivity, std::vector<ConvectionBoundary> boundaries);

    const Mesh& mesh() const { return mesh_; }
    const std::vector<ConvectionBoundary>& boundaries() const { return boundaries_; }
    /// The parameters as given (all factors 1).
    ConvectionParameters nominal() const;

    /// Nodal temperatures (K) for the given parameters. Throws std::runtime_error if the
    /// system is singular (no boundary with h > 0: the temperature level is undetermined).
    Eigen::VectorXd solve(const ConvectionParameters& p) const;

    /// Temperatures and their derivatives for the same factorization: column j of
    /// dT_dScale is ∂T/∂s_j = A⁻¹ h_j (T_j b_j − H_j T), of dT_dFluid ∂T/∂T_j = A⁻¹ s_j h_j b_j.
    struct Sensitivity {
        Eigen::VectorXd T;
        Eigen::MatrixXd dT_dScale, dT_dFluid;
    };
    Sensitivity solveWithSensitivity(const ConvectionParameters& p) const;

    /// Heat flow into the body through each boundary, W: Q_g = s_g h_g (T_g A_g − b_gᵀ T).
    Eigen::VectorXd boundaryHeatFlow(const ConvectionParameters& p, const Eigen::VectorXd& T) const;

private:
    SparseMatrix system(const ConvectionParameters& p, Eigen::VectorXd& rhs) const;
    void check(const ConvectionParameters& p) const;

    const Mesh& mesh_;
    std::vector<ConvectionBoundary> boundaries_;
    SparseMatrix conduction_;
    std::vector<SparseMatrix> H_;     ///< ∫ N Nᵀ dA per boundary (same pattern as conduction_)
    std::vector<Eigen::VectorXd> b_;  ///< ∫ N dA per boundary
};

}  // namespace flexehd::fem
