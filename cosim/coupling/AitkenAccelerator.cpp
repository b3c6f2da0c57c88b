#include "cosim/coupling/AitkenAccelerator.hpp"

namespace flexehd::cosim {

AitkenAccelerator::AitkenAccelerator(double initialRelaxation) : relaxation_(initialRelaxation) {}

void AitkenAccelerator::reset() { relaxation_.reset(); }

Eigen::VectorXd AitkenAccelerator::next(const Eigen::VectorXd& y, const Eigen::VectorXd& Hy) {
    return relaxation_.next(y, Hy);
}

}  // namespace flexehd::cosim
