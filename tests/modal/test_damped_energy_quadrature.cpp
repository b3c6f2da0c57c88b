// The damped energy by quadrature (modal::DampedEnergyQuadrature) against a closed form: two
// oscillators (unit masses, 1 and 2.5 kHz, ζ = 0.05) in the harmonic steady state of a triangle
// wave F tri(Ωt) at Ω/2π = 150 Hz, which is linear between its corners, so that four steps of
// T/4 carry it exactly (the propagator's force is linear over each step). The triangle wave is
// the series (8F/π²) Σ_{k odd} (−1)^((k−1)/2) sin(kΩt)/k²; each harmonic drives the mode to
// X̂_k = F_k/(ω² − (kΩ)² + i c kΩ) and its damping c = 2ζω takes π c kΩ |X̂_k|² per period
// of its own, k π c kΩ |X̂_k|² per period T of the wave, the cross terms vanishing over T. The steps span 1.7 and 4.2 of the modes' periods,
// so the integrand oscillates within a step and the rule converges as its points grow.
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "modal/DampedEnergyQuadrature.hpp"
#include "modal/GaussLegendre.hpp"
#include "modal/ModalPropagator.hpp"
#include "OscillatorModes.hpp"

using namespace flexehd;

namespace {

constexpr double kPi = std::numbers::pi;
const Eigen::Vector2d kOmega = 2.0 * kPi * Eigen::Vector2d(1000.0, 2500.0);
constexpr double kZeta = 0.05, kForce = 1.0, kDrive = 2.0 * kPi * 150.0;
constexpr int kHarmonics = 200001;  // the odd k up to this: the velocity's series alternates, tail < 1/k³

// The triangle wave's steady state at t = 0 (q, q̇) and its damped energy per period (J).
struct SteadyState {
    Eigen::Vector2d q = Eigen::Vector2d::Zero(), v = Eigen::Vector2d::Zero();
    double dampedPerPeriod = 0.0;
};

SteadyState triangleSteadyState() {
    SteadyState s;
    for (int j = 0; j < 2; ++j) {
        const double w = kOmega(j), c = 2.0 * kZeta * w;
        for (int k = kHarmonics; k >= 1; k -= 2) {  // smallest terms first
            const double fk = 8.0 * kForce / (kPi * kPi) * ((k / 2) % 2 == 0 ? 1.0 : -1.0) / (double(k) * k);
            const double wk = k * kDrive;
            const std::complex<double> x = fk / std::complex<double>(w * w - wk * wk, c * wk);
            s.q(j) += x.imag();         // Im(X̂ e^{ikΩt}) at t = 0
            s.v(j) += wk * x.real();    // Im(ikΩ X̂)
            s.dampedPerPeriod += k * kPi * c * wk * std::norm(x);  // k of its periods in T
        }
    }
    return s;
}

// The triangle wave at the step ends t = iT/4: 0, F, 0, −F, 0.
Eigen::VectorXd force(int i) {
    static const double corner[5] = {0.0, 1.0, 0.0, -1.0, 0.0};
    return Eigen::VectorXd::Constant(2, kForce * corner[i]);
}

}  // namespace

TEST(GaussLegendre, IntegratesPolynomialsOfDegreeTwoNMinusOneExactly) {
    for (int n : {1, 2, 5, 16, 64}) {
        const modal::QuadratureRule r = modal::gaussLegendre(n);
        for (int p = 0; p <= 2 * n - 1; ++p) {
            double sum = 0.0;
            for (std::size_t i = 0; i < r.nodes.size(); ++i) sum += r.weights[i] * std::pow(r.nodes[i], p);
            EXPECT_NEAR(sum, 1.0 / (p + 1), 1e-14) << n << " points, x^" << p;
        }
    }
    EXPECT_THROW(modal::gaussLegendre(0), std::invalid_argument);
}

TEST(DampedEnergyQuadrature, TakesPiCOmegaXSquaredPerPeriodOfATriangleWavesSteadyState) {
    const modal::ReducedBody body = test::oscillatorModes(kOmega, kZeta);
    const modal::ModalPropagator propagator(body, {});
    ASSERT_NEAR(propagator.damping()(1), 2.0 * kZeta * kOmega(1), 1e-12 * kOmega(1));
    const SteadyState s = triangleSteadyState();
    const double T = 2.0 * kPi / kDrive, dt = T / 4.0;
    // The states at the step ends, exactly (the propagator's); back where they started after T.
    std::vector<Eigen::VectorXd> y{s.q}, w{s.v};
    double work = 0.0;
    for (int i = 0; i < 4; ++i) {
        Eigen::MatrixXd q, v;
        propagator.responseWithin(y[i], w[i], force(i), force(i + 1), dt, {dt}, q, v);
        work += propagator.workOver(y[i], w[i], force(i), force(i + 1), dt, q.col(0));
        y.push_back(q.col(0));
        w.push_back(v.col(0));
    }
    EXPECT_NEAR((w[4] - w[0]).norm(), 0.0, 1e-9 * w[0].norm());  // the steady state: periodic
    std::printf("closed form %.15g J per period; the work %.15g J (%.2e)\n", s.dampedPerPeriod, work,
                work / s.dampedPerPeriod - 1.0);
    EXPECT_NEAR(work, s.dampedPerPeriod, 1e-9 * s.dampedPerPeriod);
    // The rule's m and 2m points: the error falls geometrically once m is above the periods per
    // step; the 2m-point error stays within the estimate |D_2m − D_m| plus round-off. The states'
    // round-off is measured by the exact work's departure from the closed form (the two are equal
    // but for it); the rate squares the velocity (twice that), and its sum adds a few ulps.
    const double eps = std::numeric_limits<double>::epsilon();
    const double roundoff = 2.0 * std::abs(work - s.dampedPerPeriod) + 16.0 * eps * s.dampedPerPeriod;
    double previous = 0.0;
    for (int m = 1; m <= 32; m *= 2) {
        const modal::DampedEnergyQuadrature rule(m);
        modal::DampedEnergy d;
        for (int i = 0; i < 4; ++i) {
            const modal::DampedEnergy step = rule.overStep(propagator, y[i], w[i], force(i), force(i + 1), dt);
            d.energy += step.energy;
            d.error += step.error;
        }
        const double error = std::abs(d.energy - s.dampedPerPeriod);
        std::printf("m = %2d / %2d points: D = %.15g J, error %.3e, estimate %.3e (relative %.2e, %.2e)\n", m, 2 * m,
                    d.energy, error, d.error, error / s.dampedPerPeriod, d.error / s.dampedPerPeriod);
        if (m >= 8) {  // m above the 4.2 periods per step: in the geometric regime
            EXPECT_LE(error, d.error + roundoff) << m;
            if (previous > roundoff) {  // at least 100× per doubling
                EXPECT_LT(error, 1e-2 * previous) << m;
            }
        }
        previous = error;
        if (m == 32) {
            EXPECT_LE(error, roundoff);
        }
    }
}
