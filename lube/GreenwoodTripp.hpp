#pragma once
// GreenwoodTripp: asperity contact pressure of two rough surfaces (Greenwood & Tripp 1970;
// seed eq. 3):
//   p_c(h) = K E* F_{5/2}(h/σ),   K = (16√2 π/15) (η_s β σ)² √(σ/β),
//   F_n(λ) = (2π)^(-1/2) ∫_λ^∞ (s − λ)^n e^(−s²/2) ds.
// σ: composite rms roughness (m), β: asperity tip radius (m), η_s: asperity density (1/m²).
// E* is the Hertz composite modulus 1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂ (NOT the 2/E′ convention
// used by many piston papers, which doubles p_c).
//
// F_{5/2} is tabulated once (−2 ≤ λ ≤ 8, step 0.01; Gauss–Legendre quadrature after s = λ + t²)
// and interpolated by cubic Hermite on ln F with the exact slope dF_{5/2}/dλ = −(5/2) F_{3/2}
// (relative interpolation error < 1e-8). F_{5/2}(8) ≈ 2e-17: zero beyond. The Hu et al. (1994)
// fit 4.4086e-5 (4−λ)^6.804 is available for comparison with the literature only.
#include <Eigen/Core>

namespace flexehd::lube {

enum class AsperityFunction { Exact, HuFit };

class GreenwoodTripp {
public:
    /// sigma, beta, asperityDensity, compositeModulus all positive (SI).
    GreenwoodTripp(double sigma, double beta, double asperityDensity, double compositeModulus,
                   AsperityFunction function = AsperityFunction::Exact);

    /// K = (16√2π/15)(η_s β σ)² √(σ/β)  (dimensionless).
    static double coefficient(double sigma, double beta, double asperityDensity);
    /// Hertz composite modulus E* from 1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂.
    static double compositeModulus(double E1, double nu1, double E2, double nu2);

    /// F_n(λ) by direct quadrature (reference; slow).
    static double integralF(double n, double lambda);
    /// F_{5/2}(λ) from the table (direct quadrature below λ = −2, 0 above λ = 8).
    static double F52(double lambda);
    /// dF_{5/2}/dλ = −(5/2) F_{3/2}(λ): the derivative of F52's interpolant (direct quadrature
    /// below λ = −2, 0 above λ = 8).
    static double dF52(double lambda);
    /// Hu et al. fit: 4.4086e-5 (4−λ)^6.804 for λ < 4, else 0.
    static double F52Hu(double lambda);

    /// Contact pressure (Pa) at film thickness h (m).
    double pressure(double h) const;
    /// ∂p_c/∂h (Pa/m), for Newton iterations on the secondary motion.
    double pressureSlope(double h) const;
    Eigen::VectorXd pressure(const Eigen::VectorXd& h) const;

    double sigma() const { return sigma_; }
    double K() const { return K_; }
    double modulus() const { return E_; }

private:
    double sigma_, K_, E_;
    AsperityFunction function_;
};

}  // namespace flexehd::lube
