// AitkenRelaxation: Aitken Δ² dynamic relaxation of a fixed point (header).
#include "lube/AitkenRelaxation.hpp"

#include <algorithm>

namespace flexehd::lube {

AitkenRelaxation::AitkenRelaxation(double initial, double lowest, double highest)
    : omega0_(initial), lowest_(lowest), highest_(highest), omega_(initial) {}

void AitkenRelaxation::reset() {
    lastR_.resize(0);
    omega_ = omega0_;
}

Eigen::VectorXd AitkenRelaxation::next(const Eigen::VectorXd& x, const Eigen::VectorXd& Gx) {
    Eigen::VectorXd r = Gx - x;
    if (lastR_.size() != 0) {  // not the first iteration
        const Eigen::VectorXd dr = r - lastR_;
        const double d = dr.squaredNorm();
        if (d > 0.0) omega_ = std::clamp(-omega_ * lastR_.dot(dr) / d, lowest_, highest_);
    }
    Eigen::VectorXd out = x + omega_ * r;
    lastR_ = std::move(r);
    return out;
}

}  // namespace flexehd::lube
