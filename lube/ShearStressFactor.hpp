#pragma once
// ShearStressFactor: the mean Couette shear between rough surfaces (docs/lube.md §5), the shear
// stress factor of Patir & Cheng's average flow model (Patir & Cheng 1979, J. Lubr. Technol.
// 101:220–229): for isotropic Gaussian heights of composite rms σ, approximated by the
// polynomial density f(δ) = 35/(96σ) (1 − δ²/9σ²)³ on |δ| ≤ 3σ, the mean of η ΔV/h_T over the
// local gaps h_T = h − δ is φ_f(H) η ΔV/h with H = h/σ, z = H/3,
//
//   H ≤ 3:  φ_f = (35/32) z [(1 − z²)³ ln(300 (z + 1)) + (−55 + 132z + 345z² − 160z³ − 405z⁴ + 60z⁵ + 147z⁶)/60]
//   H > 3:  φ_f = (35/32) z [(1 − z²)³ ln((z + 1)/(z − 1)) + (z/15)(66 − 80z² + 30z⁴)]
//
// (local gaps below ε = σ/100 carry no Couette shear: ε/3σ = 1/300). φ_f → 1 for H → ∞ and
// φ_f/h stays finite as h → 0 (1.74/σ), so the shear where the surfaces touch does not depend on
// the film floor of the Reynolds equation. σ = 0: smooth surfaces, φ_f = 1.

namespace flexehd::lube {

class ShearStressFactor {
public:
    /// σ: composite rms roughness (m), ≥ 0; 0 for smooth surfaces.
    explicit ShearStressFactor(double sigma = 0.0);

    /// φ_f at the nominal film thickness h (m); h ≤ 0 as h = 0.
    double factor(double h) const;
    /// The Couette coefficient c = φ_f(h/σ)/h (1/m) of τ = φ η ΔV c, and its derivative ∂c/∂h.
    void couette(double h, double& c, double& dcdh) const;

    /// φ_f(H) and dφ_f/dH of the film parameter H = h/σ ≥ 0, from the closed form.
    static void ofFilmParameter(double H, double& phi, double& dphidH);
    /// The same as factor() and couette() use them: by cubic Hermite interpolation of
    /// the closed form (within 2e-10; to H = 90), beyond by its expansion in 1/z².
    static void interpolated(double H, double& phi, double& dphidH);

private:
    double sigma_, inverseSigma_;
};

}  // namespace flexehd::lube
