#pragma once
// An elastic (Winkler) foundation under a boundary surface: a bed of independent springs
// of stiffness k per unit area (N/m³: pressure per metre of displacement) acting on all
// three displacement components, t = −k u (Winkler 1867; Hetényi, *Beams on Elastic
// Foundation*, 1946, §1). Its stiffness matrix is K_s = k ∫_Γ N_a N_b dA ⊗ I₃ over the
// surface's triangles, integrated as the convection matrix of SurfaceElement (docs/modal.md,
// "Spring supports").
#include "fem/BoundarySurface.hpp"
#include "fem/SparsityPattern.hpp"

namespace flexehd::fem {

/// K_s of the surface in the 3-DOF-per-node numbering of ElasticityAssembler (dof = 3 node
/// + component), upper triangle stored, so that K + K_s is the supported body's stiffness.
/// Throws std::invalid_argument unless k is finite and > 0.
SparseMatrix surfaceSpringMatrix(const BoundarySurface& surface, double stiffnessPerArea);

}  // namespace flexehd::fem
