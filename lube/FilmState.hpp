#pragma once
// FilmState: what the caller supplies per film solve — nodal film thickness, its rate, and the
// velocities of the two surfaces bounding the film.
//
// "Inner" is the body inside the film (piston skirt, journal), "outer" the body outside it
// (liner, sleeve). Velocities are tangential, in the grid frame, with components along +z
// (axial) and along +θ (circumferential, m/s: for a journal spinning at ω, ωR). The Reynolds
// equation sees only their sum U = V_inner + V_outer (seed eq. 1 with u = U); the shear stress
// needs them separately. See docs/lube.md §1.
#include <Eigen/Core>

namespace flexehd::lube {

struct SurfaceVelocity {
    double axial = 0.0;            ///< m/s along +z
    double circumferential = 0.0;  ///< m/s along +θ
};

struct FilmState {
    Eigen::VectorXd h;     ///< film thickness at the nodes (m), > 0 on Film and Fixed nodes
    Eigen::VectorXd dhdt;  ///< ∂h/∂t at the nodes (m/s); empty means 0 (steady)
    SurfaceVelocity inner;
    SurfaceVelocity outer;

    /// Sum of the surface velocities, the U of the Couette term (U/2)∂(ρh)/∂x.
    double sumAxial() const { return inner.axial + outer.axial; }
    double sumCircumferential() const { return inner.circumferential + outer.circumferential; }
};

}  // namespace flexehd::lube
