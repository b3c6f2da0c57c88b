#include "fem/ModalAnalysis.hpp"
#include "fem/Stopwatch.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fem/ElasticityAssembler.hpp"

namespace flexehd::fem {

FixedGroup parseFixedGroup(const std::string& text) {
    const auto colon = text.find(':');
    FixedGroup g;
    g.group = text.substr(0, colon);
    if (g.group.empty()) throw std::invalid_argument("fixed group '" + text + "': empty group name");
    if (colon != std::string::npos) g.components = parseComponents(text.substr(colon + 1));
    return g;
}

int ModalAnalysis::rigidBodyModes() const {
    const auto& l = modes.eigenvalues;
    int n = 0;
    while (n < l.size() && std::abs(l(n)) < rigidThreshold) ++n;
    return n;
}

Eigen::VectorXd ModalAnalysis::frequenciesHz() const {
    Eigen::VectorXd f = modes.frequenciesHz();
    f.head(std::min<Eigen::Index>(rigidBodyModes(), f.size())).setZero();
    return f;
}

ModalAnalysis analyseModes(const Mesh& mesh, const ElasticMaterial& material,
                           const std::vector<FixedGroup>& fixed, const EigenmodeOptions& options) {
    material.validate();
    const Stopwatch t0;
    ElasticityAssembler assembler(mesh);
    const SparseMatrix K = assembler.stiffness(material);
    const SparseMatrix M = assembler.mass(material.rho);
    DofMap dofs(mesh.numNodes(), 3);
    for (const auto& f : fixed) dofs.constrain(mesh.groupNodes(f.group), f.components);
    dofs.finalize();
    ModalAnalysis out;
    out.dofs = dofs.numDofs();
    out.freeDofs = dofs.numFree();
    const bool constrained = dofs.numConstrained() > 0;
    const SparseMatrix Kf = constrained ? dofs.reduce(K) : K;
    const SparseMatrix Mf = constrained ? dofs.reduce(M) : M;
    out.rigidThreshold = rigidBodyThreshold(Kf, Mf);
    out.assembleSeconds = t0.seconds();
    out.modes = solveEigenmodes(Kf, Mf, options);
    if (constrained) out.modes.shapes = dofs.expandHomogeneous(out.modes.shapes);
    return out;
}

}  // namespace flexehd::fem
