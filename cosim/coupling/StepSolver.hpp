#pragma once
// StepSolver: one time step of the co-simulation (docs/coupling.md §1) — from an accepted state
// to the next: the step's BDF2 context, the predictor, and the Newton/coupling iteration over the
// film contacts and the flexible bodies until the motion and the coupling residual meet their
// tolerances. coupling.method newton: Newton on (e, β, y) with the coupled Jacobian
// (CoupledNewton.cpp), a line search, Broyden updates within the step and a Levenberg–Marquardt
// step where it is nearly singular; coupling.method partitioned (or rigid bodies): Newton on the
// motion with a finite-difference Jacobian and the accelerated modal fixed point. The bodies'
// response to the contacts' summed modal load is the solver's: quasi-static (FlexibleBody) or,
// with bodies.response: dynamic, the BDF2 modal dynamics (modal::HeldModalDynamics).
//
// Translation units: StepSolver.cpp (the step and its passes), IterateEvaluation.cpp (one
// iterate), CoupledNewton.cpp (the coupled Jacobian).

#include "cosim/case/EngineCase.hpp"
#include "cosim/contact/FilmContact.hpp"
#include "cosim/coupling/CouplingAccelerator.hpp"
#include "cosim/coupling/StepState.hpp"
#include "cosim/engine/CrankKinematics.hpp"
#include "cosim/engine/CylinderPressure.hpp"
#include "cosim/engine/PistonDynamics.hpp"
#include "cosim/mapping/FlexibleBody.hpp"
#include "modal/HeldModalDynamics.hpp"

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
    /// After a contact was added: the partitioned iteration's units.
    void contactsChanged();
    /// bodies.response: dynamic (the states carry modal velocities).
    bool dynamicResponse() const { return pistonDynamics_ || linerDynamics_; }
    /// Jacobians since the last accepted step whose quasi-static modal block folded
    /// (det(I − ∂H/∂y) < 0: the skirt's equilibrium in the film is lost; docs/coupling.md §3).
    int foldedJacobians() const { return foldedJacobians_; }
    void stepAccepted() { foldedJacobians_ = 0; }

private:
    // The modal columns of the coupled Newton method's Jacobian at one linearisation, affine in the
    // rate r = a0/Δt (CoupledNewton.cpp): motion rows motionH + r motionRate, modal rows
    // I − response(modalH + r modalRate) per body; the rate parts are empty without
    // coupling.elastic_squeeze.
    struct CoupledJacobianParts {
        bool valid = false;
        Eigen::MatrixXd motionH, motionRate;    // 2 × modes
        Eigen::MatrixXd modalH, modalRate;      // modes × modes: the contacts' modal loads (piston rows, liner rows)
        Eigen::VectorXd filmChangePerUnknown;   // 2 + modes: the contacts' largest film change per unit
    };

    // The step's convergence tolerances (StepSolver.cpp).
    struct StepTolerances {
        Eigen::Vector2d motion;  // (m, rad): the clearance, and the clearance over the reach
        double reach = 0.0;      // m, the skirt's largest distance from the pin axis
        double forceFloor = 0.0; // N, the reciprocating inertia force m r ω²
        double coupling = 0.0;   // m, coupling.tolerance × clearance
    };

    // coupling.method newton: the last accepted iterate of the step (its measure, merit, unknowns and
    // residual) and the line search's state.
    struct NewtonIterate {
        double acceptedMeasure = std::numeric_limits<double>::infinity();
        double acceptedMerit = std::numeric_limits<double>::infinity();
        Eigen::Vector2d acceptedX = Eigen::Vector2d::Zero();
        Eigen::VectorXd acceptedY, acceptedF;
        int backtracks = 0;
        bool freshJacobian = false, regularize = false, revisit = false;
    };

    /// One iterate (e, β, y) of the step: every contact's film and action, the motion's residual
    /// and (structure) the bodies' response H(y) to the contacts' modal loads.
    StepEvaluation evaluate(const StepContext& ctx, const Eigen::Vector2d& x, const Eigen::VectorXd& y, bool structure);
    // The stages of evaluate.
    void motionResidual(const StepContext& ctx, const Eigen::Vector2d& x, StepEvaluation& ev) const;
    void structureResponse(const StepContext& ctx, StepEvaluation& ev);
    // The stages of advance (StepSolver.cpp).
    enum class PassOutcome { Retry, Failed, Update };
    StepContext stepContext(const StepState& s, const StepState& prev, double dtDeg);
    StepTolerances stepTolerances() const;
    /// max |Δh(H(y)) − Δh(y)| over every contact's film (m).
    double couplingResidual(const StepContext& ctx, const StepEvaluation& ev, const Eigen::VectorXd& y);
    /// coupling.method newton: the line search, the Jacobian kept, re-formed or Broyden-updated,
    /// and the damped update dz of (e, β, y); Retry: x, y were moved back (evaluate again).
    PassOutcome coupledNewtonPass(const StepContext& ctx, const StepTolerances& tol, const StepEvaluation& ev,
                                  double couplingRes, NewtonIterate& it, Eigen::Vector2d& x, Eigen::VectorXd& y,
                                  int& iterations, Eigen::VectorXd& dz, bool& resolved, std::string& why);
    /// The coupled Newton iteration has converged to the resolution of its unknowns.
    bool resolvedToTheUnknownsResolution(const StepTolerances& tol, const StepEvaluation& ev, double couplingRes,
                                         const Eigen::VectorXd& dz) const;
    /// The step's evaluations at x + δ_i e_i (i = e, β; y held; with the bodies' response when
    /// `structure`), each counted in `solves`: the finite-difference columns of the motion unknowns
    /// for both schemes. False if a film solve failed.
    bool perturbedMotion(const StepContext& ctx, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                         const Eigen::Vector2d& delta, bool structure, std::array<StepEvaluation, 2>& moved,
                         int& solves);
    /// The finite-difference Jacobian of the motion residual (modal coordinates frozen).
    bool motionJacobian(const StepContext& ctx, const StepTolerances& tol, const Eigen::Vector2d& x,
                        const Eigen::VectorXd& y, const StepEvaluation& ev, int& iterations);
    /// coupling.method partitioned: the accelerated fixed-point map of (e, β, y).
    /// The accelerator (accelerator_) holds the step's history of the map.
    void partitionedUpdate(const StepEvaluation& ev, const Eigen::Vector2d& dx, Eigen::Vector2d& x, Eigen::VectorXd& y);
    void acceptStep(const StepContext& ctx, const StepState& s, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                    const StepEvaluation& ev, StepState& out) const;
    // The coupled Jacobian (CoupledNewton.cpp).
    /// coupling.method newton: linearises (motion residual, y − H(y)) in (e, β, y) at the
    /// evaluation into the parts of CoupledJacobianParts (docs/coupling.md §1, §3)
    void linearizeCoupled(const StepContext& ctx, const Eigen::Vector2d& x, const StepEvaluation& ev);
    /// ∂(equations of motion's right-hand side)/∂(F_x, ·, F_z, ·, M_y, ·): 2 × 6, from the dynamics.
    Eigen::Matrix<double, 2, 6> actionGradient(const StepContext& ctx) const;
    /// Good Broyden update of the kept inverse Jacobian for the update s and the residual change dF.
    void broydenUpdate(const Eigen::VectorXd& s, const Eigen::VectorXd& dF);
    /// Forms the coupled Jacobian at the context's step size (its (e, β) columns by differences of
    /// two full evaluations, counted in filmSolves) and its inverse; false if a film solve failed.
    bool formCoupledJacobian(const StepContext& ctx, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                             const StepEvaluation& ev, const Eigen::Vector2d& tol, int& filmSolves);
    /// The tolerance of each residual row: motion rows 1e-4 (scale + force floor), modal rows the
    /// coupling tolerance over the largest film change of a unit of the mode.
    Eigen::VectorXd residualScale(const StepEvaluation& ev, double forceFloor, double reach, double couplingTol) const;
    /// The line search's merit ½‖F / residualScale‖² (∞ before the first Jacobian).
    static double coupledMerit(const Eigen::VectorXd& F, const Eigen::VectorXd& residualScale);
    /// −D (JsᵀJs + I)⁻¹ Jsᵀ Fs, residual in tolerance units, unknowns in clearances of film change.
    Eigen::VectorXd levenbergMarquardtStep(const Eigen::VectorXd& F, const Eigen::VectorXd& residualScale) const;
    /// The Jacobian at the context's step size from the last linearisation's parts.
    Eigen::MatrixXd coupledJacobian(const StepContext& ctx);

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
    std::unique_ptr<modal::HeldModalDynamics> pistonDynamics_, linerDynamics_;
    // coupling.method newton with flexible bodies (else null): the last linearisation
    std::unique_ptr<CoupledJacobianParts> newtonParts_;
    Eigen::MatrixXd newtonJacobian_; // the coupled Jacobian as formed (before Broyden updates)
    Eigen::MatrixXd newtonInverse_;  // inverse of the coupled Jacobian (Broyden-updated within a step)
    Eigen::VectorXd unknownScale_;   // m of film-thickness change per unit of each unknown
    // coupling.method partitioned with flexible bodies: units of (e, β, y) in clearances of film
    // change, for the quasi-Newton acceleration of the joint fixed-point map (docs/coupling.md §1)
    Eigen::VectorXd partitionedScale_;
    std::unique_ptr<CouplingAccelerator> accelerator_;  // coupling.acceleration, reset every step
    int foldedJacobians_ = 0;        // Jacobians of the current step with det(I − ∂H/∂y) < 0 (quasi-static, rigid rate)
    double newtonRate_ = -1.0;       // the a0/Δt it was formed for
    Eigen::Matrix2d jacobian_ = Eigen::Matrix2d::Zero();  // the motion's (partitioned, rigid)
};

}  // namespace flexehd::cosim
