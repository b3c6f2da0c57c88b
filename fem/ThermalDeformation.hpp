#pragma once
// Thermoelastic static displacement of a body under a nodal temperature field:
//   K u = f_th,  f_th,a = (3λ + 2μ) α ∫ (T − T_ref) ∇N_a dV   (thermal strain α(T − T_ref) I),
// with supports that do not restrain free expansion (docs/thermal.md §3):
//  - `held` groups get u_c = 0 on the chosen components (physical seats);
//  - the rigid-body motions the held DOFs leave free (all six for an unheld body) are
//    suppressed by a statically determinate set of single-DOF supports, chosen by pivoted
//    QR among the reference group's DOFs. Their reactions vanish for a self-equilibrated
//    thermal load, so they add no stress;
//  - afterwards exactly those free rigid motions are removed in least squares over the
//    reference group's nodes: its mean rigid motion is zero (as an RBE3 reference node
//    held at the group), e.g. the piston's pin bore.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fem/Material.hpp"
#include "fem/Mesh.hpp"
#include "fem/ModalAnalysis.hpp"

namespace flexehd::fem {

struct ThermalSupport {
    std::vector<FixedGroup> held;  ///< real supports, u = 0 on the chosen components
    std::string reference;         ///< group whose mean rigid motion is held ("" = all nodes)
};

struct ThermalDeformation {
    Eigen::VectorXd displacement;  ///< 3 × nodes, m
    int freeRigidModes = 0;        ///< rigid motions not restrained by `held` (0..6)
    /// Largest reaction of the determinate supports relative to the largest thermal nodal
    /// force: ~1e-12 when the support is truly free (a check, reported by the CLI).
    double determinateReaction = 0.0;
};

/// Throws std::invalid_argument for unknown groups or mismatched sizes, and
/// std::runtime_error if the stiffness matrix is singular after the supports.
ThermalDeformation solveThermalDeformation(const Mesh& mesh, const ElasticMaterial& material, double expansion,
                                           const Eigen::VectorXd& temperature, double referenceTemperature,
                                           const ThermalSupport& support);

}  // namespace flexehd::fem
