#pragma once
// RingAxialMotion: a ring's axial position in its groove (docs/ring-pack.md). Per unit
// circumference the ring of mass m moves with the piston but for its travel z ∈ [0, c] across the
// groove's side clearance c (0: on the lower flank); the net axial force on it in the piston's
// frame — gas (the pressure above minus below, over the ring's radial width), inertia (−m times
// the piston's acceleration) and the liner film's friction — drives it:
//
//   m z̈ = F   between the flanks;   on a flank, held there while F presses it on (the flank
//   carries −F), lifting when F changes sign,
//
// stepped semi-implicitly (velocity, then position); reaching a flank the ring stops there
// (inelastic: the oil in the groove takes the impact). RingPackGas steps a ring's radial collapse
// by the same law, between the liner and its groove's root.
namespace flexehd::cosim {

class RingAxialMotion {
public:
    /// mass per unit circumference (kg/m, > 0), side clearance (m, > 0); starts at rest on the
    /// lower flank.
    RingAxialMotion(double mass, double sideClearance);

    /// One step of dt (s) under the net upward force F (N/m).
    void step(double dt, double force);

    double position() const { return z_; }  ///< m above the lower flank
    double velocity() const { return v_; }  ///< m/s, upward > 0
    bool onLowerFlank() const { return z_ <= 0.0 && v_ == 0.0; }
    bool onUpperFlank() const { return z_ >= c_ && v_ == 0.0; }
    /// The force a flank carries at the last step's end (N/m; > 0 the lower flank pushing up,
    /// < 0 the upper flank pushing down, 0 in flight).
    double flankForce() const { return flank_; }

private:
    double m_, c_, z_ = 0.0, v_ = 0.0, flank_ = 0.0;
};

}  // namespace flexehd::cosim
