#pragma once
// ElasticFoundation: the hard contact of two surfaces whose mean planes overlap (film thickness
// h < 0), carried by the elastic deformation of a thin surface layer — the skirt coating — on a
// stiffer substrate (Winkler foundation; Johnson, Contact Mechanics, 1985, §5.8; docs/lube.md §5):
//   p_hard(h) = K · max(0, −h)   (Pa),
// with, for a layer of thickness t, Young's modulus E and Poisson's ratio ν bonded to the
// substrate (laterally constrained, uniaxial strain),
//   K = E (1 − ν) / [(1 + ν)(1 − 2ν) t]   (Pa/m).
// The asperity pressure (GreenwoodTripp) of the rough surfaces acts in parallel above h = 0; the
// bodies' own compliance (a flexible piston or liner) acts in series through the modal response.
namespace flexehd::lube {

class ElasticFoundation {
public:
    /// Throws std::invalid_argument unless stiffness > 0 (Pa/m).
    explicit ElasticFoundation(double stiffness);

    /// K of a bonded layer: E > 0 (Pa), −1 < ν < 0.5, thickness > 0 (m). Throws otherwise.
    static double layerStiffness(double youngsModulus, double poissonRatio, double thickness);

    /// Contact pressure (Pa) at the film thickness h (m): 0 for h ≥ 0.
    double pressure(double h) const { return h < 0.0 ? -stiffness_ * h : 0.0; }
    /// ∂p/∂h (Pa/m): −K for h < 0, else 0.
    double pressureSlope(double h) const { return h < 0.0 ? -stiffness_ : 0.0; }
    double stiffness() const { return stiffness_; }

private:
    double stiffness_;
};

}  // namespace flexehd::lube
