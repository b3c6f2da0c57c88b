#pragma once
// Global matrices and load vectors of linear elasticity on a mesh (3 DOFs per node,
// dof = 3 node + component). Matrices are symmetric, upper triangle stored.
#include <string>

#include <Eigen/Core>

#include "fem/BoundarySurface.hpp"
#include "fem/Material.hpp"
#include "fem/SparsityPattern.hpp"

namespace flexehd::fem {

class ElasticityAssembler {
public:
    explicit ElasticityAssembler(const Mesh& mesh);

    Index numDofs() const { return pattern_.numDofs(); }
    SparseMatrix stiffness(const ElasticMaterial& material) const;
    SparseMatrix mass(double density) const;
    /// Equivalent nodal forces of the thermal strain α (T - T_ref) (nodal temperatures, K).
    Eigen::VectorXd thermalLoad(const ElasticMaterial& material, double expansion,
                                const Eigen::VectorXd& temperature, double referenceTemperature) const;
    /// Nodal forces of a uniform pressure p (Pa, positive pushes into the body).
    Eigen::VectorXd pressureLoad(const BoundarySurface& surface, double pressure) const;
    /// Nodal forces of a pressure field given by nodal values (Pa, one per mesh node; only
    /// the surface's nodes are used), interpolated with the surface shape functions.
    Eigen::VectorXd pressureLoad(const BoundarySurface& surface, const Eigen::VectorXd& nodalPressure) const;

private:
    const Mesh& mesh_;
    SparsityPattern pattern_;
};

}  // namespace flexehd::fem
