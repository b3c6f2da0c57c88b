#include "cosim/ringpack/RingAxialMotion.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::cosim {

RingAxialMotion::RingAxialMotion(double mass, double sideClearance) : m_(mass), c_(sideClearance) {
    if (!(mass > 0.0) || !(sideClearance > 0.0) || !std::isfinite(mass + sideClearance))
        throw std::invalid_argument("RingAxialMotion: the ring's mass per circumference and the side clearance must be "
                                    "positive (got " + std::to_string(mass) + " kg/m, " + std::to_string(sideClearance) +
                                    " m)");
}

void RingAxialMotion::step(double dt, double force) {
    if (!(dt > 0.0) || !std::isfinite(force))
        throw std::invalid_argument("RingAxialMotion::step: the step must be positive and the force finite");
    flank_ = 0.0;
    if (onLowerFlank() && force <= 0.0) {  // pressed on the lower flank
        flank_ = -force;
        return;
    }
    if (onUpperFlank() && force >= 0.0) {  // pressed on the upper flank
        flank_ = -force;
        return;
    }
    v_ += dt * force / m_;
    z_ += dt * v_;
    if (z_ <= 0.0) {
        z_ = 0.0;
        v_ = 0.0;
    } else if (z_ >= c_) {
        z_ = c_;
        v_ = 0.0;
    }
}

}  // namespace flexehd::cosim
