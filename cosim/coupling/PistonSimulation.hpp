#pragma once
// PistonSimulation: the co-simulation master (docs/coupling.md, docs/dynamics.md). Each time
// step solves, at the new crank angle, the piston's secondary motion (PistonDynamics, BDF2 in
// time) together with the films of its contacts (FilmContact: the case's, coupling/CaseContacts,
// and any added) and the elastic response of the flexible bodies (FlexibleBody) to their summed load, until
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
#include "cosim/coupling/RunObserver.hpp"
#include "cosim/coupling/Snapshot.hpp"
#include "cosim/coupling/StepRecord.hpp"
#include "cosim/engine/CrankKinematics.hpp"
#include "cosim/engine/CylinderPressure.hpp"
#include "cosim/engine/PistonDynamics.hpp"
#include "cosim/mapping/FlexibleBody.hpp"
#include "cosim/oil/LinerOil.hpp"

#include <Eigen/Core>

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace flexehd::cosim {

class StepSolver;
struct StepState;
struct StepEvaluation;

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
    /// m, periodicityError over each kPeriodicitySectorDeg of crank angle (from 0°; empty until
    /// two cycles are done): where in the cycle its cycles differ
    std::vector<double> periodicityErrorBySector;
    static constexpr double kPeriodicitySectorDeg = 60.0;
    /// Mass-conserving film, the last cycle (docs/coupling.md §6): oil on the liner and in the film
    /// at its end (m³), the relative change of their sum over it, what the replenishment added
    /// and the sides leaked over it (m³); `oil` false with the Reynolds condition.
    bool oil = false;
    double linerOil = 0.0, filmOil = 0.0, oilPeriodicityError = 0.0, replenishedOil = 0.0, leakedOil = 0.0;
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
    /// asked before each step: a signal number (SIGINT, SIGTERM) stops the run there with
    /// RunInterrupted; 0 goes on (null: never stops)
    std::function<int()> stopRequested;
};

/// The run was stopped between two steps because the caller asked (a signal): what it was and
/// the cycle it stopped in.
class RunInterrupted : public std::runtime_error {
public:
    RunInterrupted(int signal, int cycle, double crankDeg);
    RunInterrupted(int signal, const std::string& message) : std::runtime_error(message), signal_(signal) {}
    int signal() const { return signal_; }

private:
    int signal_;
};

class PistonSimulation {
public:
    /// Reads the flexible bodies the case names and builds its film contacts (caseContacts: the
    /// skirt's first).
    explicit PistonSimulation(const EngineCase& c);
    ~PistonSimulation();

    /// A further film contact of the piston, after the case's (before run). Its modal loads and
    /// film changes use the same coordinates as theirs: the piston's, then the liner's.
    void addContact(std::unique_ptr<FilmContact> contact);
    /// An observer of the run's accepted steps, history rows, snapshots and cycle ends (before run;
    /// not owned, it must outlive the run). The callbacks given to run are its last observer.
    void addObserver(RunObserver& observer) { observers_.push_back(&observer); }

    /// Runs the cycles; records of the final cycle are returned. Throws std::runtime_error with a
    /// diagnosis when the step size falls below time.min_step_deg.
    /// spanDeg > 0 stops after that many crank degrees (tests, studies of one event).
    std::vector<StepRecord> run(const SimulationCallbacks& callbacks = {}, double spanDeg = 0.0);

    const RunStatistics& statistics() const { return stats_; }
    const CrankKinematics& kinematics() const { return kin_; }
    const PistonDynamics& dynamics() const { return dyn_; }
    /// The flexible bodies (null when rigid), shared by the contacts' surfaces.
    const std::shared_ptr<const FlexibleBody>& pistonBody() const { return pistonBody_; }
    const std::shared_ptr<const FlexibleBody>& linerBody() const { return linerBody_; }
    /// The film contacts, in the order the step iterates over them (the case's, then the added).
    const std::vector<std::unique_ptr<FilmContact>>& contacts() const { return contacts_; }
    /// The first contact of the type C, e.g. contact<SkirtContact>(); throws std::logic_error when
    /// the run has none.
    template <class C>
    const C& contact() const {
        for (const auto& c : contacts_)
            if (const auto* found = dynamic_cast<const C*>(c.get())) return *found;
        throw std::logic_error("the run has no film contact of the kind asked for");
    }
    /// A contact's film conserves oil: the records carry the oil columns and the cycle's oil
    /// balance (docs/coupling.md §6).
    bool carriesOil() const;
    /// The contacts' own history.csv columns and their summary figures, in contact order
    /// (StepRecord::contactValues holds their values).
    std::vector<ContactColumn> contactColumns() const;
    /// Liner-frame z of the piston frame's origin at the crank angle.
    double linerOffset(double crankDeg) const;

private:
    struct RunLoop;
    // The stages of run: the start, a cycle's opening, one step's attempt and its acceptance, the
    // progress line, the cycle's close (true: the run's last).
    void startRun(RunLoop& loop);
    void openCycle(RunLoop& loop);
    void tryStep(RunLoop& loop);
    void acceptStep(RunLoop& loop, StepState n, double step, int iterations, bool atSnapshot);
    void takeSnapshot(RunLoop& loop, const StepEvaluation& ev);
    void progressLine(RunLoop& loop, int iterations, double step) const;
    bool closeCycle(RunLoop& loop);
    StepRecord record(const StepState& s, const StepEvaluation& ev, int cycle, double stepDeg, int iterations) const;
    StepState initialState(const SimulationCallbacks& cb) const;
    /// After an accepted step: the load-mapping check and the observers.
    void afterAccepted(const StepState& s, const StepEvaluation& ev, int cycle, double stepDeg, double& worstDiff,
                       double& largestForce);
    /// The cycle's periodicity against the previous one (motion, and the oil of a mass-conserving
    /// film) into stats_.
    void cyclePeriodicity(const std::vector<StepRecord>& cycle, const std::vector<double>& since,
                          const std::vector<StepRecord>& previous, const std::vector<double>& previousSince);
    /// The last cycle's oil figures into stats_ (mass-conserving film).
    void cycleOil(const std::vector<StepRecord>& cycle);
    /// The oil columns of a record: the mass-conserving films' (summed over the contacts), the
    /// skirt's wetted share, the liner's layer.
    void oilRecord(const StepState& s, const StepEvaluation& ev, StepRecord& r) const;
    /// The master's liner oil layer over the contacts that run on one (none: no layer).
    void setUpLinerOil();
    /// Every covering contact's band on the liner at the state.
    LinerCovers coversAt(const StepState& s) const;
    /// The liner's oil after the accepted step s → n (the contacts' trade, the replenishment).
    void advanceLinerOil(const StepState& s, const StepEvaluation& ev, StepState& n) const;
    /// The contacts' own column values of a record.
    void contactRecord(const StepEvaluation& ev, StepRecord& r) const;
    /// The diagnosis when the step size falls below time.min_step_deg.
    std::string stepSizeExhausted(const StepState& s, int cycle, bool converged, double ratio,
                                  const std::string& failure) const;
    /// Throws when the motion left the clearance by far (diverged).
    void requireBoundedMotion(const StepState& n, int cycle) const;
    /// Updates RunStatistics::worstMappingError with the step's mapped resultant on the piston.
    void checkLoadMapping(const StepEvaluation& ev, double& worstDiff, double& largestForce);
    /// Adds the contacts' and the response's work since `counted` into the run's statistics.
    void addWork(WorkTally& counted);
    /// The largest |Δe| + |Δβ| reach of `cycle` against `previous`, and per sector of crank angle.
    double periodicityError(const std::vector<StepRecord>& cycle, const std::vector<double>& since,
                            const std::vector<StepRecord>& previous, const std::vector<double>& previousSince,
                            std::vector<double>& bySector) const;
    Snapshot snapshot(const StepState& s, const StepEvaluation& ev, int cycle) const;

    EngineCase case_;
    CrankKinematics kin_;
    PistonDynamics dyn_;
    CylinderPressure pressure_;
    // The film contacts the step iterates over: the case's (caseContacts), then the added.
    std::vector<std::unique_ptr<FilmContact>> contacts_;
    std::vector<std::size_t> columnCounts_;  // of each contact's own columns
    // The liner's oil layer (null: no contact runs on one) and the contacts that cover it.
    std::unique_ptr<LinerOil> linerOil_;
    std::vector<std::size_t> covering_;
    // The flexible bodies (null: rigid), shared with the contacts' surfaces.
    std::shared_ptr<const FlexibleBody> pistonBody_, linerBody_;
    int mp_ = 0, ml_ = 0;  // modal coordinates of piston and liner
    WorkTally work_;       // the contacts' and the step's work, since construction
    std::unique_ptr<StepSolver> stepper_;
    std::vector<RunObserver*> observers_;
    RunStatistics stats_;
};

}  // namespace flexehd::cosim
