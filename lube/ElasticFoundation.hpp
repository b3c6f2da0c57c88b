#pragma once
// ElasticFoundation: the hard contact of two surfaces whose mean planes overlap (film thickness
// h < 0), carried by the elastic deformation of a thin surface layer — the skirt coating — on a
// stiffer substrate (Winkler foundation; Johnson, Contact Mechanics, 1985, §5.8; docs/lube.md §4):
//   p_hard(h) = K · max(0, −h)   (Pa),
// with, for a layer of thickness t, Young's modulus E and Poisson's ratio ν bonded to the
// substrate (laterally constrained, uniaxial strain),
//   K = E (1 − ν) / [(1 + ν)(1 − 2ν) t]   (Pa/m).
// An impact on the layer loses energy (docs/lube.md §4, "Impact damping"): with a coefficient of
// restitution e < 1 each point of the layer is a spring with hysteresis damping (Hunt & Crossley
// 1975; Lankarani & Nikravesh 1990),
//   p_hard = K δ · max(0, 1 + χ δ̇/δ̇₀),   δ = −h, δ̇ = −ḣ,
// δ̇₀ the impact speed (the largest approach speed since the point touched, at least
// kQuasiStaticSpeed: a point pressed slower is loaded quasi-statically, its damping vanishing with
// its rate). χ(e) is the factor
// that gives a mass striking the linear layer at any speed the rebound speed e δ̇₀; it tends to
// Lankarani & Nikravesh's (3/4)(1 − e²) as e → 1.
// The asperity pressure (GreenwoodTripp) of the rough surfaces acts in parallel above h = 0; the
// bodies' own compliance (a flexible piston or liner) acts in series through the modal response.
namespace flexehd::lube {

class ElasticFoundation {
public:
    /// m/s, the smallest impact speed: a contact loaded slower than this is not an impact.
    static constexpr double kQuasiStaticSpeed = 1e-3;

    /// Throws std::invalid_argument unless stiffness > 0 (Pa/m) and 0 < restitution ≤ 1.
    explicit ElasticFoundation(double stiffness, double restitution = 1.0);

    /// K of a bonded layer: E > 0 (Pa), −1 < ν < 0.5, thickness > 0 (m). Throws otherwise.
    static double layerStiffness(double youngsModulus, double poissonRatio, double thickness);
    /// χ of the linear layer for the coefficient of restitution e (0 < e ≤ 1): the rebound of the
    /// dimensionless impact ξ'' = −ξ max(0, 1 + χ ξ'), ξ(0) = 0, ξ'(0) = 1, solved for χ.
    static double hysteresisFactor(double restitution);

    /// Elastic contact pressure (Pa) at the film thickness h (m): 0 for h ≥ 0.
    double pressure(double h) const { return h < 0.0 ? -stiffness_ * h : 0.0; }
    /// ∂p/∂h (Pa/m) of the elastic pressure: −K for h < 0, else 0.
    double pressureSlope(double h) const { return h < 0.0 ? -stiffness_ : 0.0; }
    /// The damped contact pressure (Pa) at h (m), approach speed −ḣ (m/s) and impact speed δ̇₀ ≥ the
    /// approach speed (m/s; 0: no damping).
    double pressure(double h, double approach, double impactSpeed) const;
    /// ∂p/∂h (Pa/m) of the damped pressure where the approach speed changes with h by
    /// ∂(−ḣ)/∂h = −rateSlope (the step's a0/Δt, 1/s) and the impact speed is held.
    double pressureSlope(double h, double approach, double impactSpeed, double rateSlope) const;
    double stiffness() const { return stiffness_; }
    double restitution() const { return restitution_; }
    double dampingFactor() const { return chi_; }
    bool damped() const { return chi_ > 0.0; }

private:
    double stiffness_;
    double restitution_;
    double chi_;  // χ(e)
};

}  // namespace flexehd::lube
