#include "cosim/engine/CrankKinematics.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace flexehd::cosim {

CrankKinematics::CrankKinematics(double stroke, double rodLength, double pinOffset, double speedRpm)
    : r_(0.5 * stroke), l_(rodLength), c_(pinOffset), omega_(speedRpm * 2.0 * std::numbers::pi / 60.0) {
    if (!(stroke > 0.0) || !(speedRpm > 0.0))
        throw std::invalid_argument("crank kinematics: stroke and speed must be positive");
    if (!(rodLength > r_ + std::abs(c_)))
        throw std::invalid_argument("crank kinematics: rod length " + std::to_string(rodLength) +
                                    " m must exceed stroke/2 + |pin offset| = " +
                                    std::to_string(r_ + std::abs(c_)) + " m");
}

double CrankKinematics::tdcPosition() const { return std::sqrt((l_ + r_) * (l_ + r_) - c_ * c_); }

double CrankKinematics::secondsPerDegree() const { return std::numbers::pi / 180.0 / omega_; }

CrankState CrankKinematics::at(double crankDeg) const {
    // z(φ) = r cos φ + L,  s = r sin φ + c,  L = √(l² − s²); derivatives in φ, times ω, ω².
    const double phi = crankDeg * std::numbers::pi / 180.0;
    const double sn = std::sin(phi), cs = std::cos(phi);
    const double s = r_ * sn + c_, ds = r_ * cs, dds = -r_ * sn;
    const double L = std::sqrt(l_ * l_ - s * s);
    const double dL = -s * ds / L;
    const double ddL = -(ds * ds + s * dds) / L - (s * ds) * (s * ds) / (L * L * L);
    CrankState st;
    st.position = r_ * cs + L;
    st.velocity = omega_ * (-r_ * sn + dL);
    st.acceleration = omega_ * omega_ * (-r_ * cs + ddL);
    st.sinRod = s / l_;
    st.tanRod = s / L;
    return st;
}

}  // namespace flexehd::cosim
