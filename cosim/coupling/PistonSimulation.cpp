#include "cosim/coupling/PistonSimulation.hpp"

#include "cosim/case/MemoryBudget.hpp"
#include "cosim/coupling/RunProgress.hpp"

#include "cosim/clearance/ClearanceTerms.hpp"
#include "cosim/coupling/PistonSimulationState.hpp"
#include "lube/FilmIntegrals.hpp"
#include "cosim/mapping/FlexibleBodyLoader.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <optional>
#include <stdexcept>

#include "fem/Stopwatch.hpp"

namespace flexehd::cosim {

namespace {

lube::Lubricant makeLubricant(const LubricantSpec& l) {
    lube::Lubricant lub(l.viscosity, l.density);
    if (l.barusAlpha > 0.0) lub.withBarus(l.barusAlpha);
    return lub;
}

// Multigrid, redone by the active-set method where it stalls (ReynoldsOptions::fallback).
lube::ReynoldsOptions filmSolverOptions(const LubricantSpec& l) {
    lube::ReynoldsOptions o;
    o.cavitation = lube::Cavitation::Reynolds;
    o.solver = lube::SolverKind::Multigrid;
    o.fallback = lube::SolverKind::ActiveSet;
    o.cavitationPressure = l.cavitationPressure;
    o.control.tolerance = 1e-8;
    return o;
}

// The smallest film thickness over the nodes that carry film (m; < 0: the surfaces overlap).
double minimumGap(const lube::FilmGrid& g, const Eigen::VectorXd& h) {
    double m = std::numeric_limits<double>::infinity();
    for (int k = 0; k < g.size(); ++k)
        if (g.kind(k) != lube::NodeKind::Void) m = std::min(m, h[k]);
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
      pressure_(c.cylinderPressure),
      film_(c.engine, c.piston, c.grid),
      solver_(film_.grid(), makeLubricant(c.lubricant), filmSolverOptions(c.lubricant)) {
    const fem::Stopwatch t0;
    if (c.coupling.elasticSqueeze && c.coupling.method == CouplingMethod::Partitioned)
        throw std::invalid_argument(
            "coupling: the elastic deformation rate in the squeeze term needs coupling.method: newton; set "
            "coupling.elastic_squeeze: false for the partitioned iteration (docs/coupling.md section 3)");
    if (c.contact.compositeModulus > 0.0) {
        contact_.emplace(c.contact.sigma, c.contact.beta, c.contact.asperityDensity, c.contact.compositeModulus);
        foundation_.emplace(c.contact.hardContactStiffness > 0.0
                                ? c.contact.hardContactStiffness
                                : lube::ElasticFoundation::layerStiffness(c.contact.coatingModulus, c.contact.coatingPoisson,
                                                                          c.contact.coatingThickness));
    }
    if (c.pistonBody.model == BodyModel::Flexible) {
        piston_ = loadFlexibleSurface(c, c.pistonBody, "piston", FlexibleSurface::Side::Piston, film_.grid());
        mp_ = piston_->modes();
    }
    if (c.linerBody.model == BodyModel::Flexible) {
        // The grid slides over the liner between BDC and TDC (plus a margin of two grid rows).
        const double lo = std::min(linerOffset(180.0), linerOffset(0.0));
        const double hi = std::max(linerOffset(180.0), linerOffset(0.0));
        const double margin = 2.0 * film_.grid().length() / (film_.grid().nAxial() - 1);
        liner_ = loadFlexibleSurface(c, c.linerBody, "liner", FlexibleSurface::Side::Liner, film_.grid(),
                                     lo + c.piston.skirtBottom - margin, hi + c.piston.skirtTop + margin);
        ml_ = liner_->modes();
    }
    if (mp_ + ml_ > 0) requireFilmMemory(gridKey(c), c.grid.axialNodes, c.grid.circumferentialNodes, mp_ + ml_);
    if (c.coupling.response == ElasticResponse::Dynamic) {
        if (piston_)
            pistonDynamics_ = std::make_unique<modal::HeldModalDynamics>(piston_->body(), piston_->heldInterfaces());
        if (liner_)
            linerDynamics_ = std::make_unique<modal::HeldModalDynamics>(liner_->body(), liner_->heldInterfaces());
    }
    if (ClearanceTerms::wanted(c)) {
        // Liner offsets the grid visits: the extremes of the crank-slider over a revolution.
        double lo = linerOffset(0.0), hi = lo;
        for (int k = 1; k <= 1440; ++k) {
            const double s = linerOffset(0.25 * k);
            lo = std::min(lo, s);
            hi = std::max(hi, s);
        }
        clearance_ = std::make_unique<ClearanceTerms>(c, film_.grid(), lo, hi);
    }
    if (c.coupling.method == CouplingMethod::Partitioned && (piston_ || liner_)) {
        // A unit of e or β moves the film by up to 1 or the skirt reach; a modal coordinate by the
        // largest entry of its film-change shape (the liner's at its mid-stroke offset).
        const double reach = std::max(c.piston.skirtTop, -c.piston.skirtBottom);
        partitionedScale_.resize(2 + mp_ + ml_);
        partitionedScale_.head<2>() << 1.0, reach;
        Eigen::MatrixXd Psi;
        if (piston_) {
            piston_->filmChangeShapes(0.0, Psi);
            partitionedScale_.segment(2, mp_) = Psi.colwise().lpNorm<Eigen::Infinity>().transpose();
        }
        if (liner_) {
            liner_->filmChangeShapes(linerOffset(90.0), Psi);
            partitionedScale_.tail(ml_) = Psi.colwise().lpNorm<Eigen::Infinity>().transpose();
        }
        for (Eigen::Index j = 0; j < partitionedScale_.size(); ++j)
            partitionedScale_[j] = (partitionedScale_[j] > 0.0 ? partitionedScale_[j] : 1.0) / c.piston.clearance;
    }
    if (c.coupling.method == CouplingMethod::Newton && (piston_ || liner_)) {
        linearization_ = std::make_unique<lube::FilmLinearization>(film_.grid());
        newtonParts_ = std::make_unique<CoupledJacobianParts>();
        if (piston_) piston_->filmChangeShapes(0.0, psiPiston_);
    }
    stats_.timings.setup = t0.seconds();
}

PistonSimulation::~PistonSimulation() = default;

void PistonSimulation::contactPressure(double h, double& asperity, double& hard) const {
    asperity = contact_->pressure(std::max(h, 0.0));
    hard = foundation_->pressure(h);
}

double PistonSimulation::contactSlope(double h) const {
    if (h < 0.0) return foundation_->pressureSlope(h);
    return contact_->pressureSlope(h);
}

double PistonSimulation::linerOffset(double crankDeg) const {
    return -case_.engine.pinTdcDepth - (kin_.tdcPosition() - kin_.at(crankDeg).position);
}

ClearanceRange PistonSimulation::centredClearance(double crankDeg) const {
    Eigen::VectorXd h;
    film_.rigidThickness(0.0, 0.0, h);
    if (clearance_) clearance_->add(linerOffset(crankDeg), h);
    const lube::FilmGrid& g = film_.grid();
    ClearanceRange r{std::numeric_limits<double>::infinity(), 0.0, -std::numeric_limits<double>::infinity()};
    int n = 0;
    for (int k = 0; k < g.size(); ++k)
        if (g.kind(k) != lube::NodeKind::Void) {
            r.min = std::min(r.min, h[k]);
            r.max = std::max(r.max, h[k]);
            r.mean += h[k];
            ++n;
        }
    r.mean /= std::max(n, 1);
    return r;
}

// Good Broyden update of the kept inverse Jacobian H for the update s and the residual change
// dF it caused, in the norm of the film-thickness change of s (Sherman–Morrison):
//   J₊ = J + (dF − J s) wᵀ/(wᵀ s),  w = D⁻² s  ⇔  H₊ = H + (s − H dF)(wᵀ H)/(wᵀ H dF).
void PistonSimulation::broydenUpdate(const Eigen::VectorXd& s, const Eigen::VectorXd& dF) {
    const Eigen::VectorXd w = s.cwiseProduct(unknownScale_).cwiseProduct(unknownScale_);
    const Eigen::VectorXd HdF = newtonInverse_ * dF;
    const double denom = w.dot(HdF);
    if (!(std::abs(denom) > 1e-12 * w.norm() * HdF.norm())) return;  // update undefined: keep H
    const Eigen::RowVectorXd wH = w.transpose() * newtonInverse_;
    newtonInverse_.noalias() += (s - HdF) * (wH / denom);
}

StepRecord PistonSimulation::record(const State& s, const Evaluation& ev, int cycle, double stepDeg,
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
    r.filmForce = ev.loads.pressureForce.x() + ev.loads.shearForce.x() + ev.loads.boundaryFrictionForce.x();
    r.filmMoment = ev.loads.moment.y();
    r.contactForce = ev.loads.contactForce.x();
    r.hardContactForce = ev.hardForce;
    r.frictionForce = ev.loads.frictionForce().z();
    r.linerHydrodynamicFriction = ev.loads.outerShearForce.z();
    r.linerBoundaryFriction = -ev.loads.boundaryFrictionForce.z();
    r.dissipatedPower = ev.loads.dissipatedPower();
    r.boundaryFrictionPower = ev.loads.boundaryFrictionPower;
    r.minFilm = ev.minGap;  // unfloored: < 0 where the surfaces overlap
    r.maxPressure = ev.p.size() ? ev.p.maxCoeff() : 0.0;
    if (piston_ || liner_) {
        const lube::FilmGrid& g = film_.grid();
        for (int k = 0; k < g.size(); ++k)
            if (g.kind(k) != lube::NodeKind::Void)
                r.elasticFilmChange = std::max(r.elasticFilmChange, std::abs(ev.hTotal[k] - ev.hRigid[k]));
    }
    r.couplingIterations = iterations;
    r.stepDeg = stepDeg;
    return r;
}

Snapshot PistonSimulation::snapshot(const State& s, const Evaluation& ev, int cycle) const {
    Snapshot sn;
    const lube::FilmGrid& g = film_.grid();
    const CrankState k = kin_.at(s.crankDeg);
    sn.cycle = cycle;
    sn.crankDeg = cycleCrankDeg(s.crankDeg, cycle);
    sn.continuousDeg = s.crankDeg;
    sn.pinHeight = k.position;
    sn.linerOffset = linerOffset(s.crankDeg);
    sn.lateral = s.x[0];
    sn.tilt = s.x[1];
    sn.pressure = ev.p;
    sn.filmThickness = ev.hTotal;  // unfloored: < 0 where the surfaces overlap
    sn.contactPressure = ev.pc;
    sn.cavitation = Eigen::VectorXd::Zero(g.size());
    sn.shearStress = Eigen::VectorXd::Zero(g.size());
    const double eta = solver_.lubricant().referenceViscosity();
    for (int k2 = 0; k2 < g.size(); ++k2) {
        if (g.kind(k2) == lube::NodeKind::Void) continue;
        if (g.kind(k2) == lube::NodeKind::Film && ev.p[k2] <= case_.lubricant.cavitationPressure) sn.cavitation[k2] = 1.0;
        // τ_z on the piston = η (V_liner − V_piston)/h − (h/2) ∂p/∂z (central differences).
        const int i = g.axialIndex(k2), j = g.thetaIndex(k2);
        const int i0 = std::max(0, i - 1), i1 = std::min(g.nAxial() - 1, i + 1);
        const double dpdz = (ev.p[g.index(i1, j)] - ev.p[g.index(i0, j)]) / (g.z(i1) - g.z(i0));
        const double phi = sn.cavitation[k2] > 0.0 ? 0.0 : 1.0;  // no Couette shear where cavitated
        sn.shearStress[k2] = phi * eta * (-k.velocity) / ev.h[k2] - 0.5 * ev.h[k2] * dpdz;
    }
    if (piston_) sn.pistonModal = s.y.head(mp_);
    if (liner_) sn.linerModal = s.y.tail(ml_);
    return sn;
}

PistonSimulation::State PistonSimulation::initialState(const SimulationCallbacks& cb) const {
    State s;
    s.crankDeg = case_.time.startDeg;
    film_.rigidThickness(0.0, 0.0, s.h);
    if (clearance_) {
        clearance_->add(linerOffset(s.crankDeg), s.h);
        if (cb.progress) {
            cb.progress("film thickness: " + clearance_->summary());
            std::string line = "centred clearance (min / mean / max over the skirt):";
            for (const auto& [name, deg] : {std::pair{"TDC", 0.0}, {"mid-stroke", 90.0}, {"BDC", 180.0}}) {
                const ClearanceRange r = centredClearance(deg);
                line += fmt::format(" {} {:.1f} / {:.1f} / {:.1f} um{}", name, r.min * 1e6, r.mean * 1e6, r.max * 1e6,
                                    deg < 180.0 ? ";" : "");
            }
            cb.progress(line);
        }
    }
    s.hRigid = s.h;
    s.hTotal = s.h;  // undeformed bodies at the start
    s.y = Eigen::VectorXd::Zero(mp_ + ml_);
    if (pistonDynamics_ || linerDynamics_) s.w = Eigen::VectorXd::Zero(mp_ + ml_);  // bodies at rest
    return s;
}

double PistonSimulation::plannedStep(double crankDeg, double dtDeg, double cycleStart, double cycleEnd,
                                     bool& atSnapshot) const {
    const TimeSpec& T = case_.time;
    const double every = case_.output.vtkEveryDeg;
    double step = std::min(dtDeg, cycleEnd - crankDeg);
    atSnapshot = false;
    if (every > 0.0) {
        // The next snapshot angle; those closer than time.min_step_deg to the present state
        // are skipped (landing on them would need a step below the smallest allowed).
        double next = cycleStart + every * (std::floor((crankDeg - cycleStart) / every + 1e-9) + 1.0);
        if (next - crankDeg < T.minStepDeg) next += every * std::ceil((T.minStepDeg - (next - crankDeg)) / every);
        if (next - crankDeg <= step + 1e-12) {
            step = next - crankDeg;
            atSnapshot = true;
        }
    }
    if (std::abs(crankDeg + step - cycleEnd) < 1e-9) atSnapshot = every > 0.0;
    return step;
}

double PistonSimulation::localErrorRatio(const State& s, const State& n, double stepDeg) const {
    // The predictor–corrector difference against time.lateral_tolerance and tilt_tolerance.
    const double dt = stepDeg * kin_.secondsPerDegree();
    const Eigen::Vector2d pred = s.x + dt * s.v + 0.5 * dt * dt * s.a;
    const Eigen::Vector2d err = 0.5 * (n.x - pred).cwiseAbs();
    return std::max(err[0] / case_.time.lateralTolerance, err[1] / case_.time.tiltTolerance);
}

std::string PistonSimulation::stepSizeExhausted(const State& s, int cycle, bool converged, double ratio,
                                                const std::string& failure) const {
    // A folded quasi-static equilibrium is no matter of step size or iterations.
    const std::string advice =
        !converged && foldedJacobians_ > 0
            ? "The skirt's quasi-static equilibrium in the film is lost here: on some combination of "
              "its modes the film's stiffness (the wedge of the sliding liner) exceeds the "
              "structure's (det(I - dH/dy) < 0 in the step's Jacobian), and without the elastic "
              "deformation rate in the squeeze term nothing resists that deformation. Set "
              "coupling.elastic_squeeze: true (docs/coupling.md section 3)."
        : !converged && (piston_ || liner_) && case_.coupling.method == CouplingMethod::Partitioned
            ? "With coupling.method: partitioned the squeeze term holds the rigid rate only; where "
              "the iteration fails at high speed (on the example engine from 4000 rpm on, early in "
              "the intake stroke) the skirt's quasi-static equilibrium in the film is lost, as with "
              "the rigid rate in coupling.method: newton (docs/coupling.md section 1). "
              "coupling.method: newton with coupling.elastic_squeeze: true (the defaults) runs the "
              "whole map."
            : "Try a smaller time.max_step_deg, a finer film grid, more coupling.max_iterations, or "
              "check the loads and clearances of the case.";
    return fmt::format(
        "the time step fell below time.min_step_deg = {:g} deg at crank angle {:.4f} deg of cycle {}: {}. "
        "State: lateral shift {:.3f} um, tilt {:.4f} mrad, minimum film {:.3f} um. {}",
        case_.time.minStepDeg, crankAngle720(s.crankDeg), cycle,
        converged ? fmt::format("local error {:.3g} x the tolerance", ratio) : failure, s.x[0] * 1e6, s.x[1] * 1e3,
        minimumGap(film_.grid(), s.hTotal) * 1e6, advice);
}

void PistonSimulation::requireBoundedMotion(const State& n, int cycle) const {
    const double skirtLength = case_.piston.skirtTop - case_.piston.skirtBottom;
    if (!n.x.allFinite() || std::abs(n.x[0]) > 20.0 * case_.piston.clearance ||
        std::abs(n.x[1]) * skirtLength > 40.0 * case_.piston.clearance)
        throw std::runtime_error(fmt::format(
            "the secondary motion diverged at crank angle {:.3f} deg of cycle {}: lateral shift {:.3g} m, "
            "tilt {:.3g} rad (clearance {:.3g} m). Is asperity contact (contact.composite_modulus) on?",
            crankAngle720(n.crankDeg), cycle, n.x[0], n.x[1], case_.piston.clearance));
}

void PistonSimulation::checkLoadMapping(const Evaluation& ev, double& worstDiff, double& largestForce) {
    // The mapped resultant on the flexible piston against the film's normal force.
    const Eigen::Matrix<double, 6, 1> r =
        piston_->resultant(ev.p + ev.pc, 0.0, Eigen::Vector3d(case_.engine.pinOffset, 0.0, 0.0));
    const Eigen::Vector3d film = ev.loads.pressureForce + ev.loads.contactForce;
    worstDiff = std::max(worstDiff, (r.head<3>() - film).norm());
    largestForce = std::max(largestForce, film.norm());
    stats_.worstMappingError = worstDiff / std::max(largestForce, 1e-300);
}

double PistonSimulation::periodicityError(const std::vector<StepRecord>& cycle, const std::vector<double>& since,
                                          const std::vector<StepRecord>& previous,
                                          const std::vector<double>& previousSince) const {
    // Eccentricities at the skirt ends, this cycle vs the previous one, interpolated to the same
    // degrees since the cycle's start (docs/coupling.md §1).
    const double reach = std::max(case_.piston.skirtTop, -case_.piston.skirtBottom);
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
        err = std::max({err, std::abs(r.lateral - e0) + std::abs(r.tilt - t0) * reach});
    }
    return err;
}

std::vector<StepRecord> PistonSimulation::run(const SimulationCallbacks& cb, double spanDeg) {
    const fem::Stopwatch tRun;
    const TimeSpec& T = case_.time;
    State s = initialState(cb);
    State prev = s;
    double dtDeg = std::min(T.maxStepDeg, 0.1);
    const double every = case_.output.vtkEveryDeg;
    std::vector<StepRecord> previousCycle, cycleRecords;
    // Degrees since the start of the cycle of each record (monotonic, unlike the written crank
    // angle when time.start_deg > 0): the abscissa of the periodicity comparison.
    std::vector<double> previousSince, cycleSince;
    Evaluation ev, lastEv;
    bool haveLast = false;
    stats_ = RunStatistics{.timings = stats_.timings};
    stats_.minStepDeg = T.maxStepDeg;
    double worstMappingDiff = 0.0, largestFilmForce = 0.0;
    const double filmT0 = stats_.timings.film, structT0 = stats_.timings.structure;
    RunProgress progress(T.maxCycles, T.periodicityTolerance);
    for (int cycle = 1; cycle <= T.maxCycles; ++cycle) {
        const double cycleStart = T.startDeg + 720.0 * (cycle - 1);
        const double cycleEnd = spanDeg > 0.0 ? std::min(cycleStart + 720.0, T.startDeg + spanDeg) : cycleStart + 720.0;
        cycleRecords.clear();
        cycleSince.clear();
        progress.startCycle(cycle, tRun.seconds());
        int snapshots = 0;
        auto takeSnapshot = [&](const State& at, const Evaluation& e) {
            ++snapshots;
            if (cb.onSnapshot) cb.onSnapshot(snapshot(at, e, cycle));
        };
        if (haveLast) {
            // The boundary point opens the new cycle's records too (its metrics and its 0° snapshot);
            // it is the last cycle's final step, written to the history once, there.
            StepRecord r = record(s, lastEv, cycle, 0.0, 0);
            cycleRecords.push_back(r);
            cycleSince.push_back(s.crankDeg - cycleStart);
            if (every > 0.0) takeSnapshot(s, lastEv);
        }
        double nextProgress = cycleStart;
        while (s.crankDeg < cycleEnd - 1e-9) {
            bool atSnapshot = false;
            const double step = plannedStep(s.crankDeg, dtDeg, cycleStart, cycleEnd, atSnapshot);
            State n;
            int iterations = 0;
            std::string failure;
            const bool ok = advance(s, prev, step, n, ev, iterations, failure);
            const double ratio = ok ? localErrorRatio(s, n, step) : 0.0;
            if (!ok || ratio > 1.0) {
                ++stats_.rejectedSteps;
                dtDeg = ok ? step * std::max(0.2, 0.9 * std::pow(ratio, -1.0 / 3.0)) : 0.25 * step;
                if (dtDeg < T.minStepDeg) throw std::runtime_error(stepSizeExhausted(s, cycle, ok, ratio, failure));
                continue;
            }
            requireBoundedMotion(n, cycle);
            ++stats_.steps;
            foldedJacobians_ = 0;
            stats_.maxIterations = std::max(stats_.maxIterations, iterations);
            stats_.minStepDeg = std::min(stats_.minStepDeg, step);
            if (piston_) checkLoadMapping(ev, worstMappingDiff, largestFilmForce);
            prev = std::move(s);
            s = std::move(n);
            lastEv = ev;
            haveLast = true;
            StepRecord rec = record(s, ev, cycle, step, iterations);
            cycleRecords.push_back(rec);
            cycleSince.push_back(s.crankDeg - cycleStart);
            if (cb.onStep) cb.onStep(rec);
            if (atSnapshot) takeSnapshot(s, ev);
            // Next step: grow with the error ratio, from the unclipped step size.
            const double grow = ratio > 0.0 ? std::min(2.0, 0.9 * std::pow(ratio, -1.0 / 3.0)) : 2.0;
            dtDeg = std::min(T.maxStepDeg, std::max(step, std::min(dtDeg, T.maxStepDeg)) * grow);
            if (cb.progress && s.crankDeg >= nextProgress) {
                nextProgress += 30.0;
                cb.progress(progress.stepLine(cycleCrankDeg(s.crankDeg, cycle), (s.crankDeg - cycleStart) / (cycleEnd - cycleStart),
                                              tRun.seconds(), s.x[0], s.x[1], iterations, step));
            }
        }
        stats_.cycles = cycle;
        if (!previousCycle.empty()) {  // this cycle vs the previous one
            stats_.periodicityError = periodicityError(cycleRecords, cycleSince, previousCycle, previousSince);
            stats_.periodic = stats_.periodicityError <= T.periodicityTolerance;
        }
        if (cb.progress)
            cb.progress(progress.cycleDoneLine(tRun.seconds(), previousCycle.empty() ? std::nullopt
                                                                                   : std::optional(stats_.periodicityError)));
        const bool last = stats_.periodic || cycle == T.maxCycles || (spanDeg > 0.0 && cycleEnd >= T.startDeg + spanDeg - 1e-9);
        if (cb.onCycleEnd) cb.onCycleEnd(cycle, snapshots, last);
        if (last) break;
        previousCycle = cycleRecords;
        previousSince = cycleSince;
    }
    stats_.timings.dynamics = tRun.seconds() - (stats_.timings.film - filmT0) - (stats_.timings.structure - structT0);
    return cycleRecords;
}

}  // namespace flexehd::cosim
