#pragma once
// An elastic (Winkler) foundation under a boundary surface: a bed of independent springs
// of stiffness k per unit area (N/m³: pressure per metre of displacement) acting on all
// three displacement components, t = −k u (Winkler 1867; Hetényi, *Beams on Elastic
// Foundation*, 1946, §1). Its stiffness matrix is K_s = k ∫_Γ N_a N_b dA ⊗ I₃ over the
// surface's triangles, integrated as the convection matrix of SurfaceElement (docs/modal.md,
// "Spring and damper supports"). A bed of viscous dashpots, c per unit area (N·s/m³),
// t = −c u̇, has the same matrix with c: C_s = c ∫_Γ N_a N_b dA ⊗ I₃ (the consistent
// "mass-like" surface matrix of any coefficient; surfaceBedMatrix).
#include "fem/BoundarySurface.hpp"
#include "fem/SparsityPattern.hpp"

namespace flexehd::fem {

/// K_s of the surface in the 3-DOF-per-node numbering of ElasticityAssembler (dof = 3 node
/// + component), upper triangle stored, so that K + K_s is the supported body's stiffness.
/// Throws std::invalid_argument unless k is finite and > 0.
SparseMatrix surfaceSpringMatrix(const BoundarySurface& surface, double stiffnessPerArea);

/// C_s = c ∫ N_a N_b dA ⊗ I₃ of a bed of dashpots of c per unit area (N·s/m³), in the same
/// numbering and storage, so that u̇ᵀ C_s u̇ is the power the bed takes. Throws
/// std::invalid_argument unless c is finite and > 0.
SparseMatrix surfaceDashpotMatrix(const BoundarySurface& surface, double dampingPerArea);

/// The common matrix of both beds: coefficient × ∫ N_a N_b dA ⊗ I₃ (upper triangle), for any
/// coefficient per unit area (unchecked).
SparseMatrix surfaceBedMatrix(const BoundarySurface& surface, double coefficientPerArea);

}  // namespace flexehd::fem
