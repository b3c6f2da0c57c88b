#include "cosim/coupling/AitkenAccelerator.hpp"

namespace flexehd::cosim {

AitkenAccelerator::AitkenAccelerator(double initialRelaxation)
    : omega0_(initialRelaxation), omega_(initialRelaxation) {}

void AitkenAccelerator::reset() {
    first_ = true;
    omega_ = omega0_;
}

Eigen::VectorXd AitkenAccelerator::next(const Eigen::VectorXd& y, const Eigen::VectorXd& Hy) {
    const Eigen::VectorXd r = Hy - y;
    if (first_) {
        first_ = false;
        lastR_ = r;
        return y + omega0_ * r;
    }
    const Eigen::VectorXd dr = r - lastR_;
    const double d = dr.squaredNorm();
    if (d > 0.0) omega_ = -omega_ * lastR_.dot(dr) / d;
    lastR_ = r;
    return y + omega_ * r;
}

}  // namespace flexehd::cosim
