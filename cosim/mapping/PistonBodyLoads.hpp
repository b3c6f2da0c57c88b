#pragma once
// PistonBodyLoads: the modal loads on a flexible piston besides its films' (docs/coupling.md §2,
// "Gas and inertia loads on the flexible piston"):
//   - the cylinder's gas pressure over the crown, p_g = p_cyl − p_crankcase uniform on a surface
//     group: g_gas = p_g Φᵀ F₁ with F₁ the consistent nodal forces of a unit pressure;
//   - the inertia of the piston's rigid motion in the cylinder. In the frame that moves with the
//     pin axis (the held interface, reference point r₀) every point r accelerates by
//     a(r) = (ë + β̈ (z − z₀), 0, A − β̈ (x − x₀)) (A = Z̈ + g the pin's axial acceleration with
//     gravity, ë and β̈ the secondary motion's; the centripetal β̇² r terms, about 0.2 % of A's
//     peak, are left out as in the equations of motion), so the body carries the force density
//     −ρ a(r): g_in = −Φᵀ M R [ë, β̈, A]ᵀ with R the three rigid fields. R lies in the reduced
//     basis (R = Φ c through its constraint modes) and Φᵀ M Φ = I, so Φᵀ M R = c: no mass matrix
//     is needed, c is the basis's own least-squares fit of R.
//   - the ring pack (`ring_pack`): the gas of the lands and grooves and the rings' forces on the
//     groove flanks, each uniform on its part of the piston's ring belt (RingBeltLoads).
// All are computed once per body; each evaluation is an axpy of m-vectors. The static response
// to them is exact only where the basis holds it: inertia relief always (docs/modal.md), the
// crown's gas pressure with `flexehd reduce --pressure-pattern crown`, the ring belt's with its
// bands' patterns; a body without a pattern it needs is refused.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cosim/case/EngineCase.hpp"
#include "cosim/engine/RingGas.hpp"
#include "cosim/mapping/FlexibleBody.hpp"
#include "cosim/mapping/RingBeltLoads.hpp"

namespace flexehd::cosim {

class PistonBodyLoads {
public:
    /// The loads on `piston` about its first held interface's reference point. Throws
    /// std::invalid_argument naming the group or the missing pattern (and the `reduce` option
    /// that makes it); `file` names the reduced body in those messages.
    /// rings and bore (m): the case's pack, for `ring_pack`.
    PistonBodyLoads(const FlexibleBody& piston, const PistonLoadSpec& spec, const std::string& file,
                    const std::vector<RingSpec>& rings = {}, double bore = 0.0);

    /// The modal load (m) for the gauge gas pressure pGauge (Pa), the secondary accelerations
    /// (ë m/s², β̈ rad/s²), the pin's axial acceleration with gravity A (m/s²) and, with
    /// `ring_pack`, the gas round each ring and its flank force (null: none).
    void add(double pGauge, const Eigen::Vector2d& secondaryAcceleration, double axialAcceleration,
             const std::vector<RingGas>* ringGas, Eigen::Ref<Eigen::VectorXd> f) const;
    /// ∂g/∂(ë, β̈) (m × 2): zero without inertia.
    const Eigen::MatrixXd& secondaryAccelerationColumns() const { return inertiaSecondary_; }
    /// Worst relative residual |Φ c − R| / |R| of the rigid fields' fit (0 without inertia).
    double rigidFitResidual() const { return fitResidual_; }

private:
    PistonLoadSpec spec_;
    Eigen::VectorXd gasUnit_, inertiaAxial_;
    Eigen::MatrixXd inertiaSecondary_;
    double fitResidual_ = 0.0;
    std::optional<RingBeltLoads> ringBelt_;
};

}  // namespace flexehd::cosim
