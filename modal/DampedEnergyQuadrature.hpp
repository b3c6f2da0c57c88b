#pragma once
// DampedEnergyQuadrature: the energy a held reduced body's modal damping takes over a step,
//
//   D = ∫₀^Δt q̇ᵀ C q̇ dt   (C = ModalPropagator::dampingMatrix(), the damping its equations carry:
//                          modal damping and the damper supports' projected dashpots),
//
// by Gauss–Legendre quadrature (Abramowitz & Stegun 25.4.29) of the exact velocities within the
// step (ModalPropagator::responseWithin, the piecewise-exact response of Nigam & Jennings 1969).
// A check on the energy balance W = ΔE + D that does not go through it: the work W and the stored
// change ΔE come from the step's ends and the closed-form integral of q, D from the states inside.
// Each step is integrated with m and with 2m points; the 2m-point value is the estimate and
// |D_2m − D_m| its error bound: the integrand is analytic (sums of damped exponentials and
// polynomials), so the rule's error falls geometrically with the points and, once it does, the
// m-point error bounds the 2m-point one. The rule resolves a mode when m is above the number of
// its periods within a step (a mode far above 1/Δt needs m ≳ f Δt).
#include <vector>

#include <Eigen/Core>

#include "modal/GaussLegendre.hpp"
#include "modal/ModalPropagator.hpp"

namespace flexehd::modal {

struct DampedEnergy {
    double energy = 0.0;  ///< J, the 2m-point quadrature
    double error = 0.0;   ///< J, |D_2m − D_m|
};

class DampedEnergyQuadrature {
public:
    /// points: m, the coarser rule's (>= 1).
    explicit DampedEnergyQuadrature(int points);

    int points() const { return int(coarse_.nodes.size()); }
    /// Over the step of dt of the propagator's body from (q, q̇) = (y, w) under the force linear
    /// from fStart to fEnd.
    DampedEnergy overStep(const ModalPropagator& propagator, const Eigen::VectorXd& y, const Eigen::VectorXd& w, const Eigen::VectorXd& fStart,
                          const Eigen::VectorXd& fEnd, double dt) const;

private:
    QuadratureRule coarse_, fine_;
};

}  // namespace flexehd::modal
