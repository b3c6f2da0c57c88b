#pragma once
// PistonSimulation: the co-simulation master (docs/coupling.md, docs/dynamics.md). Each time
// step solves, at the new crank angle, the piston's secondary motion (PistonDynamics, BDF2 in
// time) together with the films of its contacts (FilmContact: the skirt's, SkirtContact, and any
// added) and the elastic response of the flexible bodies (FlexibleBody) to their summed load, until
//   * the Newton update of (e, β) is below 1e-5 of the clearance (the tilt times the skirt's
//     reach from the pin), and the residual of each equation of motion below 1e-4 of the sum
//     of its terms' magnitudes plus the reciprocating inertia force m r ω² (times the reach
//     for the moment), and
//   * the coupling residual, the film-thickness change max|Δh(H(y)) − Δh(y)| of the modal
//     coordinates y, is below coupling.tolerance × clearance,
// with one film solve per iteration: Newton (finite-difference Jacobian, Broyden updates) on the
// motion and IQN-ILS or Aitken on y in the same loop. The bodies answer the film load
// quasi-statically, or (bodies.response: dynamic) with their modal inertia and damping,
// integrated by the same BDF2 as the motion (modal::HeldModalDynamics). The step size is controlled by the local
// error estimate of the predictor–corrector pair; cycles repeat until periodic.

#include "cosim/case/EngineCase.hpp"
#include "cosim/contact/FilmContact.hpp"
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/coupling/CouplingAccelerator.hpp"
#include "cosim/coupling/StepRecord.hpp"
#include "cosim/engine/CrankKinematics.hpp"
#include "cosim/engine/CylinderPressure.hpp"
#include "cosim/engine/PistonDynamics.hpp"
#include "cosim/mapping/FlexibleBody.hpp"
#include "modal/HeldModalDynamics.hpp"

#include <Eigen/Core>
#include <Eigen/LU>

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace flexehd::cosim {

/// Film and body state at one written crank angle (the VTK snapshots).
struct Snapshot {
    int cycle = 0;
    double crankDeg = 0.0;       ///< °, the crank angle 0–720 (0 = gas-exchange TDC), as in StepRecord
    double continuousDeg = 0.0;  ///< °, the continuous crank angle: time.start_deg + degrees turned
    double pinHeight = 0.0;      ///< m, cylinder-frame z of the pin axis (crank axis at 0)
    double linerOffset = 0.0;    ///< m, liner-frame z of the piston frame's origin
    double lateral = 0.0, tilt = 0.0;
    Eigen::VectorXd pressure, filmThickness, contactPressure, shearStress, cavitation;
    Eigen::VectorXd pistonModal, linerModal;  ///< modal coordinates (empty for rigid bodies)
};

struct Timings {
    double setup = 0.0;      ///< s: bodies, mappings, compliance
    double film = 0.0;       ///< s: Reynolds solves, contact, film integrals
    double structure = 0.0;  ///< s: modal response and deformation mapping (mapping + modal)
    double mapping = 0.0;    ///< s, of structure: load and deformation mapping products (Φᵀ A p, D Φ y)
    double modal = 0.0;      ///< s, of structure: quasi-static response C f and the coupling accelerator
    double dynamics = 0.0;   ///< s: everything else in the step loop
};

struct RunStatistics {
    int cycles = 0;
    bool periodic = false;
    double periodicityError = 0.0;  ///< m, last cycle vs the one before (see docs/coupling.md)
    long steps = 0, rejectedSteps = 0, filmSolves = 0, jacobians = 0;
    long fallbackSolves = 0;        ///< film solves redone by the active-set solver (multigrid failed)
    long resolvedSteps = 0;         ///< steps ended by the resolution test of the coupled Newton (docs/coupling.md §1)
    int maxIterations = 0;          ///< most film solves in one accepted step
    /// max over the steps of |mapped resultant − film normal force| on the flexible piston,
    /// relative to the largest film normal force of the run
    double worstMappingError = 0.0;
    double minStepDeg = 0.0;        ///< smallest accepted step
    Timings timings;
};

struct SimulationCallbacks {
    std::function<void(const StepRecord&)> onStep;      ///< every accepted step
    /// every output.vtkEveryDeg of every cycle, as it is taken (nothing is held back)
    std::function<void(const Snapshot&)> onSnapshot;
    /// after each cycle: its number, the snapshots it took, and whether it is the run's last
    std::function<void(int cycle, int snapshots, bool last)> onCycleEnd;
    std::function<void(const std::string&)> progress;   ///< human-readable progress lines
};

class PistonSimulation {
public:
    /// Builds the grid, solver and the flexible bodies named by the case (reads their files).
    explicit PistonSimulation(const EngineCase& c);
    ~PistonSimulation();

    /// A further film contact of the piston, beside the skirt's (before run). Its modal loads and
    /// film changes use the same coordinates as the skirt's: the piston's, then the liner's.
    void addContact(std::unique_ptr<FilmContact> contact);

    /// Runs the cycles; records of the final cycle are returned. Throws std::runtime_error with a
    /// diagnosis when the step size falls below time.min_step_deg.
    /// spanDeg > 0 stops after that many crank degrees (tests, studies of one event).
    std::vector<StepRecord> run(const SimulationCallbacks& callbacks = {}, double spanDeg = 0.0);

    const RunStatistics& statistics() const { return stats_; }
    const SkirtFilm& film() const { return skirt_->film(); }
    const CrankKinematics& kinematics() const { return kin_; }
    const PistonDynamics& dynamics() const { return dyn_; }
    /// The flexible bodies seen from the skirt's grid (null when rigid).
    const FlexibleSurface* piston() const { return skirt_->piston(); }
    const FlexibleSurface* liner() const { return skirt_->liner(); }
    /// Bore distortion and thermal terms of the film thickness (null when the case has none).
    const ClearanceTerms* clearance() const { return skirt_->clearance(); }
    /// Liner-frame z of the piston frame's origin at the crank angle.
    double linerOffset(double crankDeg) const;
    /// The centred, undeformed film thickness at the crank angle's piston position (see
    /// ClearanceRange; the liner terms depend on where the piston is in the bore).
    ClearanceRange centredClearance(double crankDeg) const;

private:
    struct State;
    struct Context;
    struct Evaluation;
    /// One iterate (e, β, y) of the step: every contact's film and action, the motion's residual
    /// and (structure) the bodies' response H(y) to the contacts' modal loads.
    Evaluation evaluate(const Context& ctx, const Eigen::Vector2d& x, const Eigen::VectorXd& y, bool structure);
    // The stages of evaluate.
    void motionResidual(const Context& ctx, const Eigen::Vector2d& x, Evaluation& ev) const;
    void structureResponse(const Context& ctx, Evaluation& ev);
    bool advance(State& s, State& prev, double dtDeg, State& out, Evaluation& ev, int& iterations,
                 std::string& failure);
    // The stages of advance (StepIteration.cpp).
    struct StepTolerances;
    struct NewtonIterate;
    enum class PassOutcome { Retry, Failed, Update };
    Context stepContext(const State& s, const State& prev, double dtDeg);
    StepTolerances stepTolerances() const;
    /// max |Δh(H(y)) − Δh(y)| over the grid (m).
    double couplingResidual(const Context& ctx, const Evaluation& ev, const Eigen::VectorXd& y);
    /// coupling.method newton: the line search, the Jacobian kept, re-formed or Broyden-updated,
    /// and the damped update dz of (e, β, y); Retry: x, y were moved back (evaluate again).
    PassOutcome coupledNewtonPass(const Context& ctx, const StepTolerances& tol, const Evaluation& ev,
                                  double couplingRes, NewtonIterate& it, Eigen::Vector2d& x, Eigen::VectorXd& y,
                                  int& iterations, Eigen::VectorXd& dz, bool& resolved, std::string& why);
    /// The coupled Newton iteration has converged to the resolution of its unknowns.
    bool resolvedToTheUnknownsResolution(const StepTolerances& tol, const Evaluation& ev, double couplingRes,
                                         const Eigen::VectorXd& dz) const;
    /// The finite-difference Jacobian of the motion residual (modal coordinates frozen).
    bool motionJacobian(const Context& ctx, const StepTolerances& tol, const Eigen::Vector2d& x,
                        const Eigen::VectorXd& y, const Evaluation& ev, int& iterations);
    /// coupling.method partitioned: the accelerated fixed-point map of (e, β, y).
    void partitionedUpdate(const Evaluation& ev, const Eigen::Vector2d& dx, CouplingAccelerator& acc,
                           Eigen::Vector2d& x, Eigen::VectorXd& y);
    void acceptStep(const Context& ctx, const State& s, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                    const Evaluation& ev, State& out) const;
    struct CoupledJacobianParts;
    /// coupling.method newton: linearises (motion residual, y − H(y)) in (e, β, y) at the
    /// evaluation into the parts of CoupledJacobianParts (CoupledNewton.cpp, docs/coupling.md §1, §3)
    void linearizeCoupled(const Context& ctx, const Eigen::Vector2d& x, const Evaluation& ev);
    /// ∂(equations of motion's right-hand side)/∂(F_x, ·, F_z, ·, M_y, ·): 2 × 6, from the dynamics.
    Eigen::Matrix<double, 2, 6> actionGradient(const Context& ctx) const;
    void broydenUpdate(const Eigen::VectorXd& s, const Eigen::VectorXd& dF);
    /// Forms the coupled Jacobian at the context's step size (its (e, β) columns by differences of
    /// two full evaluations, counted in filmSolves) and its inverse; false if a film solve failed.
    bool formCoupledJacobian(const Context& ctx, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                             const Evaluation& ev, const Eigen::Vector2d& tol, int& filmSolves);
    /// The tolerance of each residual row: motion rows 1e-4 (scale + force floor), modal rows the
    /// coupling tolerance over the largest film change of a unit of the mode.
    Eigen::VectorXd residualScale(const Evaluation& ev, double forceFloor, double reach, double couplingTol) const;
    /// The line search's merit ½‖F / residualScale‖² (∞ before the first Jacobian).
    static double coupledMerit(const Eigen::VectorXd& F, const Eigen::VectorXd& residualScale);
    /// −D (JsᵀJs + I)⁻¹ Jsᵀ Fs, residual in tolerance units, unknowns in clearances of film change.
    Eigen::VectorXd levenbergMarquardtStep(const Eigen::VectorXd& F, const Eigen::VectorXd& residualScale) const;
    /// The Jacobian at the context's step size from the last linearisation's parts.
    Eigen::MatrixXd coupledJacobian(const Context& ctx);
    StepRecord record(const State& s, const Evaluation& ev, int cycle, double stepDeg, int iterations) const;
    // The stages of run (PistonSimulation.cpp).
    State initialState(const SimulationCallbacks& cb) const;
    /// The next step: dtDeg, shortened to land on the next snapshot angle or the cycle's end.
    double plannedStep(double crankDeg, double dtDeg, double cycleStart, double cycleEnd, bool& atSnapshot) const;
    /// The local error estimate of the step s → n in units of its tolerance.
    double localErrorRatio(const State& s, const State& n, double stepDeg) const;
    /// The diagnosis when the step size falls below time.min_step_deg.
    std::string stepSizeExhausted(const State& s, int cycle, bool converged, double ratio,
                                  const std::string& failure) const;
    /// Throws when the motion left the clearance by far (diverged).
    void requireBoundedMotion(const State& n, int cycle) const;
    /// Updates RunStatistics::worstMappingError with the step's mapped resultant on the piston.
    void checkLoadMapping(const Evaluation& ev, double& worstDiff, double& largestForce);
    /// coupling.method partitioned: the units of (e, β, y) in clearances of film change.
    void setPartitionedScale();
    /// Adds the contacts' and the response's work since `counted` into the run's statistics.
    void addWork(WorkTally& counted);
    double periodicityError(const std::vector<StepRecord>& cycle, const std::vector<double>& since,
                            const std::vector<StepRecord>& previous, const std::vector<double>& previousSince) const;
    Snapshot snapshot(const State& s, const Evaluation& ev, int cycle) const;

    EngineCase case_;
    CrankKinematics kin_;
    PistonDynamics dyn_;
    CylinderPressure pressure_;
    // The film contacts the step iterates over; the skirt's is the first (history.csv's and the
    // snapshots' film columns are its).
    std::vector<std::unique_ptr<FilmContact>> contacts_;
    SkirtContact* skirt_ = nullptr;
    // The flexible bodies (null: rigid), shared with the contacts' surfaces; bodies.response:
    // dynamic — BDF2 modal dynamics per flexible body (null: quasi-static)
    std::shared_ptr<const FlexibleBody> pistonBody_, linerBody_;
    std::unique_ptr<modal::HeldModalDynamics> pistonDynamics_, linerDynamics_;
    int mp_ = 0, ml_ = 0;  // modal coordinates of piston and liner
    WorkTally work_;       // the contacts' and the response's work, since construction
    // coupling.method newton with flexible bodies (else null): the last linearisation
    std::unique_ptr<CoupledJacobianParts> newtonParts_;
    Eigen::MatrixXd newtonJacobian_; // the coupled Jacobian as formed (before Broyden updates)
    Eigen::MatrixXd newtonInverse_;  // inverse of the coupled Jacobian (Broyden-updated within a step)
    Eigen::VectorXd unknownScale_;   // m of film-thickness change per unit of each unknown
    // coupling.method partitioned with flexible bodies: units of (e, β, y) in clearances of film
    // change, for the quasi-Newton acceleration of the joint fixed-point map (docs/coupling.md §1)
    Eigen::VectorXd partitionedScale_;
    int foldedJacobians_ = 0;        // Jacobians of the current step with det(I − ∂H/∂y) < 0 (quasi-static, rigid rate)
    double newtonRate_ = -1.0;       // the a0/Δt it was formed for
    Eigen::Matrix2d jacobian_;
    bool haveJacobian_ = false;
    RunStatistics stats_;
};

}  // namespace flexehd::cosim
