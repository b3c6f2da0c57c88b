#include "cosim/ringpack/InterRingGas.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::cosim {

InterRingGas::InterRingGas(GasProperties gas, std::vector<double> volumes, std::vector<double> temperatures,
                           std::vector<double> orifices, double initialPressure)
    : gas_(gas), volume_(std::move(volumes)), temperature_(std::move(temperatures)), cda_(std::move(orifices)) {
    const std::size_t n = volume_.size();
    if (n == 0 || temperature_.size() != n || cda_.size() != n + 1)
        throw std::invalid_argument("InterRingGas: one temperature per volume and one orifice more than the volumes "
                                    "expected (" + std::to_string(n) + " volumes, " +
                                    std::to_string(temperature_.size()) + " temperatures, " +
                                    std::to_string(cda_.size()) + " orifices)");
    for (std::size_t i = 0; i < n; ++i)
        if (!(volume_[i] > 0.0) || !(temperature_[i] > 0.0))
            throw std::invalid_argument("InterRingGas: volume " + std::to_string(i) + " needs a positive size and temperature");
    for (double a : cda_)
        if (!(a >= 0.0) || !std::isfinite(a)) throw std::invalid_argument("InterRingGas: orifice areas must be >= 0");
    if (!(initialPressure > 0.0)) throw std::invalid_argument("InterRingGas: the initial pressure must be positive");
    p_ = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(n), initialPressure);
    flow_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n) + 1);
    cylinder_ = crankcase_ = initialPressure;
}

double InterRingGas::litresPerMinute(double massFlow, const GasProperties& gas) {
    const double normalDensity = 101325.0 / (gas.gasConstant * 273.15);  // kg/m³
    return massFlow / normalDensity * 1000.0 * 60.0;
}

double InterRingGas::mass() const {
    double m = 0.0;
    for (std::size_t i = 0; i < volume_.size(); ++i)
        m += p_[static_cast<Eigen::Index>(i)] * volume_[i] / (gas_.gasConstant * temperature_[i]);
    return m;
}

void InterRingGas::flows(const Eigen::VectorXd& p, Eigen::VectorXd& f, Eigen::VectorXd& dUp,
                         Eigen::VectorXd& dDown) const {
    const int n = static_cast<int>(volume_.size());
    f.resize(n + 1);
    dUp.resize(n + 1);
    dDown.resize(n + 1);
    for (int i = 0; i <= n; ++i) {
        const double pu = i == 0 ? cylinder_ : p[i - 1], pd = i == n ? crankcase_ : p[i];
        const double tu = temperature_[static_cast<std::size_t>(i == 0 ? 0 : i - 1)];
        const double td = temperature_[static_cast<std::size_t>(i == n ? n - 1 : i)];
        f[i] = orificeFlow(gas_, cda_[static_cast<std::size_t>(i)], pu, pd, tu, td, &dUp[i], &dDown[i]);
    }
}

void InterRingGas::advance(double dt, double cylinderPressure, double crankcasePressure) {
    if (!(dt > 0.0) || !(cylinderPressure > 0.0) || !(crankcasePressure > 0.0))
        throw std::invalid_argument("InterRingGas::advance: the step and the pressures must be positive");
    cylinder_ = cylinderPressure;
    crankcase_ = crankcasePressure;
    const int n = static_cast<int>(volume_.size());
    const Eigen::VectorXd old = p_;
    Eigen::VectorXd p = p_, f, dUp, dDown, c(n), r(n), sub(n), diag(n), sup(n);
    for (int i = 0; i < n; ++i) c[i] = volume_[static_cast<std::size_t>(i)] / (gas_.gasConstant * temperature_[static_cast<std::size_t>(i)] * dt);
    for (int it = 0; it < 100; ++it) {
        flows(p, f, dUp, dDown);
        // r_i = c_i (p_i − p_i,n) − (ṁ_i − ṁ_{i+1}); ṁ_i depends on p_{i−1} (up) and p_i (down).
        for (int i = 0; i < n; ++i) {
            r[i] = c[i] * (p[i] - old[i]) - (f[i] - f[i + 1]);
            diag[i] = c[i] - dDown[i] + dUp[i + 1];
            sub[i] = i > 0 ? -dUp[i] : 0.0;
            sup[i] = i + 1 < n ? dDown[i + 1] : 0.0;
        }
        // Thomas algorithm on the tridiagonal Jacobian.
        Eigen::VectorXd cp(n), dp(n);
        for (int i = 0; i < n; ++i) {
            const double m = diag[i] - (i > 0 ? sub[i] * cp[i - 1] : 0.0);
            cp[i] = sup[i] / m;
            dp[i] = (-r[i] - (i > 0 ? sub[i] * dp[i - 1] : 0.0)) / m;
        }
        for (int i = n - 2; i >= 0; --i) dp[i] -= cp[i] * dp[i + 1];
        // Damped: the pressures stay positive.
        double scale = 1.0;
        for (int i = 0; i < n; ++i)
            if (p[i] + dp[i] <= 0.0) scale = std::min(scale, 0.5 * p[i] / -dp[i]);
        p += scale * dp;
        if (dp.cwiseAbs().maxCoeff() <= 1e-12 * p.maxCoeff()) {
            p_ = p;
            flows(p_, flow_, dUp, dDown);
            return;
        }
    }
    throw std::runtime_error("InterRingGas: the land pressures did not converge in 100 Newton iterations (step " +
                             std::to_string(dt) + " s, cylinder " + std::to_string(cylinderPressure) + " Pa)");
}

}  // namespace flexehd::cosim
