#include "modal/CraigBamptonReducer.hpp"
#include "modal/PressurePattern.hpp"
#include "fem/Stopwatch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <Eigen/Eigenvalues>

#include "fem/BoundarySurface.hpp"
#include "fem/DofMap.hpp"
#include "fem/ElasticityAssembler.hpp"
#include "fem/EigenmodeSolver.hpp"
#include "fem/StaticSolver.hpp"
#include "fem/SurfaceSpring.hpp"
#include "modal/DenseProducts.hpp"
#include "modal/LoadPatterns.hpp"

namespace flexehd::modal {
namespace {

// Lowest fixed-interface modes: `count` of them, or, with a cut-off, all below it
// (computed in growing batches).
fem::Eigenmodes normalModes(const fem::SparseMatrix& Kii, const fem::SparseMatrix& Mii,
                            const fem::StaticSolver& factor, const ReductionSettings& s) {
    const int maxModes = static_cast<int>(std::min<Eigen::Index>(Kii.rows() - 1, 2000));
    if (s.normalModes > maxModes)
        throw std::invalid_argument("reduction: " + std::to_string(s.normalModes) +
                                    " normal modes requested; at most " + std::to_string(maxModes) +
                                    " (2000, and fewer than the " + std::to_string(Kii.rows()) + " interior DOFs)");
    fem::EigenmodeOptions opt;
    // The basis is Rayleigh–Ritz projected afterwards (orthonormalisation), so the
    // fixed-interface vectors need not be converged to round-off.
    opt.tolerance = 1e-8;
    if (s.cutoffHz <= 0.0) {
        if (s.normalModes <= 0) return {};
        opt.count = s.normalModes;
        return fem::solveEigenmodes(Kii, Mii, opt, &factor);
    }
    const double lambdaCut = std::pow(2 * std::numbers::pi * s.cutoffHz, 2);
    opt.count = std::min(maxModes, s.normalModes > 0 ? s.normalModes : 20);
    for (;;) {
        fem::Eigenmodes m = fem::solveEigenmodes(Kii, Mii, opt, &factor);
        const auto keep = std::count_if(m.eigenvalues.begin(), m.eigenvalues.end(),
                                        [&](double l) { return l <= lambdaCut; });
        if (keep < m.eigenvalues.size() || opt.count == maxModes) {
            m.eigenvalues.conservativeResize(keep);
            m.shapes.conservativeResize(Eigen::NoChange, keep);
            return m;
        }
        opt.count = std::min(maxModes, 2 * opt.count);
    }
}

}  // namespace

InterfaceSpec parseInterface(const std::string& text) {
    InterfaceSpec s;
    std::string rest = text;
    if (const auto at = rest.find('@'); at != std::string::npos) {
        std::stringstream p(rest.substr(at + 1));
        Eigen::Vector3d x;
        char c1 = 0, c2 = 0;
        if (!(p >> x(0) >> c1 >> x(1) >> c2 >> x(2)) || c1 != ',' || c2 != ',' || !p.eof())
            throw std::invalid_argument("interface '" + text + "': reference point must be @x,y,z in metres");
        s.referencePoint = x;
        rest = rest.substr(0, at);
    }
    const auto colon = rest.find(':');
    s.group = rest.substr(0, colon);
    if (s.group.empty()) throw std::invalid_argument("interface '" + text + "': empty group name");
    if (colon != std::string::npos) {
        const std::string kind = rest.substr(colon + 1);
        if (kind == "rbe2") s.kind = InterfaceKind::Rbe2;
        else if (kind == "rbe3") s.kind = InterfaceKind::Rbe3;
        else throw std::invalid_argument("interface '" + text + "': kind '" + kind + "', expected rbe2 or rbe3");
    }
    return s;
}

namespace {

// "GROUP:VALUE" of --support and --damper: the group before the last colon, the value a finite
// number > 0 after it.
std::pair<std::string, double> parseGroupValue(const std::string& text, const std::string& option,
                                               const std::string& symbol, const std::string& unit,
                                               const std::string& example) {
    const auto colon = text.rfind(':');
    std::string group = text.substr(0, colon == std::string::npos ? 0 : colon);
    if (colon == std::string::npos || group.empty())
        throw std::invalid_argument(option + " '" + text + "': expected GROUP:" + symbol + " with " + symbol + " in " +
                                    unit + ", e.g. " + example);
    const std::string v = text.substr(colon + 1);
    char* end = nullptr;
    const double value = std::strtod(v.c_str(), &end);
    if (v.empty() || end != v.c_str() + v.size())
        throw std::invalid_argument(option + " '" + text + "': " + symbol + " must be a number in " + unit + ", e.g. " +
                                    example);
    if (!(std::isfinite(value) && value > 0.0))
        throw std::invalid_argument(option + " '" + text + "': " + symbol + " must be finite and > 0 " + unit);
    return {std::move(group), value};
}

}  // namespace

SupportSpec parseSupport(const std::string& text) {
    auto [group, k] = parseGroupValue(text, "--support", "K", "N/m^3", "bottom:1e12");
    return {std::move(group), k};
}

DamperSpec parseDamper(const std::string& text) {
    auto [group, c] = parseGroupValue(text, "--damper", "C", "N*s/m^3", "bottom:1e6");
    return {std::move(group), c};
}

CraigBamptonReducer::CraigBamptonReducer(const fem::Mesh& mesh, const fem::ElasticMaterial& material)
    : mesh_(mesh), material_(material) {
    material_.validate();
}

namespace {

// The uniform-pressure groups: known surface groups, each once, none an interface (a held
// surface's load goes straight into the reference node; its static response is not elastic).
void requirePressurePatterns(const fem::Mesh& mesh, const std::vector<InterfaceSpec>& specs,
                             const std::vector<std::string>& patterns) {
    for (const std::string& text : patterns) {
        const PressurePattern p = PressurePattern::parse(text);
        try {
            p.surface(mesh);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("pressure pattern '" + text + "': " + e.what());
        }
        if (std::count(patterns.begin(), patterns.end(), text) > 1)
            throw std::invalid_argument("pressure pattern '" + text + "' is listed twice; each pattern gets one vector");
        for (const auto& s : specs)
            if (s.group == p.group)
                throw std::invalid_argument("pressure pattern '" + text +
                                            "' is also an interface; a held surface's load goes into its reference "
                                            "node, so a uniform-pressure vector there adds nothing");
    }
}

// The supports (springs) or dampers (dashpots): parsed, on known surface groups, each group once
// per option, none an interface (its springs or dashpots would act on the reference node's rigid
// motion, which the run prescribes). A group may carry both a spring and a damper support.
template <class Parse>
void requireSupports(const fem::Mesh& mesh, const std::vector<InterfaceSpec>& specs,
                     const std::vector<std::string>& supports, const std::string& option, const std::string& what,
                     const std::string& kind, const std::string& value, Parse parse) {
    std::vector<std::string> groups;
    for (const std::string& text : supports) {
        const std::string group = parse(text).group;
        try {
            fem::BoundarySurface(mesh, group);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(option + " '" + text + "': " + e.what());
        }
        if (std::count(groups.begin(), groups.end(), group) > 0)
            throw std::invalid_argument(option + " '" + text + "': group '" + group + "' has a " + what +
                                        " already; give one " + value + " per group");
        groups.push_back(group);
        for (const auto& i : specs)
            if (i.group == group)
                throw std::invalid_argument(option + " '" + text + "': group '" + group +
                                            "' is also an interface; a surface is either held at an interface or "
                                            "on a " + kind + ", not both");
    }
}

// K plus the spring stiffness of every support (Winkler foundation, fem/SurfaceSpring).
fem::SparseMatrix supportedStiffness(const fem::Mesh& mesh, fem::SparseMatrix K, const std::vector<std::string>& supports) {
    for (const std::string& text : supports) {
        const SupportSpec s = parseSupport(text);
        K += fem::surfaceSpringMatrix(fem::BoundarySurface(mesh, s.group), s.stiffness);
    }
    return K;
}

// D_s = Φᵀ C_s Φ: the dashpots of every damper support (fem::surfaceDashpotMatrix) projected on
// the body's final shapes (full DOF numbering), symmetrised; empty without dampers.
Eigen::MatrixXd projectedSupportDamping(const fem::Mesh& mesh, const Eigen::MatrixXd& shapes,
                                        const std::vector<std::string>& dampers) {
    if (dampers.empty()) return {};
    fem::SparseMatrix Cs(shapes.rows(), shapes.rows());
    for (const std::string& text : dampers) {
        const DamperSpec d = parseDamper(text);
        Cs += fem::surfaceDashpotMatrix(fem::BoundarySurface(mesh, d.group), d.damping);
    }
    const Eigen::MatrixXd CsPhi = fem::SparseMatrix(Cs.selfadjointView<Eigen::Upper>()) * shapes;
    const Eigen::MatrixXd Ds = multiplyTransposed(shapes, CsPhi);
    return 0.5 * (Ds + Ds.transpose());
}

// The cheap checks, before anything that can take minutes on a production mesh.
void requireReducible(const fem::Mesh& mesh, const std::vector<InterfaceSpec>& specs, const ReductionSettings& settings) {
    if (specs.empty())
        throw std::invalid_argument("reduction: no interface given; the body must be held at an interface");
    if (!(settings.cutoffHz >= 0.0)) throw std::invalid_argument("reduction: cut-off frequency must be >= 0 Hz");
    if (!(settings.dampingRatio >= 0.0 && settings.dampingRatio < 1.0))
        throw std::invalid_argument("reduction: damping ratio must lie in [0, 1)");
    if (settings.axialHats == 1 || settings.axialHats < 0 || settings.axialOrder < 0 ||
        settings.circumferentialOrder < 0)
        throw std::invalid_argument("reduction: load patterns need orders >= 0 and axial hats 0 or >= 2");
    for (const auto& surface : settings.staticCorrection) fem::BoundarySurface(mesh, surface);
    for (const auto& s : specs)
        if (mesh.group(s.group).dim != 2)
            throw std::invalid_argument("interface '" + s.group + "' is a volume group of mesh '" + mesh.source +
                                        "'; an interface is a surface group (the surfaces where the body is held)");
    requirePressurePatterns(mesh, specs, settings.pressurePatterns);
    requireSupports(mesh, specs, settings.supports, "--support", "support", "spring support", "stiffness", parseSupport);
    requireSupports(mesh, specs, settings.dampers, "--damper", "damper", "damper support", "damping", parseDamper);
}

// The interfaces: node sets tied to reference nodes (RBE2, or averaging) in dofs.
std::vector<Interface> tieInterfaces(const fem::Mesh& mesh, const std::vector<InterfaceSpec>& specs, fem::DofMap& dofs) {
    std::vector<Interface> interfaces;
    for (const auto& s : specs) {
        Interface itf{s.group, s.kind, Eigen::Vector3d::Zero(), mesh.groupNodes(s.group)};
        if (itf.nodes.empty()) throw std::invalid_argument("interface '" + s.group + "' has no nodes");
        for (auto n : itf.nodes) itf.referencePoint += mesh.nodes.col(n);
        itf.referencePoint /= double(itf.nodes.size());
        if (s.referencePoint) itf.referencePoint = *s.referencePoint;
        try {
            if (s.kind == InterfaceKind::Rbe2)
                dofs.addRigidLink(itf.nodes, mesh.nodes, itf.referencePoint);
            else
                dofs.addAveragingLink(itf.nodes, mesh.nodes, itf.referencePoint);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("interface '" + s.group + "': " + e.what());
        }
        interfaces.push_back(std::move(itf));
    }
    dofs.finalize();
    return interfaces;
}

// Residual attachment vectors K_ii⁻¹ F_i of interior loads, M-orthogonalised against Φ:
// (I − Φ Φᵀ M_ii) K_ii⁻¹ F_i (Craig & Bampton 1968; docs/modal.md, "The basis").
Eigen::MatrixXd attachment(const fem::StaticSolver& factor, const fem::SparseMatrix& Mii, const Eigen::MatrixXd& Phi,
                           const Eigen::MatrixXd& Fi) {
    Eigen::MatrixXd X = factor.solve(Fi);
    if (Phi.cols() > 0) X -= Phi * (Phi.transpose() * (Mii.selfadjointView<Eigen::Upper>() * X));
    return X;
}

void appendColumns(Eigen::MatrixXd& X, const Eigen::MatrixXd& more) {
    X.conservativeResize(Eigen::NoChange, X.cols() + more.cols());
    X.rightCols(more.cols()) = more;
}

// The static correction: residual attachment modes, M-orthogonal to Φ. Always inertia relief,
// the interior's static response to the inertia forces of a unit boundary acceleration,
// −(M_ii Ψ + M_ib): it carries the coupling between the interface's (rigid) motion and elastic
// deformation that fixed-interface modes converge to slowly; then the responses to the surface
// pressure patterns of settings.staticCorrection, and to a uniform unit pressure on each group
// of settings.pressurePatterns (also flat surfaces such as the crown, where the z–θ patterns
// do not apply).
Eigen::MatrixXd staticCorrection(const fem::Mesh& mesh, const fem::ElasticityAssembler& assembler,
                                 const fem::DofMap& dofs, const fem::StaticSolver& factor, const fem::SparseMatrix& Mii,
                                 const Eigen::MatrixXd& Mib, const Eigen::MatrixXd& Psi, const Eigen::MatrixXd& Phi,
                                 const ReductionSettings& settings, int& inertiaRelief) {
    const Eigen::Index ni = Mii.rows();
    // Nodal forces in the free DOFs (u = T u_free), interior part.
    const auto interiorLoad = [&](const Eigen::VectorXd& f) -> Eigen::VectorXd {
        return (dofs.transformation().transpose() * f).head(ni);
    };
    Eigen::MatrixXd X = attachment(factor, Mii, Phi, -(Mii.selfadjointView<Eigen::Upper>() * Psi + Mib));
    inertiaRelief = int(X.cols());
    for (const auto& surface : settings.staticCorrection) {
        const fem::BoundarySurface s(mesh, surface);
        const Eigen::MatrixXd P =
            surfacePressurePatterns(mesh, surface, settings.axialOrder, settings.circumferentialOrder, settings.axialHats);
        Eigen::MatrixXd Fi(ni, P.cols());
        for (Eigen::Index j = 0; j < P.cols(); ++j)
            Fi.col(j) = interiorLoad(assembler.pressureLoad(s, Eigen::VectorXd(P.col(j))));
        appendColumns(X, attachment(factor, Mii, Phi, Fi));
    }
    if (settings.pressurePatterns.empty()) return X;
    Eigen::MatrixXd Fi(ni, Eigen::Index(settings.pressurePatterns.size()));
    for (std::size_t k = 0; k < settings.pressurePatterns.size(); ++k)
        Fi.col(Eigen::Index(k)) =
            interiorLoad(assembler.pressureLoad(PressurePattern::parse(settings.pressurePatterns[k]).surface(mesh), 1.0));
    appendColumns(X, attachment(factor, Mii, Phi, Fi));
    return X;
}

// The basis B = [Ψ Φ X; I 0 0] in the free DOFs, its columns scaled to unit M-norm, and its
// projected matrices Mb = D Bᵀ M B D, Kb = D Bᵀ K B D.
void projectedBasis(const fem::SparseMatrix& Kr, const fem::SparseMatrix& Mr, const Eigen::MatrixXd& Psi,
                    const Eigen::MatrixXd& Phi, const Eigen::MatrixXd& X, Eigen::MatrixXd& B, Eigen::MatrixXd& Mb,
                    Eigen::MatrixXd& Kb) {
    const Eigen::Index nf = Kr.rows(), nb = Psi.cols(), ni = nf - nb;
    const Eigen::Index m0 = nb + Phi.cols() + X.cols();
    B = Eigen::MatrixXd::Zero(nf, m0);
    B.topLeftCorner(ni, nb) = Psi;
    B.bottomLeftCorner(nb, nb).setIdentity();
    B.block(0, nb, ni, Phi.cols()) = Phi;
    B.block(0, nb + Phi.cols(), ni, X.cols()) = X;
    // Unit M-norm columns (D = diag(Bᵀ M B)^-1/2): attachment vectors of unit-pascal
    // patterns are ~1e-12 m, and a dependence threshold must compare directions.
    // Sparse x (n x 100) dense: with full storage and row-major dense operands Eigen's
    // kernel streams contiguous rows (axpy per non-zero); col-major operands make it
    // stride through memory, ~5x slower here.
    using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    const RowMatrix Brow = B;
    const Eigen::MatrixXd MB = RowMatrix(fem::SparseMatrix(Mr.selfadjointView<Eigen::Upper>()) * Brow);
    const Eigen::MatrixXd KB = RowMatrix(fem::SparseMatrix(Kr.selfadjointView<Eigen::Upper>()) * Brow);
    const Eigen::VectorXd norms = (B.cwiseProduct(MB)).colwise().sum().transpose();
    // A pattern that loads nothing (e.g. sin mθ on a surface in a plane through the axis)
    // gives a zero vector: weight 0 here, dropped below as a dependent direction.
    Eigen::VectorXd d(norms.size());
    for (Eigen::Index j = 0; j < norms.size(); ++j)
        d(j) = norms(j) > 1e-28 * norms.maxCoeff() ? 1.0 / std::sqrt(norms(j)) : 0.0;
    B = B * d.asDiagonal();
    Mb = multiplyTransposed(B, MB) * d.asDiagonal();
    Kb = multiplyTransposed(B, KB) * d.asDiagonal();
}

// Orthonormalisation: Mb = U S Uᵀ, dependent directions dropped, then Kq = V Λ Vᵀ; the body's
// shapes, modal mass and stiffness, interface motion, frequencies, rigid-body flags and damping.
void orthonormalise(const fem::DofMap& dofs, const fem::SparseMatrix& Kr, const fem::SparseMatrix& Mr,
                    const Eigen::MatrixXd& B, const Eigen::MatrixXd& Mb, const Eigen::MatrixXd& Kb, Eigen::Index nb,
                    double dampingRatio, ReducedBody& body, int& droppedDependent) {
    const Eigen::Index m0 = B.cols();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> me(0.5 * (Mb + Mb.transpose()));
    const double smax = me.eigenvalues().maxCoeff();
    std::vector<Eigen::Index> keep;
    for (Eigen::Index k = 0; k < m0; ++k)
        if (me.eigenvalues()(k) > 1e-10 * smax) keep.push_back(k);
    if (smax <= 0.0) throw std::runtime_error("reduction: the basis is empty");
    droppedDependent = int(m0 - keep.size());
    Eigen::MatrixXd Q(m0, keep.size());
    for (std::size_t k = 0; k < keep.size(); ++k)
        Q.col(k) = me.eigenvectors().col(keep[k]) / std::sqrt(me.eigenvalues()(keep[k]));
    const Eigen::MatrixXd Kq = Q.transpose() * Kb * Q;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ke(0.5 * (Kq + Kq.transpose()));
    const Eigen::MatrixXd C = Q * ke.eigenvectors();
    const Eigen::MatrixXd BC = multiply(B, C);

    body.shapes = dofs.expandHomogeneous(BC);
    body.massMatrix = C.transpose() * Mb * C;
    body.stiffnessMatrix = C.transpose() * Kb * C;
    body.interfaceMotion = BC.bottomRows(nb);
    const Eigen::VectorXd lambda = ke.eigenvalues();
    const double rigidThreshold = fem::rigidBodyThreshold(Kr, Mr);
    const int m = int(lambda.size());
    body.frequenciesHz.resize(m);
    body.rigidBody.assign(m, 0);
    body.dampingRatios = Eigen::VectorXd::Constant(m, dampingRatio);
    for (int k = 0; k < m; ++k) {
        body.frequenciesHz(k) = std::copysign(std::sqrt(std::abs(lambda(k))), lambda(k)) / (2 * std::numbers::pi);
        if (std::abs(lambda(k)) < rigidThreshold) {  // same criterion as fem::ModalAnalysis
            body.rigidBody[k] = 1;
            body.frequenciesHz(k) = 0.0;  // the eigenvalue is round-off of either sign
            body.dampingRatios(k) = 0.0;
        }
    }
}

}  // namespace

ReducedBody CraigBamptonReducer::reduce(const std::vector<InterfaceSpec>& specs, const ReductionSettings& settings,
                                        ReductionReport* report) const {
    ReductionReport rep;
    fem::Stopwatch t;
    requireReducible(mesh_, specs, settings);
    ReducedBody body;
    body.mesh = mesh_;
    body.material = material_;
    body.settings = settings;
    body.elementOrder = mesh_.order();
    fem::DofMap dofs(mesh_.numNodes(), 3);
    body.interfaces = tieInterfaces(mesh_, specs, dofs);

    fem::ElasticityAssembler assembler(mesh_);
    const fem::SparseMatrix Kr = dofs.reduce(supportedStiffness(mesh_, assembler.stiffness(material_), settings.supports));
    const fem::SparseMatrix Mr = dofs.reduce(assembler.mass(material_.rho));
    const Eigen::Index nf = dofs.numFree(), nb = 6 * dofs.numLinks(), ni = nf - nb;
    rep.dofs = dofs.numDofs();
    // Interior first, boundary (reference DOFs) last: blocks by index range.
    const fem::SparseMatrix Kii = Kr.topLeftCorner(ni, ni), Mii = Mr.topLeftCorner(ni, ni);
    const Eigen::MatrixXd Kib = Eigen::MatrixXd(Kr.topRightCorner(ni, nb));
    const Eigen::MatrixXd Mib = Eigen::MatrixXd(Mr.topRightCorner(ni, nb));
    rep.assembleSeconds = t.lap();

    std::unique_ptr<fem::StaticSolver> factor;
    try {
        factor = std::make_unique<fem::StaticSolver>(Kii);
    } catch (const std::runtime_error&) {
        throw std::runtime_error(
            "reduction: the interfaces do not hold the body (interior stiffness singular): a part of the "
            "mesh is disconnected from every interface, or an interface cannot stop rigid motion");
    }
    rep.factorSeconds = t.lap();
    const Eigen::MatrixXd Psi = -factor->solve(Kib);
    rep.constraintModes = int(nb);
    rep.constraintModeSeconds = t.lap();

    const fem::Eigenmodes fixed = normalModes(Kii, Mii, *factor, settings);
    const Eigen::MatrixXd& Phi = fixed.shapes;
    rep.normalModes = int(Phi.cols());
    body.settings.normalModes = rep.normalModes;
    rep.normalModeSeconds = t.lap();

    const Eigen::MatrixXd X =
        staticCorrection(mesh_, assembler, dofs, *factor, Mii, Mib, Psi, Phi, settings, rep.inertiaReliefModes);
    rep.staticCorrectionModes = int(X.cols()) - rep.inertiaReliefModes;
    rep.staticCorrectionSeconds = t.lap();

    Eigen::MatrixXd B, Mb, Kb;
    projectedBasis(Kr, Mr, Psi, Phi, X, B, Mb, Kb);
    orthonormalise(dofs, Kr, Mr, B, Mb, Kb, nb, settings.dampingRatio, body, rep.droppedDependent);
    body.supportDamping = projectedSupportDamping(mesh_, body.shapes, settings.dampers);
    rep.orthonormaliseSeconds = t.lap();
    if (report) *report = rep;
    return body;
}

}  // namespace flexehd::modal
