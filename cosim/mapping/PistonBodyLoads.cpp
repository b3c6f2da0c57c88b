// PistonBodyLoads: the crown's gas pressure and the rigid motion's inertia as modal loads.
#include "cosim/mapping/PistonBodyLoads.hpp"

#include <algorithm>
#include <stdexcept>

#include <Eigen/Cholesky>
#include <fmt/format.h>

#include "fem/BoundarySurface.hpp"
#include "fem/ElasticityAssembler.hpp"

namespace flexehd::cosim {

namespace {

// Φᵀ F₁ for a unit pressure on `surface`; refused when the basis lacks its pattern.
Eigen::VectorXd gasLoadPerPascal(const modal::ReducedBody& body, const std::string& surface, const std::string& file) {
    if (!body.mesh.hasGroup(surface) || body.mesh.group(surface).dim != 2)
        throw std::invalid_argument(fmt::format(
            "bodies.piston.gas_surface: the reduced body {} has no surface group '{}' for the cylinder's gas pressure",
            file, surface));
    const auto& patterns = body.settings.pressurePatterns;
    if (std::find(patterns.begin(), patterns.end(), surface) == patterns.end())
        throw std::invalid_argument(fmt::format(
            "bodies.piston.loads: gas_pressure needs the reduced body's static response to a uniform pressure on "
            "'{}', but {} was reduced without it (missing pattern: uniform pressure on {}); reduce it again with "
            "`flexehd reduce ... --pressure-pattern {}` (docs/modal.md)",
            surface, file, surface, surface));
    const Eigen::VectorXd f = fem::ElasticityAssembler(body.mesh).pressureLoad(fem::BoundarySurface(body.mesh, surface), 1.0);
    return body.shapes.transpose() * f;
}

// The rigid fields (ë, β̈, A) about the reference point r0 (3·nodes × 3), m per unit acceleration.
Eigen::MatrixXd rigidFields(const fem::Mesh& mesh, const Eigen::Vector3d& r0) {
    const Eigen::Index n = mesh.numNodes();
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(3 * n, 3);
    for (Eigen::Index k = 0; k < n; ++k) {
        const Eigen::Vector3d d = mesh.nodes.col(k) - r0;
        R(3 * k, 0) = 1.0;         // ë along +x
        R(3 * k, 1) = d.z();       // β̈ about +y: (z, 0, −x)
        R(3 * k + 2, 1) = -d.x();
        R(3 * k + 2, 2) = 1.0;     // A along +z
    }
    return R;
}

}  // namespace

PistonBodyLoads::PistonBodyLoads(const FlexibleBody& piston, const PistonLoadSpec& spec, const std::string& file,
                                 const std::vector<RingSpec>& rings, double bore)
    : spec_(spec) {
    const modal::ReducedBody& body = piston.body();
    const Eigen::Index m = body.numModes();
    if (spec.ringPack) ringBelt_.emplace(body, rings, bore, file);
    gasUnit_ = spec.gasPressure ? gasLoadPerPascal(body, spec.gasSurface, file) : Eigen::VectorXd::Zero(m);
    inertiaSecondary_ = Eigen::MatrixXd::Zero(m, 2);
    inertiaAxial_ = Eigen::VectorXd::Zero(m);
    if (!spec.inertia) return;
    if (piston.heldInterfaces().empty())
        throw std::invalid_argument(
            fmt::format("bodies.piston.loads: inertia needs the piston held at an interface, but {} has none", file));
    const auto held = static_cast<std::size_t>(piston.heldInterfaces().front());
    const Eigen::MatrixXd R = rigidFields(body.mesh, body.interfaces[held].referencePoint);
    const Eigen::MatrixXd& P = body.shapes;
    const Eigen::MatrixXd c = (P.transpose() * P).ldlt().solve(P.transpose() * R);
    for (Eigen::Index j = 0; j < 3; ++j)
        fitResidual_ = std::max(fitResidual_, (P * c.col(j) - R.col(j)).norm() / R.col(j).norm());
    if (!(fitResidual_ < 1e-6))
        throw std::invalid_argument(fmt::format(
            "bodies.piston.loads: inertia needs the piston's rigid motion in its reduced basis, but {} reproduces it "
            "only to {:.1e} (a body reduced with its interfaces free has six rigid-body modes; docs/modal.md)",
            file, fitResidual_));
    inertiaSecondary_ = -c.leftCols(2);
    inertiaAxial_ = -c.col(2);
}

void PistonBodyLoads::add(double pGauge, const Eigen::Vector2d& secondaryAcceleration, double axialAcceleration,
                          const std::vector<RingGas>* ringGas, Eigen::Ref<Eigen::VectorXd> f) const {
    if (spec_.gasPressure) f += pGauge * gasUnit_;
    if (ringBelt_ && ringGas) ringBelt_->add(*ringGas, f);
    if (spec_.inertia) f += inertiaSecondary_ * secondaryAcceleration + axialAcceleration * inertiaAxial_;
}

}  // namespace flexehd::cosim
