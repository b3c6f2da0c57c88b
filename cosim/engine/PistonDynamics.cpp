#include "cosim/engine/PistonDynamics.hpp"

#include <numbers>
#include <stdexcept>

namespace flexehd::cosim {

PistonDynamics::PistonDynamics(const PistonSpec& p, const EngineSpec& e, double gravity)
    : mp_(p.mass), mpin_(p.pinMass), ig_(p.inertia), xg_(p.cgX), zg_(p.cgZ), c_(e.pinOffset),
      area_(0.25 * std::numbers::pi * e.bore * e.bore), pcc_(e.crankcasePressure), g_(gravity) {
    if (!(mp_ > 0.0) || !(mpin_ >= 0.0) || !(ig_ > 0.0))
        throw std::invalid_argument("piston dynamics: piston mass and inertia must be positive, pin mass ≥ 0");
}

Eigen::Matrix2d PistonDynamics::mass(const CrankState& k) const {
    Eigen::Matrix2d M;
    M << mp_ + mpin_, mp_ * (zg_ + xg_ * k.tanRod),
         mp_ * zg_, ig_ + mp_ * (xg_ * xg_ + zg_ * zg_);
    return M;
}

Eigen::Vector2d PistonDynamics::force(const CrankState& k, double fg, const FilmAction& f) const {
    const double A = k.acceleration + g_;
    return {f.fx + k.tanRod * ((mp_ + mpin_) * A + fg - f.fz), f.my - c_ * fg + mp_ * xg_ * A};
}

double PistonDynamics::sideForce(const CrankState& k, double fg, const FilmAction& f, double tiltAcc) const {
    const double A = k.acceleration + g_;
    return k.tanRod * ((mp_ + mpin_) * A - mp_ * xg_ * tiltAcc + fg - f.fz);
}

double PistonDynamics::kineticEnergy(double v, double w) const {
    return 0.5 * (mp_ + mpin_) * v * v + mp_ * zg_ * v * w + 0.5 * (ig_ + mp_ * (xg_ * xg_ + zg_ * zg_)) * w * w;
}

double PistonDynamics::gasForce(double p) const { return (p - pcc_) * area_; }

}  // namespace flexehd::cosim
