#include "lube/GreenwoodTripp.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace flexehd::lube {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLamMin = -2.0, kLamMax = 8.0, kStep = 0.01;

// 8-point Gauss–Legendre nodes and weights on [−1, 1].
constexpr std::array<double, 8> kGx = {-0.9602898564975363, -0.7966664774136267,
                                       -0.5255324099163290, -0.1834346424956498,
                                       0.1834346424956498,  0.5255324099163290,
                                       0.7966664774136267,  0.9602898564975363};
constexpr std::array<double, 8> kGw = {0.1012285362903763, 0.2223810344533745,
                                       0.3137066458778873, 0.3626837833783620,
                                       0.3626837833783620, 0.3137066458778873,
                                       0.2223810344533745, 0.1012285362903763};

struct Table {
    std::vector<double> lnF, slope;  // ln F_{5/2} and d ln F_{5/2}/dλ at λ_i
    Table() {
        const int n = static_cast<int>(std::lround((kLamMax - kLamMin) / kStep)) + 1;
        lnF.resize(static_cast<std::size_t>(n));
        slope.resize(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) {
            const double lam = kLamMin + i * kStep;
            const double f52 = GreenwoodTripp::integralF(2.5, lam);
            const double f32 = GreenwoodTripp::integralF(1.5, lam);
            lnF[static_cast<std::size_t>(i)] = std::log(f52);
            slope[static_cast<std::size_t>(i)] = -2.5 * f32 / f52;
        }
    }
};

const Table& table() {
    static const Table t;
    return t;
}

void requirePositive(double v, const char* what) {
    if (!(v > 0.0) || !std::isfinite(v))
        throw std::invalid_argument(std::string("GreenwoodTripp: ") + what +
                                    " must be positive and finite, got " + std::to_string(v));
}

}  // namespace

double GreenwoodTripp::integralF(double n, double lambda) {
    if (!std::isfinite(lambda)) throw std::invalid_argument("GreenwoodTripp: lambda not finite");
    // s = λ + t²: F_n = (2π)^(-1/2) ∫_0^T 2 t^(2n+1) exp(−(λ+t²)²/2) dt, integrand < 1e-40 beyond
    // λ + T² = 14 (and T covers the negative-λ bulk).
    const double T = std::sqrt(std::max(14.0 - lambda, 0.0));
    if (T == 0.0) return 0.0;
    const int panels = 96;
    const double hp = T / panels;
    double sum = 0.0;
    for (int p = 0; p < panels; ++p) {
        const double mid = (p + 0.5) * hp;
        for (std::size_t q = 0; q < kGx.size(); ++q) {
            const double t = mid + 0.5 * hp * kGx[q];
            const double s = lambda + t * t;
            sum += kGw[q] * 2.0 * std::pow(t, 2.0 * n + 1.0) * std::exp(-0.5 * s * s);
        }
    }
    return sum * 0.5 * hp / std::sqrt(2.0 * kPi);
}

namespace {

// ln F_{5/2}(λ) by cubic Hermite interpolation of the table (exact node slopes), for
// kLamMin ≤ λ < kLamMax; and its derivative into dlnF where asked.
double interpolatedLnF(double lambda, double* dlnF = nullptr) {
    const Table& tb = table();
    const double x = (lambda - kLamMin) / kStep;
    std::size_t i = static_cast<std::size_t>(x);
    if (i + 1 >= tb.lnF.size()) i = tb.lnF.size() - 2;
    const double u = x - static_cast<double>(i);
    const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u);
    const double h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
    if (dlnF) {
        const double d00 = 6 * u * (u - 1), d10 = (1 - u) * (1 - 3 * u), d01 = -d00, d11 = u * (3 * u - 2);
        *dlnF = (d00 * tb.lnF[i] + d01 * tb.lnF[i + 1]) / kStep + d10 * tb.slope[i] + d11 * tb.slope[i + 1];
    }
    return h00 * tb.lnF[i] + h10 * kStep * tb.slope[i] + h01 * tb.lnF[i + 1] + h11 * kStep * tb.slope[i + 1];
}

}  // namespace

double GreenwoodTripp::F52(double lambda) {
    if (!std::isfinite(lambda)) throw std::invalid_argument("GreenwoodTripp::F52: lambda not finite");
    if (lambda >= kLamMax) return 0.0;
    if (lambda < kLamMin) return integralF(2.5, lambda);
    return std::exp(interpolatedLnF(lambda));
}

double GreenwoodTripp::dF52(double lambda) {
    if (!std::isfinite(lambda)) throw std::invalid_argument("GreenwoodTripp::dF52: lambda not finite");
    if (lambda >= kLamMax) return 0.0;
    if (lambda < kLamMin) return -2.5 * integralF(1.5, lambda);
    // The derivative of the interpolant F52 gives: F d(ln F)/dλ.
    double dlnF = 0.0;
    const double lnF = interpolatedLnF(lambda, &dlnF);
    return std::exp(lnF) * dlnF;
}

double GreenwoodTripp::F52Hu(double lambda) {
    return lambda < 4.0 ? 4.4086e-5 * std::pow(4.0 - lambda, 6.804) : 0.0;
}

double GreenwoodTripp::coefficient(double sigma, double beta, double density) {
    requirePositive(sigma, "sigma (composite rms roughness, m)");
    requirePositive(beta, "beta (asperity radius, m)");
    requirePositive(density, "asperity density (1/m^2)");
    const double nbs = density * beta * sigma;
    return 16.0 * std::sqrt(2.0) * kPi / 15.0 * nbs * nbs * std::sqrt(sigma / beta);
}

double GreenwoodTripp::compositeModulus(double E1, double nu1, double E2, double nu2) {
    requirePositive(E1, "E1 (Young's modulus, Pa)");
    requirePositive(E2, "E2 (Young's modulus, Pa)");
    if (!(nu1 > -1.0 && nu1 < 0.5) || !(nu2 > -1.0 && nu2 < 0.5))
        throw std::invalid_argument("GreenwoodTripp: Poisson ratios must be in (-1, 0.5)");
    return 1.0 / ((1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2);
}

GreenwoodTripp::GreenwoodTripp(double sigma, double beta, double density, double modulus,
                               AsperityFunction function)
    : sigma_(sigma), K_(coefficient(sigma, beta, density)), E_(modulus), function_(function) {
    requirePositive(modulus, "composite modulus E* (Pa)");
}

double GreenwoodTripp::pressure(double h) const {
    const double lam = h / sigma_;
    return K_ * E_ * (function_ == AsperityFunction::Exact ? F52(lam) : F52Hu(lam));
}

double GreenwoodTripp::pressureSlope(double h) const {
    const double lam = h / sigma_;
    if (function_ == AsperityFunction::HuFit)
        return lam < 4.0 ? -K_ * E_ * 6.804 * 4.4086e-5 * std::pow(4.0 - lam, 5.804) / sigma_ : 0.0;
    return K_ * E_ * dF52(lam) / sigma_;
}

Eigen::VectorXd GreenwoodTripp::pressure(const Eigen::VectorXd& h) const {
    Eigen::VectorXd p(h.size());
    for (Eigen::Index k = 0; k < h.size(); ++k) p[k] = pressure(h[k]);
    return p;
}

}  // namespace flexehd::lube
