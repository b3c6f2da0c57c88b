#pragma once
// Free-vibration analysis of an elastic body: assemble K and M, hold the fixed groups,
// solve for the lowest modes, return shapes on all nodes. The pipeline behind
// `flexehd modes`, and the reference that modal reduction is checked against.
#include <string>
#include <vector>

#include "fem/DofMap.hpp"
#include "fem/EigenmodeSolver.hpp"
#include "fem/Material.hpp"
#include "fem/Mesh.hpp"

namespace flexehd::fem {

struct FixedGroup {
    std::string group;                     ///< physical group (surface or volume)
    unsigned components = kAllComponents;  ///< which displacement components are held
};

/// Parses "GROUP" (all components) or "GROUP:xy" (selected components).
FixedGroup parseFixedGroup(const std::string& text);

struct ModalAnalysis {
    Eigenmodes modes;             ///< shapes expanded to all 3 x nodes DOFs (held DOFs zero)
    Index dofs = 0, freeDofs = 0;
    double assembleSeconds = 0.0;
    double rigidThreshold = 0.0;  ///< (rad/s)^2, see fem::rigidBodyThreshold
    /// Number of leading modes with |λ| below rigidThreshold: the rigid-body modes of an
    /// insufficiently held body.
    int rigidBodyModes() const;
    /// Natural frequencies, Hz; the rigid-body modes as exactly 0 (their eigenvalues are
    /// round-off of either sign).
    Eigen::VectorXd frequenciesHz() const;
};

ModalAnalysis analyseModes(const Mesh& mesh, const ElasticMaterial& material,
                           const std::vector<FixedGroup>& fixed, const EigenmodeOptions& options);

}  // namespace flexehd::fem
