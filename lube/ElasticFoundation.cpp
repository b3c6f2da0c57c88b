#include "lube/ElasticFoundation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::lube {

namespace {

// Rebound speed of the dimensionless impact ξ'' = −ξ max(0, 1 + χ ξ'), ξ(0) = 0, ξ'(0) = 1 (RK4,
// Δτ = 1e-3 of the undamped half period π; the crossing ξ = 0 interpolated).
double reboundSpeed(double chi) {
    const auto accel = [chi](double x, double v) { return -x * std::max(0.0, 1.0 + chi * v); };
    const double dt = 1e-3;
    double x = 0.0, v = 1.0;
    for (int n = 0; n < 10'000'000; ++n) {
        const double k1x = v, k1v = accel(x, v);
        const double k2x = v + 0.5 * dt * k1v, k2v = accel(x + 0.5 * dt * k1x, v + 0.5 * dt * k1v);
        const double k3x = v + 0.5 * dt * k2v, k3v = accel(x + 0.5 * dt * k2x, v + 0.5 * dt * k2v);
        const double k4x = v + dt * k3v, k4v = accel(x + dt * k3x, v + dt * k3v);
        const double xn = x + dt / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
        const double vn = v + dt / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
        if (xn <= 0.0 && n > 0) {  // left the layer within this step
            const double s = x / (x - xn);
            return -(v + s * (vn - v));
        }
        x = xn;
        v = vn;
    }
    return -v;
}

}  // namespace

ElasticFoundation::ElasticFoundation(double stiffness, double restitution)
    : stiffness_(stiffness), restitution_(restitution), chi_(0.0) {
    if (!(stiffness > 0.0) || !std::isfinite(stiffness))
        throw std::invalid_argument("ElasticFoundation: the contact stiffness must be positive and finite (Pa/m), got " +
                                    std::to_string(stiffness));
    chi_ = hysteresisFactor(restitution);
}

double ElasticFoundation::layerStiffness(double E, double nu, double t) {
    if (!(E > 0.0) || !(nu > -1.0 && nu < 0.5) || !(t > 0.0) || !std::isfinite(E) || !std::isfinite(t))
        throw std::invalid_argument("ElasticFoundation::layerStiffness: expected E > 0 Pa, -1 < nu < 0.5 and a layer "
                                    "thickness > 0 m");
    return E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu) * t);
}

double ElasticFoundation::hysteresisFactor(double e) {
    if (!(e > 0.0 && e <= 1.0))
        throw std::invalid_argument("ElasticFoundation: the coefficient of restitution must lie in (0, 1], got " +
                                    std::to_string(e));
    if (e == 1.0) return 0.0;
    // The rebound speed falls monotonically with χ: bracket, then bisect.
    double lo = 0.0, hi = 1.0;
    while (reboundSpeed(hi) > e) {
        lo = hi;
        hi *= 2.0;
    }
    for (int i = 0; i < 60 && hi - lo > 1e-12 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (reboundSpeed(mid) > e ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

double ElasticFoundation::pressure(double h, double approach, double impactSpeed) const {
    if (h >= 0.0) return 0.0;
    const double ratio = impactSpeed > 0.0 ? approach / impactSpeed : 0.0;
    return -stiffness_ * h * std::max(0.0, 1.0 + chi_ * ratio);
}

double ElasticFoundation::pressureSlope(double h, double approach, double impactSpeed, double rateSlope) const {
    if (h >= 0.0) return 0.0;
    if (!(impactSpeed > 0.0) || chi_ == 0.0) return -stiffness_;
    const double factor = 1.0 + chi_ * approach / impactSpeed;
    if (factor <= 0.0) return 0.0;
    // δ = −h, ∂δ̇/∂h = −rateSlope; a point at its impact speed (approach = δ̇₀, ratio 1) holds the ratio.
    if (approach >= impactSpeed) return -stiffness_ * (1.0 + chi_);
    return -stiffness_ * factor + stiffness_ * h * chi_ * rateSlope / impactSpeed;
}

}  // namespace flexehd::lube
