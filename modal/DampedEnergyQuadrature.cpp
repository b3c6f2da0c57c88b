#include "modal/DampedEnergyQuadrature.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::modal {

DampedEnergyQuadrature::DampedEnergyQuadrature(int points)
    : coarse_(gaussLegendre(points)), fine_(gaussLegendre(2 * points)) {}

DampedEnergy DampedEnergyQuadrature::overStep(const ModalPropagator& propagator, const Eigen::VectorXd& y, const Eigen::VectorXd& w,
                                              const Eigen::VectorXd& fStart, const Eigen::VectorXd& fEnd,
                                              double dt) const {
    if (!(dt > 0.0)) throw std::invalid_argument("damped energy quadrature: step " + std::to_string(dt) + " s must be > 0");
    // Both rules' nodes in one call: the coarse first, then the fine.
    std::vector<double> taus;
    for (const QuadratureRule* rule : {&coarse_, &fine_})
        for (double x : rule->nodes) taus.push_back(x * dt);
    Eigen::MatrixXd q, v;
    propagator.responseWithin(y, w, fStart, fEnd, dt, taus, q, v);
    Eigen::RowVectorXd rate;  // q̇ᵀ C q̇ at each node (W)
    if (propagator.coupledDamping())
        rate = v.cwiseProduct(propagator.dampingMatrix() * v).colwise().sum();
    else
        rate = propagator.damping().transpose() * v.cwiseAbs2();
    double coarse = 0.0, fine = 0.0;
    const auto mc = static_cast<Eigen::Index>(coarse_.nodes.size());
    for (Eigen::Index i = 0; i < mc; ++i) coarse += coarse_.weights[std::size_t(i)] * rate(i);
    for (std::size_t i = 0; i < fine_.nodes.size(); ++i) fine += fine_.weights[i] * rate(mc + Eigen::Index(i));
    return {fine * dt, std::abs(fine - coarse) * dt};
}

}  // namespace flexehd::modal
