#pragma once
// FilmContact: one lubricated contact of the piston as the co-simulation master sees it
// (docs/coupling.md §1, "Film contacts"). The master's unknowns of a step are the
// secondary motion x = (e, β) and the modal coordinates y of the flexible bodies (the piston's,
// then the liner's); a contact turns an iterate (x, y) into
//   * its film: thickness from the motion, its clearance terms and the bodies' elastic change,
//     contact pressure, the film solve and the film's loads;
//   * its action on the piston's equations of motion (lateral force, axial force, moment about
//     the pin axis);
//   * its modal load on the bodies' coordinates (the mapped film and contact pressure);
//   * for the coupled Newton method, the change of those loads with y (ContactJacobian).
// The master sums the contacts' actions and modal loads; the bodies' response to the summed load
// and the whole iteration are the master's. Every contact keeps its own grid, solver, surface
// mappings and history (ContactState); a contact is a new class, never an edit of the step.

#include "cosim/contact/ContactColumns.hpp"
#include "cosim/contact/CouplingNeeds.hpp"
#include "cosim/contact/FilmFigures.hpp"
#include "cosim/engine/PistonDynamics.hpp"
#include "cosim/engine/RingGas.hpp"
#include "cosim/oil/LinerOil.hpp"
#include "lube/FilmIntegrals.hpp"

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace flexehd::cosim {

/// What a contact sees of the step: its BDF2 coefficients, the piston's axial velocity and where
/// the piston frame is along the liner.
struct ContactStep {
    double dt = 0.0;                  ///< s
    double a0 = 1.0, a1 = -1.0, a2 = 0.0;  ///< BDF2: ḟ = (a0 f + a1 fₙ + a2 fₙ₋₁)/dt
    double pistonVelocity = 0.0;      ///< m/s, the piston's axial velocity (+z towards the head)
    double linerOffset = 0.0;         ///< m, liner-frame z of the piston frame's origin
    double cylinderPressure = 0.0;    ///< Pa, gauge (relative to the crankcase) at the step's end
    /// The liner's oil layer at the step's start and every contact's cover on it (null: no
    /// contact runs on a liner layer).
    const LinerOilState* oil = nullptr;
    /// The ring pack's gas, per ring top first (null: no gas model: the cylinder's pressure above
    /// and behind the top ring, the crankcase's below it and round the other rings).
    const std::vector<RingGas>* ringGas = nullptr;
};

/// Oil volumes (m³) a mass-conserving film exchanged since the start of the run (docs/coupling.md
/// §6): through its axial edges in and out, and out at its sides (into the panels' relief: lost
/// to the crankcase).
struct OilBalance {
    double edgeIn = 0.0, edgeOut = 0.0, sideOut = 0.0;
};

/// A contact's film at an accepted step: the history its squeeze term and warm start need.
struct ContactState {
    Eigen::VectorXd h;       ///< m, the film thickness the film equation saw (floored)
    Eigen::VectorXd hRigid;  ///< m, rigid motion + clearance terms
    Eigen::VectorXd hTotal;  ///< m, rigid + elastic, unfloored (< 0: overlap)
    Eigen::VectorXd p;       ///< Pa, gauge film pressure
    Eigen::VectorXd fraction;  ///< mass-conserving film: film fraction φ per node (empty: Reynolds)
    /// m/s, the damped hard contact's impact speed per node (0 where the surfaces do not overlap;
    /// empty: none anywhere)
    Eigen::VectorXd impactSpeed;
    double linerOffset = 0.0;  ///< m, the step's liner offset
    OilBalance oilBalance;     ///< mass-conserving film: cumulative volumes
    /// m, smallest unfloored film thickness over the film's nodes (< 0: the surfaces overlap;
    /// +∞ for a contact that does not say)
    double minGap = std::numeric_limits<double>::infinity();
    /// N, the contact's axial force on the piston at the step (+z towards the head)
    double axialForce = 0.0;
    /// A ring on the liner's oil layer: the gap its oil leaves open to the gas (none elsewhere)
    RingOpenGap openGap;
};

/// A contact's film at one iterate (x, y) of a step.
struct ContactIterate {
    Eigen::VectorXd h, hRigid, hTotal, dhdt, p;  ///< as ContactState; dhdt the squeeze rate (m/s)
    Eigen::VectorXd pc;      ///< Pa, contact pressure (asperities + hard contact)
    Eigen::VectorXd pcHard;  ///< Pa, its hard-contact part
    Eigen::VectorXd impactSpeed;  ///< m/s, as ContactState (a damped hard contact only)
    Eigen::VectorXd approach;     ///< m/s, −ḣ where the damped hard contact acts (0 elsewhere)
    double hardForce = 0.0;  ///< N, lateral (x) force of the hard contact on the piston
    double minGap = 0.0;     ///< m, smallest unfloored film thickness (< 0: the surfaces overlap)
    int floored = 0;         ///< nodes where the film equation saw the floor, not hTotal
    lube::FilmLoads loads;   ///< forces, moments (about the pin), friction, powers
    FilmAction action;       ///< on the piston's equations of motion
    // The mass-conserving film only (empty / 0 with the Reynolds condition):
    Eigen::VectorXd fraction;                ///< film fraction φ per node
    Eigen::VectorXd inflowLow, inflowHigh;   ///< m³/s per grid column into the film through its lower / upper edge
    double sideInflow = 0.0;                 ///< m³/s into the film at its sides (< 0: leakage)
    double oilVolume = 0.0;                  ///< m³, oil in the film, Σ V φ h
    double layerLeft = 0.0;  ///< m, a ring on the liner's layer: the layer it leaves behind (outflow / |U|)
    RingOpenGap openGap;     ///< a ring on the liner's layer: the gap its oil leaves open to the gas
    /// a ring on the liner's layer: 1 where a face's film is open to the gas in the step (partial
    /// from edge to edge between two gases, or unable to hold the higher one: docs/lube.md §9), else 0
    double openToGas = 0.0;
    Eigen::VectorXd linerLoad;  ///< Pa, a ring on a flexible liner: its pressure on the liner, on its load grid
};

/// The oil balance after an accepted step of dt (s) from `b`: the iterate's flows in and out
/// through the edges and out at the sides, as volumes.
inline OilBalance afterStep(OilBalance b, const ContactIterate& it, double dt) {
    for (Eigen::Index j = 0; j < it.inflowLow.size(); ++j)
        for (double q : {it.inflowLow[j], it.inflowHigh[j]}) (q > 0.0 ? b.edgeIn : b.edgeOut) += std::abs(q) * dt;
    b.sideOut -= it.sideInflow * dt;
    return b;
}

/// The change of a contact's loads with the modal coordinates y at an iterate, affine in the
/// step's rate r = a0/dt (the elastic squeeze term): δload = (loadH + r loadRate) δy and
/// δ(modal load) = (modalH + r modalRate) δy; the rate parts are empty without
/// coupling.elastic_squeeze.
struct ContactJacobian {
    Eigen::MatrixXd loadH, loadRate;    ///< 6 × modes: (F_x, F_y, F_z, M_x, M_y, M_z) about the pin
    Eigen::MatrixXd modalH, modalRate;  ///< modes × modes: the modal load on (piston, liner) rows
    /// The same for the rigid motion (e, β): 6 × 2 and modes × 2, given where the contact's
    /// linearisation follows a rigid motion as differences of its full solves do (a contact without
    /// loads: empty); otherwise motionColumns is false and the master forms them by differences.
    Eigen::MatrixXd loadX, modalX;
    bool motionColumns = false;
    /// 2 + modes: the largest film-thickness change per unit of each unknown (e, β, y)
    Eigen::VectorXd filmChangePerUnknown;
};

/// The work of the contacts and of the step's iteration, added into the run's statistics.
struct WorkTally {
    double film = 0.0;     ///< s: film thickness, contact, film solves and integrals
    double mapping = 0.0;  ///< s: load and deformation mapping products
    double modal = 0.0;    ///< s: modal response, the coupled Jacobian's structure part, acceleration
    long filmSolves = 0;
    long fallbackSolves = 0;  ///< film solves redone by the fallback solver
    long jacobians = 0;       ///< Jacobians formed by the step's iteration
    long resolvedSteps = 0;   ///< steps ended by the coupled Newton's resolution test
};

class FilmContact {
public:
    virtual ~FilmContact() = default;

    /// The film at the start of the run: piston centred, bodies undeformed, at the liner offset.
    virtual ContactState initialState(double linerOffset) const = 0;
    /// The film at the iterate (x, y): thickness, contact, film solve, loads and action.
    /// now, before: the contact's last two accepted states. Throws std::runtime_error when the
    /// film solve fails.
    virtual void evaluate(const ContactStep& step, const ContactState& now, const ContactState& before,
                          const Eigen::Vector2d& x, const Eigen::VectorXd& y, ContactIterate& it,
                          WorkTally& work) = 0;
    /// Adds the iterate's modal load (N per unit modal coordinate; piston rows, then liner rows)
    /// to f.
    virtual void addModalLoad(const ContactStep& step, const ContactIterate& it, Eigen::VectorXd& f,
                              WorkTally& work) const = 0;
    /// The largest film-thickness change (m) the change dy of the modal coordinates makes.
    virtual double filmChange(const ContactStep& step, const Eigen::VectorXd& dy, WorkTally& work) const = 0;
    /// An upper bound of filmChange(dy) at any step that needs no product over the grid
    /// (m; the default, infinity: none).
    virtual double filmChangeBound(const Eigen::VectorXd& /*dy*/) const {
        return std::numeric_limits<double>::infinity();
    }
    /// The largest film-thickness change per unit of each modal coordinate (m) at a typical
    /// position (the units of the partitioned coupling's acceleration); empty (the default) for a
    /// contact the modes do not move.
    virtual Eigen::VectorXd modalFilmChangeScale() const { return {}; }
    /// coupling.method newton: the loads' change with y at the iterate of the step from `now`.
    virtual void linearize(const ContactStep& step, const ContactState& now, const Eigen::Vector2d& x,
                           const ContactIterate& it,
                           ContactJacobian& J, WorkTally& work) = 0;
    /// The state kept from an accepted iterate of the step from `now`.
    virtual ContactState accepted(const ContactStep& step, const ContactState& now, const ContactIterate& it) const = 0;
    /// A contact with a modal load on the flexible piston: its mapped resultant against its film's
    /// normal force, worstDiff = max |mapped − film| (N), largestForce = max |film| (N) over the
    /// calls (RunStatistics::worstMappingError); nothing to check by default.
    virtual void checkLoadMapping(const ContactIterate& /*it*/, double& /*worstDiff*/, double& /*largestForce*/) const {}

    /// The columns this contact adds to history.csv after the master's, with their summary.json
    /// figures (ContactColumns.hpp); none by default. Fixed for the contact's life.
    virtual std::vector<ContactColumn> columns() const { return {}; }
    /// The values of columns() at an accepted iterate, appended to `values` in their order.
    virtual void columnValues(const ContactIterate& /*it*/, std::vector<double>& /*values*/) const {}
    /// The run's own film results (FilmFigures.hpp) at an accepted iterate, and its film fields at
    /// a snapshot (pistonVelocity in m/s, for the shear stress): a contact that reports them (the
    /// skirt's) fills them and returns true, and the master asks no further contact; one that does
    /// not (the default) returns false and reports through columns().
    virtual bool filmFigures(const ContactIterate& /*it*/, FilmFigures& /*figures*/) const { return false; }
    virtual bool filmFields(const ContactIterate& /*it*/, double /*pistonVelocity*/, FilmFields& /*fields*/) const {
        return false;
    }
    /// Progress lines for the start of a run (e.g. the clearance the film starts from); none by
    /// default.
    virtual std::vector<std::string> startReport() const { return {}; }

    /// Its film conserves oil (a mass-conserving film): the run then writes the oil columns and
    /// balances the oil (docs/coupling.md §6); false by default.
    virtual bool carriesOil() const { return false; }
    /// A contact on the liner's oil layer (docs/coupling.md §6, "The liner's oil layer and its
    /// covers"): what it needs of the master's layer; none (the default) for a contact that
    /// neither reads nor writes it.
    virtual std::optional<LinerFootprint> linerFootprint() const { return std::nullopt; }
    /// The band of the liner it covers at the liner offset (m; a contact with a footprint).
    virtual LinerCover linerCover(double /*linerOffset*/) const { return {}; }
    /// Its trade with the layer over the accepted step from `now` to `next` (the accepted
    /// iterate `it`): what its edges took in, left and banked (LinerOilExchange).
    virtual void exchangeOil(const ContactState& /*now*/, const ContactState& /*next*/, const ContactIterate& /*it*/,
                             LinerOilExchange& /*ex*/) const {}
    /// What the coupling scheme needs of the contact (CouplingNeeds.hpp), told once before the
    /// contact's first step; nothing to prepare by default.
    virtual void prepare(const CouplingNeeds& /*needs*/) {}
    /// A ring of the pack's gas model (docs/ring-pack.md, "The pack's gas in a run"): its place in
    /// the pack, top first, whose ContactStep::ringGas entry it reads and whose axial balance takes
    /// its friction (ContactState::axialForce); −1 (the default) for any other contact.
    virtual int packRing() const { return -1; }
};

}  // namespace flexehd::cosim
