#pragma once
// RingGas: the gas round one ring of the pack at a step's end (docs/ring-pack.md, "The pack's gas
// in a run", "Ring lift in a run"), what the ring's film contact and the flexible piston's
// ring-belt loads read of the pack's gas.

#include <limits>

namespace flexehd::cosim {

/// The gap a ring's oil leaves open to the gas across its running faces (lube::openGap; the oil-
/// control ring's two lands in series, docs/ring-pack.md, "Gas past a face on the oil layer"):
/// ∫ dx/h_o³ over the faces (m⁻², +∞ where the oil closes the gap) and the narrowest open height (m).
struct RingOpenGap {
    double resistance = std::numeric_limits<double>::infinity();
    double narrowest = 0.0;
};

/// Pressures (Pa, gauge: relative to the crankcase) above the ring's face, behind it and below
/// it, the mass flow past it (kg/s, towards the crankcase > 0: through its end gap and, off its
/// lower flank, its groove's lower flank clearance) and, with ring_gas.ring_lift, its axial
/// position in the groove (m above the lower flank) and the force per unit of the bore's
/// circumference (N/m) its flank exerts on it (> 0 the lower flank pushing up, < 0 the upper
/// flank pushing down, 0 in flight), and the opening of its face off the liner where the gas has
/// collapsed it at the step's end and at its start (m, 0 on the liner; the flow past it then
/// includes its face's).
struct RingGas {
    double above = 0.0, behind = 0.0, below = 0.0;
    double flow = 0.0;
    double position = 0.0;
    double flankForce = 0.0;
    double faceOpening = 0.0, faceOpeningBefore = 0.0;
};

}  // namespace flexehd::cosim
