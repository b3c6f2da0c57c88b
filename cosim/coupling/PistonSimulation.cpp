#include "cosim/coupling/PistonSimulation.hpp"

#include "cosim/coupling/MemoryBudget.hpp"
#include "cosim/coupling/RunProgress.hpp"

#include "cosim/coupling/CaseContacts.hpp"
#include "cosim/coupling/StepSizeControl.hpp"
#include "cosim/coupling/StepSolver.hpp"
#include "lube/FilmIntegrals.hpp"
#include "cosim/mapping/FlexibleBodyLoader.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <csignal>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "fem/Stopwatch.hpp"

namespace flexehd::cosim {

namespace {

// The smallest film thickness over the contacts' films (m; < 0: the surfaces overlap).
double minimumGap(const StepState& s) {
    double m = std::numeric_limits<double>::infinity();
    for (const ContactState& f : s.films) m = std::min(m, f.minGap);
    return m;
}

// The crank angle 0–720° (0 = gas-exchange TDC) written for a point of `cycle`: the continuous
// angle reduced by whole cycles. Cycle k spans time.start_deg + 720 (k − 1) … + 720, so the
// reduced angle runs from start_deg to 720 and on from 0 to start_deg; it is 720 (not 0) at the
// end of a cycle that starts at 0.
double cycleCrankDeg(double continuousDeg, int cycle) {
    const double a = continuousDeg - 720.0 * (cycle - 1);
    return a > 720.0 + 1e-9 ? a - 720.0 : a;
}

std::string gridKey(const EngineCase& c) { return c.path.empty() ? std::string("grid") : c.path + ": grid"; }

/// The case, once its film grid is known to fit into memory (before any of it is allocated).
const EngineCase& withinMemory(const EngineCase& c) {
    requireFilmMemory(gridKey(c), c.grid.axialNodes, c.grid.circumferentialNodes, 0);
    return c;
}
}  // namespace

PistonSimulation::PistonSimulation(const EngineCase& c)
    : case_(withinMemory(c)),
      kin_(c.engine.stroke, c.engine.rodLength, c.engine.pinOffset, c.engine.speedRpm),
      dyn_(c.piston, c.engine),
      pressure_(c.cylinderPressure) {
    const fem::Stopwatch t0;
    if (c.coupling.elasticSqueeze && c.coupling.method == CouplingMethod::Partitioned)
        throw std::invalid_argument(
            "coupling: the elastic deformation rate in the squeeze term needs coupling.method: newton; set "
            "coupling.elastic_squeeze: false for the partitioned iteration (docs/coupling.md section 3)");
    // The bodies, read once and shared by the contacts' surfaces; then the contacts.
    const CaseBodies bodies = loadCaseBodies(c);
    pistonBody_ = bodies.piston;
    linerBody_ = bodies.liner;
    mp_ = pistonBody_ ? pistonBody_->modes() : 0;
    ml_ = linerBody_ ? linerBody_->modes() : 0;
    if (mp_ + ml_ > 0) requireFilmMemory(gridKey(c), c.grid.axialNodes, c.grid.circumferentialNodes, mp_ + ml_);
    contacts_ = caseContacts(c, bodies, [this](double deg) { return linerOffset(deg); });
    for (const auto& contact : contacts_) columnCounts_.push_back(contact->columns().size());
    stepper_ = std::make_unique<StepSolver>(case_, kin_, dyn_, pressure_, contacts_, pistonBody_, linerBody_,
                                            [this](double deg) { return linerOffset(deg); }, work_);
    stats_.timings.setup = t0.seconds();
}

PistonSimulation::~PistonSimulation() = default;

void PistonSimulation::addContact(std::unique_ptr<FilmContact> contact) {
    columnCounts_.push_back(contact->columns().size());
    contacts_.push_back(std::move(contact));
    stepper_->contactsChanged();
}

double PistonSimulation::linerOffset(double crankDeg) const {
    return -case_.engine.pinTdcDepth - (kin_.tdcPosition() - kin_.at(crankDeg).position);
}

bool PistonSimulation::carriesOil() const {
    return std::any_of(contacts_.begin(), contacts_.end(), [](const auto& c) { return c->carriesOil(); });
}

std::vector<ContactColumn> PistonSimulation::contactColumns() const {
    std::vector<ContactColumn> all;
    for (const auto& contact : contacts_)
        for (ContactColumn& c : contact->columns()) all.push_back(std::move(c));
    return all;
}

void PistonSimulation::setUpLinerOil() {
    linerOil_.reset();
    covering_.clear();
    std::vector<LinerFootprint> footprints;
    for (std::size_t c = 0; c < contacts_.size(); ++c)
        if (std::optional<LinerFootprint> f = contacts_[c]->linerFootprint()) {
            footprints.push_back(std::move(*f));
            covering_.push_back(c);
        }
    if (footprints.empty()) return;
    // The replenishment's depth: the case's, or the lowest cover's lower edge at mid-stroke.
    const OilSupplySpec& sp = case_.lubricant.supply;
    double zReplenish = -std::numeric_limits<double>::infinity();
    if (sp.replenish && !std::isnan(sp.replenishBelowDepth)) {
        zReplenish = -sp.replenishBelowDepth;
    } else if (sp.replenish) {
        zReplenish = std::numeric_limits<double>::infinity();
        for (std::size_t c : covering_) zReplenish = std::min(zReplenish, contacts_[c]->linerCover(linerOffset(90.0)).low);
    }
    linerOil_ = std::make_unique<LinerOil>(sp, footprints, zReplenish);
}

LinerCovers PistonSimulation::coversAt(const StepState& s) const {
    std::vector<LinerCover> bands;
    for (std::size_t c : covering_) bands.push_back(contacts_[c]->linerCover(s.films[c].linerOffset));
    return LinerCovers(std::move(bands));
}

void PistonSimulation::advanceLinerOil(const StepState& s, const StepEvaluation& ev, StepState& n) const {
    if (!linerOil_) return;
    n.oil = linerOil_->advance(s.oil, coversAt(n), n.dt, [&](LinerOilExchange& ex) {
        for (std::size_t c : covering_) contacts_[c]->exchangeOil(s.films[c], n.films[c], ev.films[c], ex);
    });
}

void PistonSimulation::contactRecord(const StepEvaluation& ev, StepRecord& r) const {
    for (std::size_t c = 0; c < contacts_.size(); ++c) {
        const std::size_t before = r.contactValues.size();
        contacts_[c]->columnValues(ev.films[c], r.contactValues);
        if (r.contactValues.size() - before != columnCounts_[c])
            throw std::logic_error(fmt::format("film contact {} gave {} column values for its {} columns", c,
                                               r.contactValues.size() - before, columnCounts_[c]));
    }
}

StepRecord PistonSimulation::record(const StepState& s, const StepEvaluation& ev, int cycle, double stepDeg,
                                    int iterations) const {
    StepRecord r;
    const CrankState k = kin_.at(s.crankDeg);
    r.cylinderPressure = pressure_(crankAngle720(s.crankDeg));
    const double gas = dyn_.gasForce(r.cylinderPressure);
    r.cycle = cycle;
    r.crankDeg = cycleCrankDeg(s.crankDeg, cycle);
    r.time = s.time;
    r.lateral = s.x[0];
    r.tilt = s.x[1];
    r.lateralVelocity = s.v[0];
    r.tiltRate = s.v[1];
    r.sideForce = dyn_.sideForce(k, gas, ev.action, s.a[1]);
    // The film's figures: the first contact's that reports them (the skirt's).
    for (std::size_t c = 0; c < contacts_.size(); ++c)
        if (contacts_[c]->filmFigures(ev.films[c], r)) break;
    if (carriesOil()) oilRecord(s, ev, r);
    contactRecord(ev, r);
    r.couplingIterations = iterations;
    r.stepDeg = stepDeg;
    return r;
}

void PistonSimulation::oilRecord(const StepState& s, const StepEvaluation& ev, StepRecord& r) const {
    // The oil of the mass-conserving films, summed over the contacts, and of the liner's layer
    // (docs/coupling.md §6).
    double sideInflow = 0.0;
    for (const ContactIterate& c : ev.films) {  // a contact without oil adds nothing
        for (Eigen::Index j = 0; j < c.inflowLow.size(); ++j)
            for (double q : {c.inflowLow[j], c.inflowHigh[j]}) (q > 0.0 ? r.oilIn : r.oilOut) += std::abs(q);
        sideInflow += c.sideInflow;
        r.filmOil += c.oilVolume;
    }
    r.sideLeakage = -sideInflow;
    r.linerOil = LinerOil::volume(s.oil);
    r.replenishedOil = s.oil.replenished;
}

void PistonSimulation::afterAccepted(const StepState& s, const StepEvaluation& ev, int cycle, double stepDeg,
                                     double& worstDiff, double& largestForce) {
    if (mp_ > 0) checkLoadMapping(ev, worstDiff, largestForce);
    const AcceptedStep step{s, ev, cycle, stepDeg, stepDeg * kin_.secondsPerDegree()};
    for (RunObserver* o : observers_) o->stepAccepted(step);
}

void PistonSimulation::cyclePeriodicity(const std::vector<StepRecord>& cycle,
                                        const std::vector<double>& since, const std::vector<StepRecord>& previous,
                                        const std::vector<double>& previousSince) {
    const TimeSpec& T = case_.time;
    if (carriesOil()) cycleOil(cycle);
    if (previous.empty()) return;  // this cycle vs the previous one
    stats_.periodicityError =
        periodicityError(cycle, since, previous, previousSince, stats_.periodicityErrorBySector);
    stats_.periodic = stats_.periodicityError <= T.periodicityTolerance &&
                      (!stats_.oil || stats_.oilPeriodicityError <= T.oilPeriodicityTolerance);
}

void PistonSimulation::cycleOil(const std::vector<StepRecord>& cycle) {
    if (cycle.empty()) return;
    const StepRecord &a = cycle.front(), &b = cycle.back();
    stats_.oil = true;
    stats_.linerOil = b.linerOil;
    stats_.filmOil = b.filmOil;
    const double start = a.linerOil + a.filmOil, end = b.linerOil + b.filmOil;
    stats_.oilPeriodicityError = std::abs(end - start) / std::max(end, 1e-300);
    stats_.replenishedOil = b.replenishedOil - a.replenishedOil;
    stats_.leakedOil = 0.0;
    for (std::size_t i = 1; i < cycle.size(); ++i) stats_.leakedOil += (cycle[i].time - cycle[i - 1].time) * cycle[i].sideLeakage;
}

Snapshot PistonSimulation::snapshot(const StepState& s, const StepEvaluation& ev, int cycle) const {
    Snapshot sn;
    const CrankState k = kin_.at(s.crankDeg);
    sn.cycle = cycle;
    sn.crankDeg = cycleCrankDeg(s.crankDeg, cycle);
    sn.continuousDeg = s.crankDeg;
    sn.pinHeight = k.position;
    sn.linerOffset = linerOffset(s.crankDeg);
    sn.lateral = s.x[0];
    sn.tilt = s.x[1];
    for (std::size_t c = 0; c < contacts_.size(); ++c)
        if (contacts_[c]->filmFields(ev.films[c], k.velocity, sn)) break;  // the first that reports them
    if (s.oil.layer) {
        const LinerOilLayer& layer = *s.oil.layer;
        sn.linerOil = layer.meanThickness(s.oil.covers);
        for (int c = 0; c < layer.cells(); ++c) sn.linerOilZ.push_back(layer.zLow() + (c + 0.5) * layer.cellLength());
    }
    if (mp_ > 0) sn.pistonModal = s.y.head(mp_);
    if (ml_ > 0) sn.linerModal = s.y.tail(ml_);
    return sn;
}

StepState PistonSimulation::initialState(const SimulationCallbacks& cb) const {
    StepState s;
    s.crankDeg = case_.time.startDeg;
    const double offset = linerOffset(s.crankDeg);
    for (const auto& contact : contacts_) s.films.push_back(contact->initialState(offset));
    if (linerOil_) s.oil = linerOil_->initial(coversAt(s));
    if (cb.progress)
        for (const auto& contact : contacts_)
            for (const std::string& line : contact->startReport()) cb.progress(line);
    s.y = Eigen::VectorXd::Zero(mp_ + ml_);
    if (stepper_->dynamicResponse()) s.w = Eigen::VectorXd::Zero(mp_ + ml_);  // bodies at rest
    return s;
}

std::string PistonSimulation::stepSizeExhausted(const StepState& s, int cycle, bool converged, double ratio,
                                                const std::string& failure) const {
    // A folded quasi-static equilibrium is no matter of step size or iterations.
    const std::string advice =
        !converged && stepper_->foldedJacobians() > 0
            ? "The skirt's quasi-static equilibrium in the film is lost here: on some combination of "
              "its modes the film's stiffness (the wedge of the sliding liner) exceeds the "
              "structure's (det(I - dH/dy) < 0 in the step's Jacobian), and without the elastic "
              "deformation rate in the squeeze term nothing resists that deformation. Set "
              "coupling.elastic_squeeze: true (docs/coupling.md section 3)."
        : !converged && mp_ + ml_ > 0 && case_.coupling.method == CouplingMethod::Partitioned
            ? "With coupling.method: partitioned the squeeze term holds the rigid rate only; where "
              "the iteration fails at high speed (on the example engine from 4000 rpm on, early in "
              "the intake stroke) the skirt's quasi-static equilibrium in the film is lost, as with "
              "the rigid rate in coupling.method: newton (docs/coupling.md section 1). "
              "coupling.method: newton with coupling.elastic_squeeze: true (the defaults) runs the "
              "whole map."
        : converged
            ? fmt::format("Every iteration converged, but the local error stays above the step error tolerance "
                          "(time.lateral_tolerance {:g} m, time.tilt_tolerance_deg {:g}) at the smallest step: "
                          "loosen them, or let the step go smaller (time.min_step_deg)",
                          case_.time.lateralTolerance, case_.time.tiltTolerance * 180.0 / std::numbers::pi)
            : "Try a smaller time.max_step_deg, a finer film grid, more coupling.max_iterations, or "
              "check the loads and clearances of the case.";
    return fmt::format(
        "the time step fell below time.min_step_deg = {:g} deg at crank angle {:.4f} deg of cycle {}: {}. "
        "StepState: lateral shift {:.3f} um, tilt {:.4f} mrad, minimum film {:.3f} um. {}",
        case_.time.minStepDeg, crankAngle720(s.crankDeg), cycle,
        converged ? fmt::format("local error {:.3g} x the tolerance", ratio) : failure, s.x[0] * 1e6, s.x[1] * 1e3,
        minimumGap(s) * 1e6, advice);
}

void PistonSimulation::requireBoundedMotion(const StepState& n, int cycle) const {
    const double skirtLength = case_.piston.skirtTop - case_.piston.skirtBottom;
    if (!n.x.allFinite() || std::abs(n.x[0]) > 20.0 * case_.piston.clearance ||
        std::abs(n.x[1]) * skirtLength > 40.0 * case_.piston.clearance)
        throw std::runtime_error(fmt::format(
            "the secondary motion diverged at crank angle {:.3f} deg of cycle {}: lateral shift {:.3g} m, "
            "tilt {:.3g} rad (clearance {:.3g} m). {}",
            crankAngle720(n.crankDeg), cycle, n.x[0], n.x[1], case_.piston.clearance,
            case_.contact.compositeModulus > 0.0
                ? fmt::format("Asperity contact is on (contact.composite_modulus {:g} Pa) and did not hold the "
                              "piston: check the clearance, the masses and the cylinder pressure of the case, or "
                              "take a smaller time.max_step_deg",
                              case_.contact.compositeModulus)
                : std::string("Asperity contact is off (contact.composite_modulus 0): nothing stops the piston at "
                              "the liner; give contact.composite_modulus (docs/case-file.md, contact)")));
}

void PistonSimulation::checkLoadMapping(const StepEvaluation& ev, double& worstDiff, double& largestForce) {
    // The mapped resultant on the flexible piston against the film's normal force, per contact.
    for (std::size_t c = 0; c < contacts_.size(); ++c) contacts_[c]->checkLoadMapping(ev.films[c], worstDiff, largestForce);
    stats_.worstMappingError = worstDiff / std::max(largestForce, 1e-300);
}

void PistonSimulation::addWork(WorkTally& counted) {
    Timings& t = stats_.timings;
    t.film += work_.film - counted.film;
    t.mapping += work_.mapping - counted.mapping;
    t.modal += work_.modal - counted.modal;
    t.structure += (work_.mapping - counted.mapping) + (work_.modal - counted.modal);
    stats_.filmSolves += work_.filmSolves - counted.filmSolves;
    stats_.fallbackSolves += work_.fallbackSolves - counted.fallbackSolves;
    stats_.jacobians += work_.jacobians - counted.jacobians;
    stats_.resolvedSteps += work_.resolvedSteps - counted.resolvedSteps;
    counted = work_;
}

double PistonSimulation::periodicityError(const std::vector<StepRecord>& cycle, const std::vector<double>& since,
                                          const std::vector<StepRecord>& previous,
                                          const std::vector<double>& previousSince,
                                          std::vector<double>& bySector) const {
    // Eccentricities at the skirt ends, this cycle vs the previous one, interpolated to the same
    // degrees since the cycle's start (docs/coupling.md §1); per sector of the crank angle too.
    const double reach = std::max(case_.piston.skirtTop, -case_.piston.skirtBottom);
    const double sector = RunStatistics::kPeriodicitySectorDeg;
    bySector.assign(static_cast<std::size_t>(std::lround(720.0 / sector)), 0.0);
    double err = 0.0;
    std::size_t j = 0;
    for (std::size_t i = 0; i < cycle.size(); ++i) {
        const StepRecord& r = cycle[i];
        const double at = since[i];
        while (j + 1 < previous.size() && previousSince[j + 1] < at) ++j;
        const std::size_t j1 = std::min(j + 1, previous.size() - 1);
        const StepRecord& a = previous[j];
        const StepRecord& b = previous[j1];
        const double sa = previousSince[j], sb = previousSince[j1];
        const double w = sb > sa ? std::clamp((at - sa) / (sb - sa), 0.0, 1.0) : 0.0;
        const double e0 = a.lateral + w * (b.lateral - a.lateral);
        const double t0 = a.tilt + w * (b.tilt - a.tilt);
        const double here = std::abs(r.lateral - e0) + std::abs(r.tilt - t0) * reach;
        err = std::max(err, here);
        const double crank = std::fmod(case_.time.startDeg + at, 720.0);
        const auto k = std::min(bySector.size() - 1, static_cast<std::size_t>(std::max(0.0, crank) / sector));
        bySector[k] = std::max(bySector[k], here);
    }
    return err;
}

// The cycle loop's state over a run: the accepted states, the current cycle's span and records
// against the previous cycle's, the step control and the counters of the run's statistics.
struct PistonSimulation::RunLoop {
    RunLoop(const SimulationCallbacks& callbacks, double span, const TimeSpec& T, double every, double secondsPerDegree)
        : cb(callbacks), spanDeg(span), control(T, every, secondsPerDegree), progress(T.maxCycles, T.periodicityTolerance) {}

    const fem::Stopwatch clock;  // since the run started
    const SimulationCallbacks& cb;
    const double spanDeg;
    StepSizeControl control;
    RunProgress progress;
    StepState s, prev;
    StepEvaluation ev, lastEv;
    bool haveLast = false;
    // The cycle: its number, crank-angle span, snapshots taken and the next progress line's angle.
    int cycle = 0;
    double cycleStart = 0.0, cycleEnd = 0.0, nextProgress = 0.0;
    int snapshots = 0;
    std::vector<StepRecord> records, previous;
    // Degrees since the start of the cycle of each record (monotonic, unlike the written crank
    // angle when time.start_deg > 0): the abscissa of the periodicity comparison.
    std::vector<double> since, previousSince;
    double worstMappingDiff = 0.0, largestFilmForce = 0.0;
    WorkTally counted;  // the work already in stats_
    double filmT0 = 0.0, structT0 = 0.0;
};

namespace {

// The callbacks of a run as its last observer.
class CallbackObserver final : public RunObserver {
public:
    explicit CallbackObserver(const SimulationCallbacks& cb) : cb_(cb) {}
    void recorded(const StepRecord& row) override {
        if (cb_.onStep) cb_.onStep(row);
    }
    void snapshotTaken(const Snapshot& s) override {
        if (cb_.onSnapshot) cb_.onSnapshot(s);
    }
    void cycleEnded(const CycleEnd& e) override {
        if (cb_.onCycleEnd) cb_.onCycleEnd(e.cycle, e.snapshots, e.last);
    }

private:
    const SimulationCallbacks& cb_;
};

// Keeps an observer in a list while it lives.
class ObserverDuringRun {
public:
    ObserverDuringRun(std::vector<RunObserver*>& list, RunObserver& o) : list_(list) { list_.push_back(&o); }
    ~ObserverDuringRun() { list_.pop_back(); }
    ObserverDuringRun(const ObserverDuringRun&) = delete;
    ObserverDuringRun& operator=(const ObserverDuringRun&) = delete;

private:
    std::vector<RunObserver*>& list_;
};

}  // namespace

RunInterrupted::RunInterrupted(int signal, int cycle, double crankDeg)
    : std::runtime_error(fmt::format("interrupted by signal {} ({}) in cycle {} at {:.1f} deg", signal,
                                     signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal", cycle,
                                     std::fmod(crankDeg, 720.0))),
      signal_(signal) {}

std::vector<StepRecord> PistonSimulation::run(const SimulationCallbacks& cb, double spanDeg) {
    CallbackObserver callbacks(cb);
    const ObserverDuringRun during(observers_, callbacks);
    RunLoop loop(cb, spanDeg, case_.time, case_.output.vtkEveryDeg, kin_.secondsPerDegree());
    startRun(loop);
    for (loop.cycle = 1; loop.cycle <= case_.time.maxCycles; ++loop.cycle) {
        openCycle(loop);
        while (loop.s.crankDeg < loop.cycleEnd - 1e-9) {
            if (const int signal = cb.stopRequested ? cb.stopRequested() : 0) {
                addWork(loop.counted);
                throw RunInterrupted(signal, loop.cycle, loop.s.crankDeg);
            }
            tryStep(loop);
        }
        if (closeCycle(loop)) break;
    }
    addWork(loop.counted);
    stats_.timings.dynamics =
        loop.clock.seconds() - (stats_.timings.film - loop.filmT0) - (stats_.timings.structure - loop.structT0);
    return loop.records;
}

void PistonSimulation::startRun(RunLoop& loop) {
    setUpLinerOil();
    loop.s = initialState(loop.cb);
    loop.prev = loop.s;
    stats_ = RunStatistics{.timings = stats_.timings};
    stats_.minStepDeg = case_.time.maxStepDeg;
    loop.filmT0 = stats_.timings.film;
    loop.structT0 = stats_.timings.structure;
    loop.counted = work_;
}

void PistonSimulation::takeSnapshot(RunLoop& loop, const StepEvaluation& ev) {
    ++loop.snapshots;
    const Snapshot taken = snapshot(loop.s, ev, loop.cycle);
    for (RunObserver* o : observers_) o->snapshotTaken(taken);
}

void PistonSimulation::openCycle(RunLoop& loop) {
    const TimeSpec& T = case_.time;
    loop.cycleStart = T.startDeg + 720.0 * (loop.cycle - 1);
    loop.cycleEnd = loop.spanDeg > 0.0 ? std::min(loop.cycleStart + 720.0, T.startDeg + loop.spanDeg)
                                       : loop.cycleStart + 720.0;
    loop.records.clear();
    loop.since.clear();
    loop.progress.startCycle(loop.cycle, loop.clock.seconds());
    loop.snapshots = 0;
    if (loop.haveLast) {
        // The boundary point opens the new cycle's records too (its metrics and its 0° snapshot);
        // it is the last cycle's final step, written to the history once, there.
        loop.records.push_back(record(loop.s, loop.lastEv, loop.cycle, 0.0, 0));
        loop.since.push_back(loop.s.crankDeg - loop.cycleStart);
        if (case_.output.vtkEveryDeg > 0.0) takeSnapshot(loop, loop.lastEv);
    }
    loop.nextProgress = loop.cycleStart;
}

void PistonSimulation::tryStep(RunLoop& loop) {
    bool atSnapshot = false;
    const double step = loop.control.planned(loop.s.crankDeg, loop.cycleStart, loop.cycleEnd, atSnapshot);
    StepState n;
    int iterations = 0;
    std::string failure;
    const bool ok = stepper_->advance(loop.s, loop.prev, step, n, loop.ev, iterations, failure);
    const double ratio = ok ? loop.control.errorRatio(loop.s, n, step) : 0.0;
    if (!ok || ratio > 1.0) {
        ++stats_.rejectedSteps;
        if (!loop.control.rejected(step, ok, ratio)) {
            addWork(loop.counted);
            throw std::runtime_error(stepSizeExhausted(loop.s, loop.cycle, ok, ratio, failure));
        }
        return;
    }
    acceptStep(loop, std::move(n), step, iterations, atSnapshot);
    loop.control.accepted(step, ratio);
    progressLine(loop, iterations, step);
}

void PistonSimulation::acceptStep(RunLoop& loop, StepState n, double step, int iterations, bool atSnapshot) {
    addWork(loop.counted);
    requireBoundedMotion(n, loop.cycle);
    advanceLinerOil(loop.s, loop.ev, n);
    ++stats_.steps;
    stepper_->stepAccepted();
    stats_.maxIterations = std::max(stats_.maxIterations, iterations);
    stats_.minStepDeg = std::min(stats_.minStepDeg, step);
    loop.prev = std::move(loop.s);
    loop.s = std::move(n);
    afterAccepted(loop.s, loop.ev, loop.cycle, step, loop.worstMappingDiff, loop.largestFilmForce);
    loop.lastEv = loop.ev;
    loop.haveLast = true;
    StepRecord rec = record(loop.s, loop.ev, loop.cycle, step, iterations);
    loop.records.push_back(rec);
    loop.since.push_back(loop.s.crankDeg - loop.cycleStart);
    for (RunObserver* o : observers_) o->recorded(rec);
    if (atSnapshot) takeSnapshot(loop, loop.ev);
}

void PistonSimulation::progressLine(RunLoop& loop, int iterations, double step) const {
    const StepState& s = loop.s;
    if (!loop.cb.progress || s.crankDeg < loop.nextProgress) return;
    loop.nextProgress += 30.0;
    loop.cb.progress(loop.progress.stepLine(cycleCrankDeg(s.crankDeg, loop.cycle),
                                            (s.crankDeg - loop.cycleStart) / (loop.cycleEnd - loop.cycleStart),
                                            loop.clock.seconds(), s.x[0], s.x[1], iterations, step));
}

bool PistonSimulation::closeCycle(RunLoop& loop) {
    const TimeSpec& T = case_.time;
    stats_.cycles = loop.cycle;
    cyclePeriodicity(loop.records, loop.since, loop.previous, loop.previousSince);
    if (loop.cb.progress)
        loop.cb.progress(loop.progress.cycleDoneLine(
            loop.clock.seconds(), loop.previous.empty() ? std::nullopt : std::optional(stats_.periodicityError)));
    const bool last = stats_.periodic || loop.cycle == T.maxCycles ||
                      (loop.spanDeg > 0.0 && loop.cycleEnd >= T.startDeg + loop.spanDeg - 1e-9);
    for (RunObserver* o : observers_) o->cycleEnded({loop.cycle, loop.snapshots, last, &loop.records});
    if (!last) {
        loop.previous = loop.records;
        loop.previousSince = loop.since;
    }
    return last;
}

}  // namespace flexehd::cosim
