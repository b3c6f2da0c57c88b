#include "fem/SteadyHeatConduction.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

#include "fem/BoundarySurface.hpp"
#include "fem/HeatAssembler.hpp"
#include "fem/StaticSolver.hpp"

namespace flexehd::fem {

SteadyHeatConduction::SteadyHeatConduction(const Mesh& mesh, double conductivity,
                                           std::vector<ConvectionBoundary> boundaries)
    : mesh_(mesh), boundaries_(std::move(boundaries)) {
    if (!(conductivity > 0.0) || !std::isfinite(conductivity))
        throw std::invalid_argument("thermal conductivity must be > 0 W/(m K), got " + std::to_string(conductivity));
    std::set<std::string> seen;
    for (const auto& b : boundaries_) {
        if (!seen.insert(b.group).second)
            throw std::invalid_argument("convection on surface '" + b.group + "' given twice");
        if (!(b.h >= 0.0) || !std::isfinite(b.h))
            throw std::invalid_argument("convection on '" + b.group + "': heat-transfer coefficient must be >= 0 W/(m^2 K), got " +
                                        std::to_string(b.h));
        if (!(b.fluidTemperature > 0.0) || !std::isfinite(b.fluidTemperature))
            throw std::invalid_argument("convection on '" + b.group + "': fluid temperature must be > 0 K, got " +
                                        std::to_string(b.fluidTemperature));
    }
    const HeatAssembler heat(mesh);
    conduction_ = heat.conductivity(conductivity);
    for (const auto& b : boundaries_) {
        const BoundarySurface surface(mesh, b.group);  // unknown / volume group: invalid_argument
        SparseMatrix H = conduction_;
        H.coeffs().setZero();
        Eigen::VectorXd f = Eigen::VectorXd::Zero(heat.numDofs());
        heat.addConvection(surface, 1.0, 1.0, H, f);  // h = 1, T = 1: H_g and b_g
        H_.push_back(std::move(H));
        b_.push_back(std::move(f));
    }
}

ConvectionParameters SteadyHeatConduction::nominal() const {
    ConvectionParameters p;
    p.hScale = Eigen::VectorXd::Ones(Eigen::Index(boundaries_.size()));
    p.fluidTemperature.resize(Eigen::Index(boundaries_.size()));
    for (std::size_t g = 0; g < boundaries_.size(); ++g) p.fluidTemperature(Eigen::Index(g)) = boundaries_[g].fluidTemperature;
    return p;
}

void SteadyHeatConduction::check(const ConvectionParameters& p) const {
    const auto n = Eigen::Index(boundaries_.size());
    if (p.hScale.size() != n || p.fluidTemperature.size() != n)
        throw std::invalid_argument("heat conduction: " + std::to_string(n) + " boundaries but " +
                                    std::to_string(p.hScale.size()) + " factors and " +
                                    std::to_string(p.fluidTemperature.size()) + " fluid temperatures given");
    for (Eigen::Index g = 0; g < n; ++g)
        if (!(p.hScale(g) >= 0.0) || !std::isfinite(p.hScale(g)) || !std::isfinite(p.fluidTemperature(g)))
            throw std::invalid_argument("heat conduction: invalid parameters on '" + boundaries_[g].group + "'");
}

SparseMatrix SteadyHeatConduction::system(const ConvectionParameters& p, Eigen::VectorXd& rhs) const {
    check(p);
    SparseMatrix A = conduction_;
    rhs = Eigen::VectorXd::Zero(conduction_.rows());
    for (std::size_t g = 0; g < boundaries_.size(); ++g) {
        const double sh = p.hScale(Eigen::Index(g)) * boundaries_[g].h;
        A.coeffs() += sh * H_[g].coeffs();  // same pattern: values add entry by entry
        rhs += (sh * p.fluidTemperature(Eigen::Index(g))) * b_[g];
    }
    return A;
}

namespace {
StaticSolver factor(const SparseMatrix& A) {
    try {
        return StaticSolver(A);
    } catch (const std::runtime_error&) {
        throw std::runtime_error(
            "steady heat conduction is singular: no convection boundary with h > 0 fixes the temperature level");
    }
}
}  // namespace

Eigen::VectorXd SteadyHeatConduction::solve(const ConvectionParameters& p) const {
    Eigen::VectorXd rhs;
    const SparseMatrix A = system(p, rhs);
    return factor(A).solve(rhs);
}

SteadyHeatConduction::Sensitivity SteadyHeatConduction::solveWithSensitivity(const ConvectionParameters& p) const {
    Eigen::VectorXd rhs;
    const SparseMatrix A = system(p, rhs);
    const StaticSolver solver = factor(A);
    Sensitivity s;
    s.T = solver.solve(rhs);
    const auto n = Eigen::Index(boundaries_.size());
    // Differentiating A T = f:  A ∂T/∂s_j = ∂f/∂s_j − (∂A/∂s_j) T,  A ∂T/∂T_j = ∂f/∂T_j.
    Eigen::MatrixXd R(conduction_.rows(), 2 * n);
    for (Eigen::Index g = 0; g < n; ++g) {
        const double h = boundaries_[std::size_t(g)].h;
        const auto& H = H_[std::size_t(g)];
        R.col(g) = h * (p.fluidTemperature(g) * b_[std::size_t(g)] -
                        H.selfadjointView<Eigen::Upper>() * s.T);
        R.col(n + g) = (p.hScale(g) * h) * b_[std::size_t(g)];
    }
    const Eigen::MatrixXd D = solver.solve(R);
    s.dT_dScale = D.leftCols(n);
    s.dT_dFluid = D.rightCols(n);
    return s;
}

Eigen::VectorXd SteadyHeatConduction::boundaryHeatFlow(const ConvectionParameters& p, const Eigen::VectorXd& T) const {
    check(p);
    Eigen::VectorXd Q(Eigen::Index(boundaries_.size()));
    for (std::size_t g = 0; g < boundaries_.size(); ++g) {
        const double area = b_[g].sum();
        Q(Eigen::Index(g)) = p.hScale(Eigen::Index(g)) * boundaries_[g].h *
                             (p.fluidTemperature(Eigen::Index(g)) * area - b_[g].dot(T));
    }
    return Q;
}

}  // namespace flexehd::fem
