#include "fem/ThermalCalibration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

#include <Eigen/Dense>

namespace flexehd::fem {
namespace {

std::string fmtNumber(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string pointText(const Eigen::Vector3d& x) {
    return "(" + fmtNumber("%.6g", x(0)) + ", " + fmtNumber("%.6g", x(1)) + ", " + fmtNumber("%.6g", x(2)) + ") m";
}

}  // namespace

std::string CalibrationParameter::label() const {
    return std::string(kind == Kind::HeatTransferScale ? "h factor" : "fluid temperature") + " on '" + group + "'";
}

ThermalCalibration::ThermalCalibration(const SteadyHeatConduction& problem, std::vector<CalibrationParameter> parameters,
                                       std::vector<TemperatureMeasurement> measurements, CalibrationOptions options)
    : problem_(problem), parameters_(std::move(parameters)), measurements_(std::move(measurements)), options_(options) {
    if (parameters_.empty()) throw std::invalid_argument("calibration: no parameters to fit");
    std::set<std::pair<std::string, int>> seen;
    for (const auto& p : parameters_) {
        const auto& b = problem.boundaries();
        const auto it = std::find_if(b.begin(), b.end(), [&](const ConvectionBoundary& c) { return c.group == p.group; });
        if (it == b.end()) {
            std::string names;
            for (const auto& c : b) names += (names.empty() ? "" : ", ") + c.group;
            throw std::invalid_argument("calibration parameter " + p.label() +
                                        ": the group has no convection boundary; boundaries: " + names);
        }
        if (!seen.insert({p.group, int(p.kind)}).second)
            throw std::invalid_argument("calibration parameter " + p.label() + " listed twice");
        boundary_.push_back(int(it - b.begin()));
    }
    const PointLocator locator(problem.mesh());
    std::vector<Eigen::Vector3d> distinct;
    for (const auto& m : measurements_) {
        if (!std::isfinite(m.temperature) || !(m.temperature > 0.0))
            throw std::invalid_argument("measurement '" + m.name + "': temperature must be > 0 K, got " +
                                        fmtNumber("%g", m.temperature));
        auto loc = locator.locate(m.position);
        if (!loc)
            throw std::invalid_argument("measurement point '" + m.name + "' at " + pointText(m.position) +
                                        " lies outside the mesh '" + problem.mesh().source + "' (nearest node " +
                                        fmtNumber("%.3g", 1e3 * locator.distanceToNearestNode(m.position)) +
                                        " mm away)");
        locations_.push_back(std::move(*loc));
        if (std::none_of(distinct.begin(), distinct.end(),
                         [&](const Eigen::Vector3d& y) { return (y - m.position).norm() < 1e-9; }))
            distinct.push_back(m.position);
    }
    if (distinct.size() < parameters_.size())
        throw std::invalid_argument("calibration is under-determined: " + std::to_string(distinct.size()) +
                                    " distinct measurement points for " + std::to_string(parameters_.size()) +
                                    " parameters; give at least as many points as parameters");
}

ConvectionParameters ThermalCalibration::parametersAt(const Eigen::VectorXd& q) const {
    ConvectionParameters p = problem_.nominal();
    for (Eigen::Index j = 0; j < q.size(); ++j) {
        const int g = boundary_[std::size_t(j)];
        if (parameters_[std::size_t(j)].kind == CalibrationParameter::Kind::HeatTransferScale) p.hScale(g) = std::exp(q(j));
        else p.fluidTemperature(g) = q(j);
    }
    return p;
}

ThermalCalibration::Bounds ThermalCalibration::bounds(Eigen::VectorXd& q) const {
    const auto n = Eigen::Index(parameters_.size());
    const ConvectionParameters base = problem_.nominal();
    Bounds b{Eigen::VectorXd(n), Eigen::VectorXd(n)};
    q.resize(n);
    for (Eigen::Index j = 0; j < n; ++j) {
        const int g = boundary_[std::size_t(j)];
        if (parameters_[std::size_t(j)].kind == CalibrationParameter::Kind::HeatTransferScale) {
            b.lo(j) = std::log(options_.minScale), b.hi(j) = std::log(options_.maxScale), q(j) = std::log(base.hScale(g));
        } else {
            b.lo(j) = options_.minFluidTemperature, b.hi(j) = options_.maxFluidTemperature, q(j) = base.fluidTemperature(g);
        }
        q(j) = std::clamp(q(j), b.lo(j), b.hi(j));
    }
    return b;
}

ThermalCalibration::Evaluation ThermalCalibration::evaluate(const Eigen::VectorXd& q,
                                                            const Eigen::VectorXd& measured) const {
    const auto n = q.size(), m = measured.size();
    const ConvectionParameters p = parametersAt(q);
    const auto s = problem_.solveWithSensitivity(p);
    Evaluation e;
    e.T = s.T;
    e.r.resize(m);
    e.J.resize(m, n);
    for (Eigen::Index i = 0; i < m; ++i) {
        const auto& loc = locations_[std::size_t(i)];
        e.r(i) = loc.interpolate(s.T) - measured(i);
        for (Eigen::Index j = 0; j < n; ++j) {
            const int g = boundary_[std::size_t(j)];
            // ∂T/∂ln s = s ∂T/∂s; ∂T/∂T_g directly.
            e.J(i, j) = parameters_[std::size_t(j)].kind == CalibrationParameter::Kind::HeatTransferScale
                            ? p.hScale(g) * loc.interpolate(s.dT_dScale.col(g))
                            : loc.interpolate(s.dT_dFluid.col(g));
        }
    }
    e.cost = 0.5 * e.r.squaredNorm();
    return e;
}

void ThermalCalibration::requireIdentifiable(const Eigen::MatrixXd& J) const {
    // Every parameter must move some measured temperature, and the columns must be independent
    // (a parameter change of 1 = a factor e on h or 1 K).
    const auto n = J.cols();
    const Eigen::VectorXd colNorm = J.colwise().norm();
    for (Eigen::Index j = 0; j < n; ++j)
        if (!(colNorm(j) > 1e-6))
            throw std::invalid_argument("calibration parameter " + parameters_[std::size_t(j)].label() +
                                        " has no effect on the measured temperatures (sensitivity " +
                                        fmtNumber("%.3g", colNorm(j)) +
                                        " K); drop it or add measurement points near that surface");
    const Eigen::MatrixXd Jn = J * colNorm.cwiseInverse().asDiagonal();
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jn, Eigen::ComputeThinV);
    const Eigen::VectorXd sv = svd.singularValues();
    if (sv(n - 1) < 1e-8 * sv(0)) {
        const Eigen::VectorXd v = svd.matrixV().col(n - 1);
        std::string involved;
        for (Eigen::Index j = 0; j < n; ++j)
            if (std::abs(v(j)) > 0.1) involved += (involved.empty() ? "" : ", ") + parameters_[std::size_t(j)].label();
        throw std::invalid_argument("calibration is under-determined: the measurement points cannot separate " +
                                    involved + " (fewer independent points than parameters)");
    }
}

bool ThermalCalibration::fit(Eigen::VectorXd& q, Evaluation& cur, const Bounds& b, const Eigen::VectorXd& measured,
                             int& iterations, int& evaluations) const {
    // Levenberg–Marquardt with bounds: parameters at a bound whose gradient points outwards
    // are held there (active set), the others take the damped Gauss–Newton step, projected.
    const auto n = q.size(), m = measured.size();
    const Eigen::VectorXd& lo = b.lo;
    const Eigen::VectorXd& hi = b.hi;
    double lambda = 1e-3;
    int it = 0;
    bool converged = false;
    for (; it < options_.maxIterations && !converged; ++it) {
        const Eigen::VectorXd g = cur.J.transpose() * cur.r;
        std::vector<Eigen::Index> active;  // free to move
        for (Eigen::Index j = 0; j < n; ++j) {
            const bool atLo = q(j) <= lo(j) + 1e-12 * (1.0 + std::abs(lo(j))) && g(j) > 0.0;
            const bool atHi = q(j) >= hi(j) - 1e-12 * (1.0 + std::abs(hi(j))) && g(j) < 0.0;
            if (!atLo && !atHi) active.push_back(j);
        }
        double gFree = 0.0;
        for (Eigen::Index j : active) gFree = std::max(gFree, std::abs(g(j)) / std::max(cur.J.col(j).norm(), 1e-300));
        // Projected gradient small against the residual norm: a (bounded) stationary point.
        if (active.empty() || gFree <= 1e-10 * std::max(cur.r.norm(), 1e-12)) {
            converged = true;
            break;
        }
        const auto na = Eigen::Index(active.size());
        Eigen::MatrixXd Ja(m, na);
        for (Eigen::Index k = 0; k < na; ++k) Ja.col(k) = cur.J.col(active[std::size_t(k)]);
        const Eigen::MatrixXd JtJ = Ja.transpose() * Ja;
        const Eigen::VectorXd ga = Ja.transpose() * cur.r;
        bool accepted = false;
        for (int tries = 0; tries < 12 && !accepted; ++tries) {
            Eigen::MatrixXd A = JtJ;
            A.diagonal() += lambda * JtJ.diagonal().cwiseMax(1e-12 * JtJ.diagonal().maxCoeff());
            const Eigen::VectorXd da = A.ldlt().solve(-ga);
            Eigen::VectorXd qNew = q;
            for (Eigen::Index k = 0; k < na; ++k) qNew(active[std::size_t(k)]) += da(k);
            qNew = qNew.cwiseMax(lo).cwiseMin(hi);
            const Eigen::VectorXd step = qNew - q;
            const double relStep = (step.array() / (1.0 + q.array().abs())).abs().maxCoeff();
            if (relStep <= 1e-12) {
                converged = true;  // no further progress possible
                break;
            }
            Evaluation next = evaluate(qNew, measured);
            ++evaluations;
            if (next.cost < cur.cost) {
                const double drop = (cur.cost - next.cost) / std::max(cur.cost, 1e-300);
                q = qNew;
                cur = std::move(next);
                lambda = std::max(lambda / 3.0, 1e-12);
                accepted = true;
                if (relStep < 1e-9 || drop < 1e-12 || cur.cost < 1e-20) converged = true;
            } else {
                lambda *= 4.0;
            }
        }
        if (!accepted && !converged) converged = true;  // no descent at any damping: a minimum to round-off
    }
    iterations = it;
    return converged;
}

CalibrationResult ThermalCalibration::result(const Eigen::VectorXd& q, const Evaluation& cur, const Bounds& b,
                                             const Eigen::VectorXd& measured) const {
    const auto n = q.size(), m = measured.size();
    CalibrationResult res;
    res.parameters = parametersAt(q);
    res.values.resize(n);
    res.atBound.resize(std::size_t(n));
    for (Eigen::Index j = 0; j < n; ++j) {
        const bool scale = parameters_[std::size_t(j)].kind == CalibrationParameter::Kind::HeatTransferScale;
        res.values(j) = scale ? std::exp(q(j)) : q(j);
        res.atBound[std::size_t(j)] = q(j) <= b.lo(j) + 1e-9 * (1.0 + std::abs(b.lo(j))) ||
                                      q(j) >= b.hi(j) - 1e-9 * (1.0 + std::abs(b.hi(j)));
    }
    res.temperature = cur.T;
    res.residuals = cur.r;
    res.computed = cur.r + measured;
    res.rms = std::sqrt(cur.r.squaredNorm() / double(m));
    Eigen::Index worst = 0;
    res.maxAbs = cur.r.cwiseAbs().maxCoeff(&worst);
    res.worst = int(worst);
    return res;
}

CalibrationResult ThermalCalibration::run() const {
    const auto m = Eigen::Index(measurements_.size());
    Eigen::VectorXd measured(m);
    for (Eigen::Index i = 0; i < m; ++i) measured(i) = measurements_[std::size_t(i)].temperature;
    Eigen::VectorXd q;
    const Bounds b = bounds(q);
    Evaluation cur = evaluate(q, measured);
    const double initialRms = std::sqrt(cur.r.squaredNorm() / double(m));
    requireIdentifiable(cur.J);
    int iterations = 0, evaluations = 1;
    const bool converged = fit(q, cur, b, measured, iterations, evaluations);

    CalibrationResult res = result(q, cur, b, measured);
    res.initialRms = initialRms;
    res.iterations = iterations;
    res.evaluations = evaluations;
    res.converged = converged;
    std::string why;
    if (!converged) why += "no convergence in " + std::to_string(options_.maxIterations) + " iterations; ";
    if (res.rms > options_.tolerance)
        why += "RMS residual " + fmtNumber("%.3g", res.rms) + " K exceeds the tolerance " +
               fmtNumber("%.3g", options_.tolerance) + " K (largest at '" + measurements_[std::size_t(res.worst)].name +
               "': " + fmtNumber("%+.3g", cur.r(res.worst)) + " K); ";
    for (Eigen::Index j = 0; j < q.size(); ++j)
        if (res.atBound[std::size_t(j)])
            why += parameters_[std::size_t(j)].label() + " stopped at its bound " + fmtNumber("%g", res.values(j)) + "; ";
    res.matched = why.empty();
    if (!res.matched)
        res.message = "the calibration cannot match the measurements: " + why.substr(0, why.size() - 2);
    return res;
}

}  // namespace flexehd::fem
