#pragma once
// Craig–Bampton reduction of an elastic body (Craig & Bampton 1968; docs/modal.md):
//   u = [u_i; u_b] ≈ [[Ψ, Φ, X], [I, 0, 0]] [q_b; η; ξ],
//   Ψ = -K_ii⁻¹ K_ib (constraint modes), Φ: K_ii φ = ω² M_ii φ (fixed-interface modes),
//   X = (I - Φ Φᵀ M_ii) K_ii⁻¹ F_i (static-correction / residual attachment modes: inertia
//   relief F_i = -(M_ii Ψ + M_ib), the pressure patterns of LoadPatterns on the
//   staticCorrection surfaces, and one uniform unit pressure per pressurePatterns group,
//   e.g. the crown under the cylinder's gas pressure).
// Boundary DOFs are the 6 DOFs of a reference node per interface: a node set tied to it
// rigidly (RBE2) or followed by it on average (RBE3). The basis is then orthonormalised: Mᵣ = I, Kᵣ = diag(ω²), rigid-body modes flagged.
// One factorization of K_ii serves Ψ, the Lanczos iterations and X. Spring supports
// (ReductionSettings::supports) add their surface stiffness to K before all of this; damper
// supports (ReductionSettings::dampers) leave the reduction undamped and are projected on its
// final basis, D_s = Φᵀ C_s Φ (ReducedBody::supportDamping).
#include <optional>
#include <string>
#include <vector>

#include "modal/ReducedBody.hpp"

namespace flexehd::modal {

struct InterfaceSpec {
    std::string group;
    InterfaceKind kind = InterfaceKind::Rbe2;
    std::optional<Eigen::Vector3d> referencePoint;  ///< default: centroid of the node set
};

/// Parses "GROUP", "GROUP:rbe2", "GROUP:rbe3" with an optional "@x,y,z" reference point (m).
InterfaceSpec parseInterface(const std::string& text);

/// An elastic (Winkler) support: springs of `stiffness` per unit area (N/m³) on a surface group.
struct SupportSpec {
    std::string group;
    double stiffness = 0.0;
};

/// Parses "GROUP:K" (K in N/m³, finite and > 0); errors name the option and the text.
SupportSpec parseSupport(const std::string& text);

/// A viscous support: dashpots of `damping` per unit area (N·s/m³) on a surface group.
struct DamperSpec {
    std::string group;
    double damping = 0.0;
};

/// Parses "GROUP:C" (C in N·s/m³, finite and > 0); errors name the option and the text.
DamperSpec parseDamper(const std::string& text);

/// Wall-clock seconds of the steps, and the size of what was built.
struct ReductionReport {
    double assembleSeconds = 0, factorSeconds = 0, constraintModeSeconds = 0, normalModeSeconds = 0,
           staticCorrectionSeconds = 0, orthonormaliseSeconds = 0;
    int constraintModes = 0, normalModes = 0, inertiaReliefModes = 0, staticCorrectionModes = 0,
        droppedDependent = 0;
    long long dofs = 0;
};

class CraigBamptonReducer {
public:
    CraigBamptonReducer(const fem::Mesh& mesh, const fem::ElasticMaterial& material);

    /// Throws std::invalid_argument for unknown groups, empty or overlapping interfaces,
    /// more modes than interior DOFs, a pressure-pattern group listed twice or also an
    /// interface, a support or damper on an unknown, volume or interface group or listed twice;
    /// std::runtime_error if the interfaces do not hold the body (K_ii singular:
    /// a disconnected part, or no interface).
    ReducedBody reduce(const std::vector<InterfaceSpec>& interfaces, const ReductionSettings& settings,
                       ReductionReport* report = nullptr) const;

private:
    const fem::Mesh& mesh_;
    fem::ElasticMaterial material_;
};

}  // namespace flexehd::modal
