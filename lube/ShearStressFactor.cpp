#include "lube/ShearStressFactor.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace flexehd::lube {

namespace {

constexpr double kScale = 35.0 / 32.0;

// H > 9 (z > 3): the closed form loses digits to cancellation (its terms grow as z⁵, its sum is
// about 1); its expansion φ_f = 1 + Σ_m a_m z^(−2m) with
// a_m = (35/16) [1/(2m+1) − 3/(2m+3) + 3/(2m+5) − 1/(2m+7)] (a_1 = 1/9, a_2 = 1/33), to z^(−20).
constexpr int kTerms = 10;

constexpr std::array<double, kTerms + 1> seriesCoefficients() {
    std::array<double, kTerms + 1> a{};
    a[0] = 1.0;
    for (int m = 1; m <= kTerms; ++m)
        a[m] = 2.0 * kScale * (1.0 / (2 * m + 1) - 3.0 / (2 * m + 3) + 3.0 / (2 * m + 5) - 1.0 / (2 * m + 7));
    return a;
}
constexpr std::array<double, kTerms + 1> kSeries = seriesCoefficients();

void largeFilm(double z, double& phi, double& dphidz) {
    // Horner in w = 1/z²: φ = Σ a_m w^m, dφ/dz = −(2/z) Σ m a_m w^m.
    const double w = 1.0 / (z * z);
    double p = kSeries[kTerms], q = kTerms * kSeries[kTerms];
    for (int m = kTerms - 1; m >= 0; --m) {
        p = p * w + kSeries[m];
        q = q * w + m * kSeries[m];
    }
    phi = p;
    dphidz = -2.0 * q / z;
}

// The factor is evaluated at every node of every film evaluation: cubic Hermite interpolation of
// the closed form and its slope, stored per interval as the cubic's coefficients in t ∈ [0, 1] —
// for H ≤ 9 at steps of 0.0025 (a node at H = 3, where the branches meet with equal value and
// slope), for 9 < H ≤ 90 at steps of 0.05 — within 2e-10 of the closed form; beyond, its
// expansion's first three terms (the fourth below 2e-11).
constexpr double kNearEnd = 9.0, kNearStep = 0.0025, kFarEnd = 90.0, kFarStep = 0.05;

struct HermiteTable {
    std::vector<double> cubic;  // per interval: φ = c0 + t (c1 + t (c2 + t c3))
    double start, inverseStep;
    int intervals = 0;
    HermiteTable(double from, double to, double step) : start(from), inverseStep(1.0 / step) {
        intervals = static_cast<int>(std::lround((to - from) / step));
        cubic.resize(4 * static_cast<std::size_t>(intervals));
        double a, da, b, db;
        ShearStressFactor::ofFilmParameter(from, a, da);
        for (int i = 0; i < intervals; ++i) {
            ShearStressFactor::ofFilmParameter(from + (i + 1) * step, b, db);
            const double sa = step * da, sb = step * db;
            double* c = &cubic[4 * static_cast<std::size_t>(i)];
            c[0] = a;
            c[1] = sa;
            c[2] = 3.0 * (b - a) - 2.0 * sa - sb;
            c[3] = 2.0 * (a - b) + sa + sb;
            a = b;
            da = db;
        }
    }
    void at(double H, double& phi, double& dphidH) const {
        const double x = (H - start) * inverseStep;
        const int i = std::min(static_cast<int>(x), intervals - 1);
        const double t = x - i;
        const double* c = &cubic[4 * static_cast<std::size_t>(i)];
        phi = c[0] + t * (c[1] + t * (c[2] + t * c[3]));
        dphidH = (c[1] + t * (2.0 * c[2] + 3.0 * t * c[3])) * inverseStep;
    }
};

const HermiteTable kNear(0.0, kNearEnd, kNearStep), kFar(kNearEnd, kFarEnd, kFarStep);

}  // namespace

void ShearStressFactor::interpolated(double H, double& phi, double& dphidH) {
    if (H > kFarEnd) {  // φ = 1 + w/9 + w²/33 in w = 1/z² = 9/H²
        const double w = 9.0 / (H * H);
        phi = 1.0 + w * (kSeries[1] + w * kSeries[2]);
        dphidH = -2.0 * w * (kSeries[1] + 2.0 * w * kSeries[2]) / H;
        return;
    }
    if (H > kNearEnd) {
        kFar.at(H, phi, dphidH);
        return;
    }
    kNear.at(std::max(H, 0.0), phi, dphidH);
    if (H < 0.0) dphidH = 0.0;
}

ShearStressFactor::ShearStressFactor(double sigma) : sigma_(sigma), inverseSigma_(sigma > 0.0 ? 1.0 / sigma : 0.0) {
    if (!(sigma >= 0.0) || !std::isfinite(sigma))
        throw std::invalid_argument("ShearStressFactor: the composite roughness must be >= 0 m");
}

void ShearStressFactor::ofFilmParameter(double H, double& phi, double& dphidH) {
    const double z = std::max(H, 0.0) / 3.0;
    double dphidz = 0.0;
    if (z > 3.0) {
        largeFilm(z, phi, dphidz);
    } else {
        const double u = 1.0 - z * z, u2 = u * u, u3 = u2 * u;
        double L, dL, Q, dQ;
        if (z <= 1.0) {
            L = std::log(300.0 * (z + 1.0));
            dL = 1.0 / (z + 1.0);
            Q = (-55.0 + z * (132.0 + z * (345.0 + z * (-160.0 + z * (-405.0 + z * (60.0 + z * 147.0)))))) / 60.0;
            dQ = (132.0 + z * (690.0 + z * (-480.0 + z * (-1620.0 + z * (300.0 + z * 882.0))))) / 60.0;
            dphidz = kScale * (u3 * L + Q) + kScale * z * (-6.0 * z * u2 * L + u3 * dL + dQ);
        } else {
            L = std::log((z + 1.0) / (z - 1.0));
            Q = z * (66.0 + z * z * (-80.0 + 30.0 * z * z)) / 15.0;
            dQ = (66.0 + z * z * (-240.0 + 150.0 * z * z)) / 15.0;
            // (1 − z²)³ dL/dz = (1 − z²)³ (−2/(z² − 1)) = 2 (1 − z²)²
            dphidz = kScale * (u3 * L + Q) + kScale * z * (-6.0 * z * u2 * L + 2.0 * u2 + dQ);
        }
        phi = kScale * z * (u3 * L + Q);
    }
    dphidH = dphidz / 3.0;  // at H ≤ 0: the slope at H = 0 from above
}

double ShearStressFactor::factor(double h) const {
    if (sigma_ == 0.0) return 1.0;
    double phi, d;
    interpolated(h / sigma_, phi, d);
    return phi;
}

void ShearStressFactor::couette(double h, double& c, double& dcdh) const {
    if (sigma_ == 0.0) {
        c = 1.0 / h;
        dcdh = -1.0 / (h * h);
        return;
    }
    // Where the surfaces touch (h ≤ 0) the coefficient's limit at h → 0.
    const double hc = std::max(h, 1e-6 * sigma_), inverse = 1.0 / hc;
    double phi, dphidH;
    interpolated(hc * inverseSigma_, phi, dphidH);
    c = phi * inverse;
    dcdh = h >= hc ? (dphidH * inverseSigma_ - c) * inverse : 0.0;
}

}  // namespace flexehd::lube
