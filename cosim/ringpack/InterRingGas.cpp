#include "cosim/ringpack/InterRingGas.hpp"

#include <Eigen/LU>

#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::cosim {

namespace {

// The chain's orifices (one more than the volumes), refused when the counts do not fit.
std::vector<GasOrifice> chain(std::size_t volumes, std::size_t temperatures, const std::vector<double>& areas) {
    if (volumes == 0 || temperatures != volumes || areas.size() != volumes + 1)
        throw std::invalid_argument("InterRingGas: one temperature per volume and one orifice more than the volumes "
                                    "expected (" + std::to_string(volumes) + " volumes, " +
                                    std::to_string(temperatures) + " temperatures, " +
                                    std::to_string(areas.size()) + " orifices)");
    std::vector<GasOrifice> o;
    const int n = static_cast<int>(volumes);
    for (int i = 0; i <= n; ++i)
        o.push_back({i == 0 ? GasOrifice::kCylinder : i - 1, i == n ? GasOrifice::kCrankcase : i,
                     areas[static_cast<std::size_t>(i)]});
    return o;
}

void checkArea(double a) {
    if (!(a >= 0.0) || !std::isfinite(a)) throw std::invalid_argument("InterRingGas: orifice areas must be >= 0");
}

}  // namespace

InterRingGas::InterRingGas(GasProperties gas, std::vector<double> volumes, std::vector<double> temperatures,
                           std::vector<double> orifices, double initialPressure)
    : InterRingGas(gas, volumes, temperatures, chain(volumes.size(), temperatures.size(), orifices), initialPressure) {}

InterRingGas::InterRingGas(GasProperties gas, std::vector<double> volumes, std::vector<double> temperatures,
                           std::vector<GasOrifice> orifices, double initialPressure)
    : gas_(gas), volume_(std::move(volumes)), temperature_(std::move(temperatures)), orifice_(std::move(orifices)) {
    const int n = static_cast<int>(volume_.size());
    if (n == 0 || temperature_.size() != volume_.size())
        throw std::invalid_argument("InterRingGas: one temperature per volume expected (" + std::to_string(n) +
                                    " volumes, " + std::to_string(temperature_.size()) + " temperatures)");
    for (int i = 0; i < n; ++i)
        if (!(volume_[static_cast<std::size_t>(i)] > 0.0) || !(temperature_[static_cast<std::size_t>(i)] > 0.0))
            throw std::invalid_argument("InterRingGas: volume " + std::to_string(i) + " needs a positive size and temperature");
    std::vector<bool> reached(static_cast<std::size_t>(n), false);
    for (const GasOrifice& o : orifice_) {
        checkArea(o.area);
        for (int end : {o.from, o.to}) {
            if (end >= n || (end < 0 && end != GasOrifice::kCylinder && end != GasOrifice::kCrankcase))
                throw std::invalid_argument("InterRingGas: an orifice ends at no volume (" + std::to_string(end) + ")");
            if (end >= 0) reached[static_cast<std::size_t>(end)] = true;
        }
        if (o.from == o.to) throw std::invalid_argument("InterRingGas: an orifice joins a volume to itself");
    }
    for (int i = 0; i < n; ++i)
        if (!reached[static_cast<std::size_t>(i)])
            throw std::invalid_argument("InterRingGas: volume " + std::to_string(i) + " has no orifice");
    if (!(initialPressure > 0.0)) throw std::invalid_argument("InterRingGas: the initial pressure must be positive");
    p_ = Eigen::VectorXd::Constant(n, initialPressure);
    flow_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(orifice_.size()));
    cylinder_ = crankcase_ = initialPressure;
}

void InterRingGas::setOrificeArea(int i, double area) {
    checkArea(area);
    orifice_.at(static_cast<std::size_t>(i)).area = area;
}

void InterRingGas::setChannel(int i, double conductance, double limitArea) {
    if (!(conductance >= 0.0) || !(limitArea >= 0.0) || !std::isfinite(conductance + limitArea))
        throw std::invalid_argument("InterRingGas: a channel's conductance and area must be >= 0");
    GasOrifice& o = orifice_.at(static_cast<std::size_t>(i));
    o.channel = conductance;
    o.channelArea = limitArea;
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

double InterRingGas::blowBy() const {
    double q = 0.0;
    for (std::size_t k = 0; k < orifice_.size(); ++k) {
        if (orifice_[k].to == GasOrifice::kCrankcase) q += flow_[static_cast<Eigen::Index>(k)];
        if (orifice_[k].from == GasOrifice::kCrankcase) q -= flow_[static_cast<Eigen::Index>(k)];
    }
    return q;
}

double InterRingGas::endPressure(int end, const Eigen::VectorXd& p) const {
    return end == GasOrifice::kCylinder ? cylinder_ : end == GasOrifice::kCrankcase ? crankcase_ : p[end];
}

void InterRingGas::flows(const Eigen::VectorXd& p, Eigen::VectorXd& f, Eigen::VectorXd& dFrom,
                         Eigen::VectorXd& dTo) const {
    const Eigen::Index m = static_cast<Eigen::Index>(orifice_.size());
    f.resize(m);
    dFrom.resize(m);
    dTo.resize(m);
    for (Eigen::Index k = 0; k < m; ++k) {
        const GasOrifice& o = orifice_[static_cast<std::size_t>(k)];
        // A boundary's gas enters at the temperature of the volume on the other side.
        const int inner = o.from >= 0 ? o.from : o.to >= 0 ? o.to : 0;
        const double tFrom = temperature_[static_cast<std::size_t>(o.from >= 0 ? o.from : inner)];
        const double tTo = temperature_[static_cast<std::size_t>(o.to >= 0 ? o.to : inner)];
        const double pFrom = endPressure(o.from, p), pTo = endPressure(o.to, p);
        f[k] = orificeFlow(gas_, o.area, pFrom, pTo, tFrom, tTo, &dFrom[k], &dTo[k]);
        if (o.channel > 0.0) {
            double cFrom = 0.0, cTo = 0.0;
            f[k] += channelFlow(gas_, o.channel, o.channelArea, pFrom, pTo, tFrom, tTo, &cFrom, &cTo);
            dFrom[k] += cFrom;
            dTo[k] += cTo;
        }
    }
}

void InterRingGas::advance(double dt, double cylinderPressure, double crankcasePressure) {
    if (!(dt > 0.0) || !(cylinderPressure > 0.0) || !(crankcasePressure > 0.0))
        throw std::invalid_argument("InterRingGas::advance: the step and the pressures must be positive");
    cylinder_ = cylinderPressure;
    crankcase_ = crankcasePressure;
    const Eigen::Index n = p_.size();
    const Eigen::VectorXd old = p_;
    Eigen::VectorXd p = p_, f, dFrom, dTo, c(n), r(n);
    Eigen::MatrixXd J(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
        c[i] = volume_[static_cast<std::size_t>(i)] / (gas_.gasConstant * temperature_[static_cast<std::size_t>(i)] * dt);
    // The residual r_i = c_i (p_i − p_i,n) − Σ in + Σ out and, when asked, its Jacobian.
    auto residual = [&](const Eigen::VectorXd& p, Eigen::VectorXd& r, Eigen::MatrixXd* J) {
        flows(p, f, dFrom, dTo);
        r = c.cwiseProduct(p - old);
        if (J) *J = c.asDiagonal();
        for (std::size_t k = 0; k < orifice_.size(); ++k) {
            const GasOrifice& o = orifice_[k];
            const Eigen::Index e = static_cast<Eigen::Index>(k);
            if (o.from >= 0) r[o.from] += f[e];
            if (o.to >= 0) r[o.to] -= f[e];
            if (!J) continue;
            if (o.from >= 0) {
                (*J)(o.from, o.from) += dFrom[e];
                if (o.to >= 0) (*J)(o.from, o.to) += dTo[e];
            }
            if (o.to >= 0) {
                (*J)(o.to, o.to) -= dTo[e];
                if (o.from >= 0) (*J)(o.to, o.from) -= dFrom[e];
            }
        }
    };
    Eigen::VectorXd trial(n), rTrial(n), halved(n), rHalved(n);
    residual(p, r, &J);
    for (int it = 0; it < 100; ++it) {
        const Eigen::VectorXd dp = J.partialPivLu().solve(-r);
        // Damped: the pressures stay positive, and the residual falls — the step halved until it
        // falls enough, and on while the halved step does better still: across a wide passage
        // between nearly equal pressures the flow's square-root law sends a full Newton step as
        // far past the root as it started before it (f = √x: x − f/f' = −x), which a sufficient
        // decrease alone lets through at a residual falling by 1 % a pass.
        double scale = 1.0;
        for (Eigen::Index i = 0; i < n; ++i)
            if (p[i] + dp[i] <= 0.0) scale = std::min(scale, 0.5 * p[i] / -dp[i]);
        const double merit = r.norm();
        trial = p + scale * dp;
        residual(trial, rTrial, nullptr);
        double reached = rTrial.norm();
        for (int half = 0; half < 30; ++half) {
            const bool enough = reached <= (1.0 - 1e-4 * scale) * merit;
            halved = p + 0.5 * scale * dp;
            residual(halved, rHalved, nullptr);
            const double there = rHalved.norm();
            if (enough && !(there < reached)) break;
            scale *= 0.5;
            trial.swap(halved);
            rTrial.swap(rHalved);
            reached = there;
        }
        p = trial;
        if ((scale * dp).cwiseAbs().maxCoeff() <= 1e-12 * p.maxCoeff() || rTrial.norm() == 0.0) {
            p_ = p;
            flows(p_, flow_, dFrom, dTo);
            return;
        }
        residual(p, r, &J);
    }
    throw std::runtime_error("InterRingGas: the pack's gas pressures did not converge in 100 Newton iterations (step " +
                             std::to_string(dt) + " s, cylinder " + std::to_string(cylinderPressure) + " Pa)");
}

}  // namespace flexehd::cosim
