#pragma once
// StepSolver: one time step of the co-simulation (docs/coupling.md §1) — from an accepted state
// to the next: the step's BDF2 context, the predictor, and the iteration over the film contacts
// and the flexible bodies until the motion and the coupling residual meet their tolerances. How a
// pass moves the iterate is the coupling scheme's, chosen once (CouplingScheme.hpp):
// CoupledNewtonScheme with coupling.method newton and flexible bodies, PartitionedScheme
// otherwise; both take the motion's finite-difference columns from perturbedMotion. The bodies'
// response to the contacts' summed modal load is the solver's: quasi-static (FlexibleBody) or,
// with bodies.response: dynamic, the BDF2 modal dynamics (modal::HeldModalDynamics); with
// bodies.piston.loads the piston's modal load also carries the crown's gas pressure and the
// inertia of its rigid motion at the iterate's accelerations (PistonBodyLoads).
//
// Translation units: StepSolver.cpp (the step), IterateEvaluation.cpp (one iterate).

#include "cosim/case/EngineCase.hpp"
#include "cosim/contact/FilmContact.hpp"
#include "cosim/coupling/CouplingResidual.hpp"
#include "cosim/coupling/CouplingScheme.hpp"
#include "cosim/coupling/StepState.hpp"
#include "cosim/engine/CrankKinematics.hpp"
#include "cosim/engine/CylinderPressure.hpp"
#include "cosim/engine/PistonDynamics.hpp"
#include "cosim/ringpack/RingPackGas.hpp"
#include "cosim/mapping/FlexibleBody.hpp"
#include "cosim/mapping/PistonBodyLoads.hpp"
#include "modal/ModalStepper.hpp"

#include <Eigen/Core>

#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace flexehd::cosim {

class StepSolver {
public:
    /// The solver of the case's steps over the contacts (held by reference: the caller may add
    /// contacts, then calls contactsChanged) and the flexible bodies (null: rigid).
    /// linerOffset(crank angle in degrees): the liner-frame z of the piston frame's origin. The
    /// contacts' and the response's work is counted into `work`.
    StepSolver(const EngineCase& c, const CrankKinematics& kin, const PistonDynamics& dyn,
               const CylinderPressure& pressure, const std::vector<std::unique_ptr<FilmContact>>& contacts,
               std::shared_ptr<const FlexibleBody> piston, std::shared_ptr<const FlexibleBody> liner,
               std::function<double(double)> linerOffset, WorkTally& work);
    ~StepSolver();

    /// One step of dtDeg from s (prev: the state before it) into out, with the accepted iterate
    /// in ev and the film solves it took in iterations; false with the reason in failure when the
    /// iteration fails (the caller shortens the step).
    bool advance(const StepState& s, const StepState& prev, double dtDeg, StepState& out, StepEvaluation& ev,
                 int& iterations, std::string& failure);
    /// After a contact was added: the new contacts are told what the scheme needs (prepare), the
    /// scheme updates its units.
    void contactsChanged();
    /// bodies.response: dynamic (the states carry modal velocities).
    bool dynamicResponse() const { return pistonDynamics_ || linerDynamics_; }
    /// Jacobians since the last accepted step whose quasi-static modal block folded
    /// (det(I − ∂H/∂y) < 0: the skirt's equilibrium in the film is lost; docs/coupling.md §3).
    int foldedJacobians() const { return foldedJacobians_; }
    void stepAccepted() {
        foldedJacobians_ = 0;
        if (packGas_) packGas_->accept();
    }
    /// The Newton iteration's start for the motion from s (prev: the state before it): the
    /// second-order predictor x + Δt v + ½ Δt² a, or the first-order one x + Δt v where that
    /// predicted the last step (prev → s) better, in units of `scale` (docs/coupling.md §1).
    static Eigen::Vector2d predictedMotion(const StepState& s, const StepState& prev, double dt,
                                           const Eigen::Vector2d& scale);
    /// The iteration's start for the modal coordinates from s: with `quadratic` the quadratic
    /// through the last three states' y (prev.yFrom, prev.y, s.y), else (or where fewer are known)
    /// the linear extrapolation through the last two, s.y on the first step (docs/coupling.md §1).
    static Eigen::VectorXd predictedModal(const StepState& s, const StepState& prev, double dt, bool quadratic);
    /// The same extrapolation of any modal vector the states carry: v at s, at prev and at the
    /// state before prev (empty where unknown; empty result where the extrapolation needs it).
    static Eigen::VectorXd extrapolatedModal(const StepState& s, const StepState& prev, double dt, bool quadratic,
                                             const Eigen::VectorXd& now, const Eigen::VectorXd& before,
                                             const Eigen::VectorXd& beforeThat);

private:
    // The schemes are parts of the step: they evaluate the motion's difference columns
    // (perturbedMotion) and the coupled Jacobian the bodies' response.
    friend class CoupledNewtonScheme;
    friend class PartitionedScheme;

    /// One iterate (e, β, y) of the step: every contact's film and action, the motion's residual
    /// and (structure) the bodies' response H(y) to the contacts' modal loads.
    StepEvaluation evaluate(const StepContext& ctx, const Eigen::Vector2d& x, const Eigen::VectorXd& y, bool structure);
    // The stages of evaluate.
    void motionResidual(const StepContext& ctx, const Eigen::Vector2d& x, StepEvaluation& ev) const;
    void structureResponse(const StepContext& ctx, StepEvaluation& ev);
    // The stages of advance (StepSolver.cpp).
    StepContext stepContext(const StepState& s, const StepState& prev, double dtDeg);
    StepTolerances stepTolerances() const;
    /// The largest film-thickness change of the modal change d over every contact's film.
    double largestFilmChange(const StepContext& ctx, const Eigen::VectorXd& d);
    /// max |Δh(H(y)) − Δh(y)| over every contact's film (m), computed where a test needs it.
    CouplingResidual couplingResidual(const StepContext& ctx, const StepEvaluation& ev, const Eigen::VectorXd& y);
    /// The step's evaluations at x + δ_i e_i (i = e, β; y held; with the bodies' response when
    /// `structure`), each counted in `solves`: the finite-difference columns of the motion unknowns
    /// for both schemes. False if a film solve failed.
    bool perturbedMotion(const StepContext& ctx, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                         const Eigen::Vector2d& delta, bool structure, std::array<StepEvaluation, 2>& moved,
                         int& solves);
    void acceptStep(const StepContext& ctx, const StepState& s, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                    const StepEvaluation& ev, StepState& out) const;
    /// The bodies' quasi-static response to the step's given loads (bodies.piston.loads at the
    /// step's cylinder pressure, crank acceleration and ring-pack gas, no secondary acceleration);
    /// empty without such loads or with a dynamic piston.
    Eigen::VectorXd givenLoadResponse(const StepContext& ctx) const;
    /// N per ring of the pack's gas model (top first): the liner film's axial force on it at s.
    std::vector<double> ringFriction(const StepState& s) const;
    /// Per ring of the pack's gas model: the gap its oil left open to the gas at s.
    std::vector<RingOpenGap> ringOpenGaps(const StepState& s) const;

    const EngineCase& case_;
    const CrankKinematics& kin_;
    const PistonDynamics& dyn_;
    const CylinderPressure& pressure_;
    const std::vector<std::unique_ptr<FilmContact>>& contacts_;
    std::shared_ptr<const FlexibleBody> pistonBody_, linerBody_;
    std::function<double(double)> linerOffset_;
    WorkTally& work_;
    int mp_ = 0, ml_ = 0;  // modal coordinates of piston and liner
    // bodies.response: dynamic — BDF2 modal dynamics per flexible body (null: quasi-static)
    std::unique_ptr<modal::ModalStepper> pistonDynamics_, linerDynamics_;
    std::unique_ptr<CouplingScheme> scheme_;  // chosen once (ctor)
    std::unique_ptr<RingPackGas> packGas_;    // ring_gas: the lands' gas (null: none)
    std::unique_ptr<PistonBodyLoads> pistonLoads_;  // bodies.piston.loads on the flexible piston (null: none)
    std::size_t preparedContacts_ = 0;       // contacts told the scheme's needs
    int foldedJacobians_ = 0;        // Jacobians of the current step with det(I − ∂H/∂y) < 0 (quasi-static, rigid rate)
};

}  // namespace flexehd::cosim
