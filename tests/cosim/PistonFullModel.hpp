#pragma once
// The full finite-element model of a piston mesh, for the tests that hold its reduced body's gas
// and inertia loads against it (docs/coupling.md §2, "Gas and inertia loads on the flexible
// piston"): the static displacement with the pin bore's nodes held, and the consistent nodal
// forces of a rigid acceleration's body force.
#include <Eigen/Core>

#include "fem/DofMap.hpp"
#include "fem/ElasticityAssembler.hpp"
#include "fem/Mesh.hpp"
#include "fem/StaticSolver.hpp"

namespace flexehd::test {

/// The full model's static displacement under nodal forces f with the pin bore's nodes held.
inline Eigen::VectorXd pinBoreHeldStatic(const fem::Mesh& m, const fem::ElasticMaterial& material,
                                         const Eigen::VectorXd& f) {
    const fem::SparseMatrix K = fem::ElasticityAssembler(m).stiffness(material);
    fem::DofMap dofs(m.numNodes(), 3);
    dofs.constrain(m.groupNodes("pin_bore"), fem::kAllComponents);
    dofs.finalize();
    return dofs.expand(fem::StaticSolver(dofs.reduce(K)).solve(dofs.reduceLoad(f, K)));
}

/// The body force −ρ a(r) of the rigid acceleration a(r) = (ë + β̈ z, 0, A − β̈ x) (about the pin
/// axis at the origin) as consistent nodal forces −M a.
inline Eigen::VectorXd rigidAccelerationForces(const fem::Mesh& m, double rho, double lateral, double tilt,
                                               double axial) {
    Eigen::VectorXd a = Eigen::VectorXd::Zero(3 * m.numNodes());
    for (fem::Index k = 0; k < m.numNodes(); ++k) {
        a[3 * k] = lateral + tilt * m.nodes(2, k);
        a[3 * k + 2] = axial - tilt * m.nodes(0, k);
    }
    const fem::SparseMatrix M = fem::ElasticityAssembler(m).mass(rho);
    return -(M.selfadjointView<Eigen::Upper>() * a);
}

}  // namespace flexehd::test
