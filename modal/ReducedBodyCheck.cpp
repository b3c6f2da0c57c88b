#include "modal/ReducedBodyCheck.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <fmt/format.h>

namespace flexehd::modal {
namespace {

/// "dataset NAME has a non-finite value (nan) at [r, c]" for the first such entry, in the
/// file's row-major order ([rows, cols] of the file; `transposed` when memory holds colsxrows).
std::optional<std::string> nonFinite(const std::string& dataset, const Eigen::MatrixXd& a, bool transposed) {
    if (a.allFinite()) return std::nullopt;
    const Eigen::Index fileRows = transposed ? a.cols() : a.rows(), fileCols = transposed ? a.rows() : a.cols();
    for (Eigen::Index r = 0; r < fileRows; ++r)
        for (Eigen::Index c = 0; c < fileCols; ++c) {
            const double v = transposed ? a(c, r) : a(r, c);
            if (!std::isfinite(v)) {
                if (fileCols == 1) return fmt::format("dataset {} has a non-finite value ({}) at [{}]", dataset, v, r);
                return fmt::format("dataset {} has a non-finite value ({}) at [{}, {}]", dataset, v, r, c);
            }
        }
    return std::nullopt;
}

std::optional<std::string> notSymmetric(const std::string& dataset, const Eigen::MatrixXd& a) {
    const double scale = a.cwiseAbs().maxCoeff();
    const double asym = (a - a.transpose()).cwiseAbs().maxCoeff();
    if (asym <= 1e-8 * scale) return std::nullopt;
    return fmt::format("dataset {} is not symmetric (largest |A - Aᵀ| {:.3g} against largest |A| {:.3g})",
                       dataset, asym, scale);
}

std::optional<std::string> massDefect(const Eigen::MatrixXd& m) {
    if (m.size() == 0) return std::nullopt;
    if (auto d = notSymmetric("/modes/mass", m)) return d;
    const Eigen::LLT<Eigen::MatrixXd> llt(m);
    const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m, Eigen::EigenvaluesOnly).eigenvalues();
    if (llt.info() != Eigen::Success || !(lambda.minCoeff() > 1e-12 * lambda.maxCoeff()))
        return fmt::format("dataset /modes/mass is not positive definite (eigenvalues from {:.3g} to {:.3g} kg): "
                           "every mode must carry mass",
                           lambda.minCoeff(), lambda.maxCoeff());
    return std::nullopt;
}

std::optional<std::string> stiffnessDefect(const Eigen::MatrixXd& k) {
    if (k.size() == 0) return std::nullopt;
    if (auto d = notSymmetric("/modes/stiffness", k)) return d;
    const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k, Eigen::EigenvaluesOnly).eigenvalues();
    const double scale = lambda.cwiseAbs().maxCoeff();
    if (lambda.minCoeff() < -1e-8 * scale)
        return fmt::format("dataset /modes/stiffness has a negative eigenvalue ({:.3g} N/m, largest {:.3g} N/m): "
                           "a body's stiffness cannot release energy",
                           lambda.minCoeff(), scale);
    return std::nullopt;
}

// The damper supports' projected dashpots: symmetric and positive semi-definite (dashpots take
// energy, never give it), present exactly when /settings lists dampers.
std::optional<std::string> supportDampingDefect(const ReducedBody& b) {
    const Eigen::MatrixXd& d = b.supportDamping;
    if (d.size() == 0) {
        if (!b.settings.dampers.empty())
            return fmt::format("attribute 'dampers' of /settings lists {} damper(s) but dataset /modes/support_damping "
                               "is missing",
                               b.settings.dampers.size());
        return std::nullopt;
    }
    if (b.settings.dampers.empty())
        return std::string("dataset /modes/support_damping is present but attribute 'dampers' of /settings lists none");
    if (auto e = nonFinite("/modes/support_damping", d, false)) return e;
    if (auto e = notSymmetric("/modes/support_damping", d)) return e;
    const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(d, Eigen::EigenvaluesOnly).eigenvalues();
    const double scale = lambda.cwiseAbs().maxCoeff();
    if (lambda.minCoeff() < -1e-8 * scale)
        return fmt::format("dataset /modes/support_damping has a negative eigenvalue ({:.3g} N s/m, largest {:.3g} "
                           "N s/m): dashpots cannot release energy",
                           lambda.minCoeff(), scale);
    return std::nullopt;
}

std::optional<std::string> materialDefect(const fem::ElasticMaterial& m) {
    if (!std::isfinite(m.E) || !(m.E > 0.0))
        return fmt::format("attribute 'E_pa' of /material is {}, expected a Young's modulus > 0 Pa", m.E);
    if (!std::isfinite(m.nu) || !(m.nu > -1.0 && m.nu < 0.5))
        return fmt::format("attribute 'nu' of /material is {}, expected a Poisson's ratio in (-1, 0.5)", m.nu);
    if (!std::isfinite(m.rho) || !(m.rho > 0.0))
        return fmt::format("attribute 'rho_kg_m3' of /material is {}, expected a density > 0 kg/m³", m.rho);
    return std::nullopt;
}

}  // namespace

std::optional<std::string> reducedBodyDefect(const ReducedBody& b) {
    if (auto d = materialDefect(b.material)) return d;
    if (!std::isfinite(b.meshSize) || b.meshSize < 0.0)
        return fmt::format("attribute 'mesh_size_m' of /provenance is {}, expected a size >= 0 m", b.meshSize);
    if (auto d = nonFinite("/mesh/nodes", b.mesh.nodes, true)) return d;
    for (std::size_t i = 0; i < b.interfaces.size(); ++i)
        if (auto d = nonFinite("/interfaces/" + std::to_string(i) + "/reference_point", b.interfaces[i].referencePoint, false))
            return d;
    // The file holds shapes as [modes, 3 nodes] (transposed in memory), the rest as written.
    if (auto d = nonFinite("/modes/shapes", b.shapes, true)) return d;
    if (auto d = nonFinite("/modes/mass", b.massMatrix, false)) return d;
    if (auto d = nonFinite("/modes/stiffness", b.stiffnessMatrix, false)) return d;
    if (auto d = nonFinite("/modes/frequencies_hz", b.frequenciesHz, false)) return d;
    if (auto d = nonFinite("/modes/damping_ratio", b.dampingRatios, false)) return d;
    if (auto d = nonFinite("/modes/interface_motion", b.interfaceMotion, false)) return d;
    for (std::size_t k = 0; k < b.rigidBody.size(); ++k)
        if (b.rigidBody[k] != 0 && b.rigidBody[k] != 1)
            return fmt::format("dataset /modes/rigid_body has {} at [{}], expected 0 or 1", b.rigidBody[k], k);
    for (Eigen::Index k = 0; k < b.dampingRatios.size(); ++k)
        if (b.dampingRatios[k] < 0.0)
            return fmt::format("dataset /modes/damping_ratio has {} at [{}], expected a ratio >= 0", b.dampingRatios[k], k);
    if (auto d = massDefect(b.massMatrix)) return d;
    if (auto d = supportDampingDefect(b)) return d;
    return stiffnessDefect(b.stiffnessMatrix);
}

}  // namespace flexehd::modal
