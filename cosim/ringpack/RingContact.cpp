#include "cosim/ringpack/RingContact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "cosim/mapping/FlexibleBodyLoader.hpp"
#include "cosim/oil/OilSupply.hpp"
#include "fem/Stopwatch.hpp"

namespace flexehd::cosim {
namespace {

// The film's face: the ring's, or one of the oil-control ring's two lands.
lube::RingFaceProfile faceProfile(const RingSpec& r) {
    if (r.lands) return lube::RingFaceProfile::barrel(r.lands->width, r.lands->crownHeight);
    if (r.face.table.empty()) return lube::RingFaceProfile::barrel(r.height, r.face.crownHeight, r.face.vertexOffset);
    return lube::RingFaceProfile::table(r.face.table);
}

lube::GreenwoodTripp asperityLaw(const EngineCase& c, const RingSpec& r) {
    if (!(c.contact.compositeModulus > 0.0))
        throw std::invalid_argument(fmt::format(
            "ring '{}': the ring needs asperity contact (contact.composite_modulus > 0): without it nothing carries "
            "the ring where the liner stops at the dead centres",
            r.name));
    return lube::GreenwoodTripp(r.roughness, c.contact.beta, c.contact.asperityDensity, c.contact.compositeModulus);
}

// The film's nodes across the face: 101 (a barrel's parabola), and on a tabulated face at least 8
// per shortest table interval (its edge rounding or chamfer, where a taper face runs).
int nodesAcross(const RingSpec& r, int faceNodes) {
    if (faceNodes > 0) return faceNodes;
    if (r.face.table.empty()) return 101;
    double shortest = r.height;
    for (std::size_t k = 1; k < r.face.table.size(); ++k)
        shortest = std::min(shortest, r.face.table[k].first - r.face.table[k - 1].first);
    return std::max(101, static_cast<int>(std::ceil(8.0 * r.height / shortest)) + 1);
}

const RingSpec& supported(const EngineCase& c, const RingSpec& r) {
    auto refuse = [&](const std::string& what) {
        throw std::invalid_argument(fmt::format("ring '{}': {} is not built for a ring contact yet", r.name, what));
    };
    if (r.kind == RingKind::OilControl && !r.lands) refuse("an oil-control ring without its lands");
    return r;
}

// On the liner's oil layer: the ring's cover (its height, on the groove's lower flank) round the
// bore, over the liner-frame range it sweeps; cells of half its height, so that its trailing edge
// never leaves oil in a cell its leading edge still takes from.
std::optional<RingOilExchange> ringOil(const RingSpec& r, const LinerFootprint* layer) {
    if (!layer) return std::nullopt;
    LinerFootprint f = *layer;
    f.zLow += r.groove.lowerFlank;
    f.zHigh += r.top();
    f.cell = 0.5 * r.height;
    return RingOilExchange({r.groove.lowerFlank, r.top()}, std::move(f));
}

}  // namespace

RingContact::RingContact(const EngineCase& c, const RingSpec& ring, bool top, int faceNodes, const LinerFootprint* layer,
                         std::shared_ptr<const FlexibleBody> liner, double offsetLow, double offsetHigh)
    : ring_(supported(c, ring)),
      top_(top),
      faces_(ring.lands ? 2 : 1),
      circumference_(std::numbers::pi * c.engine.bore),
      boundaryFriction_(c.contact.boundaryFriction),
      asperity_(asperityLaw(c, ring)),
      radial_(lube::RingFilm(faceProfile(ring), lube::Lubricant(c.lubricant.viscosity, c.lubricant.density),
                             nodesAcross(ring, faceNodes),
                             c.lubricant.cavitationPressure, ring.roughness),
              asperity_, ring.tensionPerLength / faces_, faces_),
      oil_(ringOil(ring, layer)),
      supply_(c.lubricant.supply),
      nodes_(nodesAcross(ring, faceNodes)) {
    if (c.ringGas.model == RingGasModel::Lands)
        for (std::size_t i = 0; i < c.rings.size(); ++i)
            if (c.rings[i].name == ring.name) {
                gasIndex_ = static_cast<int>(i);
                lastInPack_ = i + 1 == c.rings.size();
                lift_ = c.ringGas.ringLift;
            }
    crankcasePressure_ = c.engine.crankcasePressure;
    if (!liner) return;
    // The load grid: kLoadRows rows across the ring's height, the case grid's θ columns, sliding
    // with the piston over the liner (two rows of margin).
    loadGrid_ = std::make_unique<lube::FilmGrid>(lube::FilmGrid::fullCircumference(
        0.5 * c.engine.bore, lube::FilmGrid::uniform(ring.groove.lowerFlank, ring.top(), kLoadRows),
        c.grid.circumferentialNodes));
    const double margin = 2.0 * ring.height / (kLoadRows - 1);
    linerSurface_ = facingSurface(c, std::move(liner), c.linerBody, "liner", FlexibleSurface::Side::Liner, *loadGrid_,
                                  offsetLow + ring.groove.lowerFlank - margin, offsetHigh + ring.top() + margin);
}

RingContact::~RingContact() = default;

std::optional<LinerFootprint> RingContact::linerFootprint() const {
    if (!oil_) return std::nullopt;
    return oil_->footprint();
}

double RingContact::restingGap() const {
    // The asperity load falls as the gap grows: bisection between a gap that carries more than the
    // tension and one that carries less.
    double lo = -RingRadialMotion::kDeepestGap * asperity_.sigma(), hi = 10.0 * asperity_.sigma();
    if (!(faces_ * radial_.asperityLoad(lo) > ring_.tensionPerLength))
        throw std::invalid_argument(fmt::format(
            "ring '{}': its asperities carry at most {:.4g} N/m (at a gap of -2 sigma), less than its tension of "
            "{:.4g} N/m: check contact.beta, contact.asperity_density, contact.composite_modulus and the ring's "
            "roughness and face",
            ring_.name, faces_ * radial_.asperityLoad(lo), ring_.tensionPerLength));
    for (int it = 0; it < 200 && hi - lo > 1e-12 * hi; ++it) {
        const double h = 0.5 * (lo + hi);
        (faces_ * radial_.asperityLoad(h) > ring_.tensionPerLength ? lo : hi) = h;
    }
    return 0.5 * (lo + hi);
}

ContactState RingContact::initialState(double linerOffset) const {
    ContactState s;
    s.linerOffset = linerOffset;
    s.minGap = restingGap();
    if (!oil_) return s;
    // Each face's film at rest holds the supply layer where the ring stands: φ = min(1, 2t/h).
    const lube::RingFaceProfile& f = radial_.film().profile();
    const double t = supplyLayerThickness(supply_, linerOffset + 0.5 * (ring_.groove.lowerFlank + ring_.top()));
    const double gap = std::max(s.minGap, radial_.filmFloor());
    s.fraction.resize(static_cast<Eigen::Index>(faces_) * nodes_);
    for (int i = 0; i < nodes_; ++i) {
        const double x = f.lower() + (f.upper() - f.lower()) * i / (nodes_ - 1);
        const double phi = std::min(1.0, 2.0 * t / (gap + f.drop(x)));
        for (int k = 0; k < faces_; ++k) s.fraction[k * nodes_ + i] = phi;
    }
    return s;
}

const RingRadialStep& RingContact::radialStep(const ContactStep& step, const ContactState& now, double guess) {
    // The gas above, behind and below the ring: the pack's lands, or the cylinder's above and
    // behind the top ring and the crankcase's elsewhere.
    gas_ = RingGas{};
    gas_.above = gas_.behind = top_ ? step.cylinderPressure : 0.0;
    if (gasIndex_ >= 0 && step.ringGas && gasIndex_ < static_cast<int>(step.ringGas->size()))
        gas_ = (*step.ringGas)[static_cast<std::size_t>(gasIndex_)];
    const double pressure = gas_.behind;
    const double U = -step.pistonVelocity;  // the liner relative to the ring, + towards the crown
    std::optional<RingSupply> supply;
    if (oil_ && step.oil && step.oil->layer) {
        supply.emplace();
        supply->film = oil_->supplyFilm(*step.oil, now.linerOffset, step.linerOffset, step.dt, U);
        for (int k = 0; k < faces_; ++k) supply->previousFraction.push_back(now.fraction.segment(k * nodes_, nodes_));
    }
    const Cached key{now.minGap, step.dt, step.pistonVelocity, gas_.above, gas_.behind, gas_.below,
                     supply ? supply->film : -1.0, gas_.faceOpening, gas_.faceOpeningBefore};
    if (cachedFor_ == key) return cached_;
    lube::RingFilmState conditions;
    conditions.slidingSpeed = U;
    conditions.pressureAbove = gas_.above;
    conditions.pressureBelow = gas_.below;
    cachedFor_.reset();  // a failed step leaves no stale result behind
    const RingSupply* oil = supply ? &*supply : nullptr;
    if (gas_.faceOpening > 0.0 || gas_.faceOpeningBefore > 0.0) {
        // Off the liner (ring lift): the gas moves the ring (RingPackGas's radial collapse), its
        // film carried along at the gap the opening's change leaves.
        cached_ = radial_.at(now.minGap + gas_.faceOpening - gas_.faceOpeningBefore, now.minGap, step.dt, conditions, oil);
        cachedFor_ = key;
        return cached_;
    }
    try {
        // With ring lift, where no gap up to the groove's root balances the ring, the gas pushes
        // it off the liner: it stays where it was until RingPackGas's radial collapse moves it.
        cached_ = radial_.step(now.minGap, step.dt, conditions, pressure, guess, oil,
                               lift_ ? ring_.groove.backClearance : std::numeric_limits<double>::quiet_NaN());
        if (cached_.atStop) cached_ = radial_.at(now.minGap, now.minGap, step.dt, conditions, oil);
    } catch (const std::runtime_error& e) {
        // No gap balances the ring when the gas on its face outweighs its tension and the gas
        // behind it: the ring collapses off the liner, which the radial balance does not model.
        throw std::runtime_error(fmt::format(
            "ring '{}': {} with {:.4g} Pa above its face, {:.4g} behind it and {:.4g} below (gauge){}", ring_.name,
            e.what(), gas_.above, gas_.behind, gas_.below,
            gas_.behind < std::max(gas_.above, gas_.below)
                ? ": the gas on its face outweighs its tension and the gas behind it, so the ring would collapse "
                  "radially, which a run models with ring_gas.ring_lift (docs/ring-pack.md, \"Ring collapse in a run\")"
                : ""));
    }
    cachedFor_ = key;
    return cached_;
}

void RingContact::oilFlows(const ContactStep& step, const ContactState& now, const RingRadialStep& r,
                           ContactIterate& it) const {
    const double circumference = oil_->circumference();
    it.fraction.resize(static_cast<Eigen::Index>(faces_) * nodes_);
    it.oilVolume = 0.0;
    for (int k = 0; k < faces_; ++k) {
        const lube::RingFilmResult& f = r.faces[static_cast<std::size_t>(k)];
        it.fraction.segment(k * nodes_, nodes_) = f.fraction;
        it.oilVolume += circumference * f.oil;
    }
    // In through the ring's lower and upper edges; between the lands, what the one lets out and
    // the other does not take in drains through the ring (its side flow).
    const lube::RingFilmResult &low = r.faces.front(), &high = r.faces.back();
    oil_->columnFlows(*step.oil, now.linerOffset, step.linerOffset, low.inflowLow, high.inflowHigh, it.inflowLow,
                      it.inflowHigh);
    it.sideInflow = faces_ > 1 ? circumference * (low.inflowHigh + high.inflowLow) : 0.0;
    // What the trailing edge leaves, as the layer the liner carries away at |U|.
    const double U = -step.pistonVelocity, out = U >= 0.0 ? -high.inflowHigh : -low.inflowLow;
    it.layerLeft = std::abs(U) > 0.0 ? std::max(out, 0.0) / std::abs(U) : 0.0;
    it.openToGas = std::any_of(r.faces.begin(), r.faces.end(),
                                  [](const lube::RingFilmResult& f) { return f.openToGas; })
                          ? 1.0
                          : 0.0;
    // The gap the oil leaves open to the gas, the faces in series.
    it.openGap.resistance = 0.0;
    it.openGap.narrowest = std::numeric_limits<double>::infinity();
    for (const lube::RingFilmResult& f : r.faces) {
        const lube::OpenGap g = lube::openGap(f);
        it.openGap.resistance += g.resistance;
        it.openGap.narrowest = std::min(it.openGap.narrowest, g.narrowest);
    }
    if (!std::isfinite(it.openGap.resistance)) it.openGap = RingOpenGap{};
}

void RingContact::evaluate(const ContactStep& step, const ContactState& now, const ContactState& before,
                           const Eigen::Vector2d& /*x*/, const Eigen::VectorXd& /*y*/, ContactIterate& it,
                           WorkTally& work) {
    const fem::Stopwatch t0;
    // The balance looked for from the last two gaps' linear extrapolation (steps of like size).
    const double guess = std::isfinite(before.minGap) ? 2.0 * now.minGap - before.minGap : now.minGap;
    const RingRadialStep& r = radialStep(step, now, guess);
    it = ContactIterate{};
    const lube::RingFilmResult& film = r.faces.front();
    it.h = it.hRigid = it.hTotal = film.h;
    it.p = film.p;
    it.dhdt = Eigen::VectorXd::Constant(film.h.size(), r.squeezeRate);
    it.minGap = r.minimumGap;
    if (oil_ && step.oil && step.oil->layer) oilFlows(step, now, r, it);
    if (linerSurface_) linerLoad(r, it.linerLoad);
    const double v = step.pistonVelocity;
    const double perFace = faces_ * circumference_;
    // The faces' shear: flooded one film for its alike faces, on the layer each its own.
    double friction = 0.0, pMax = 0.0;
    for (const lube::RingFilmResult& f : r.faces) {
        friction += f.friction;
        if (f.p.size()) pMax = std::max(pMax, f.p.maxCoeff());
    }
    const double hydro = circumference_ * friction * (faces_ / static_cast<double>(r.faces.size()));
    const double boundary = -perFace * boundaryFriction_ * r.asperityLoad * (v > 0.0 ? 1.0 : v < 0.0 ? -1.0 : 0.0);
    it.loads.shearForce.z() = hydro;
    it.loads.boundaryFrictionForce.z() = boundary;
    it.loads.contactLoad = perFace * r.asperityLoad;
    it.loads.viscousDissipation = -hydro * v;
    it.loads.boundaryFrictionPower = -boundary * v;
    it.loads.minFilm = r.minimumGap;
    it.loads.maxPressure = pMax;
    it.action.fz = hydro + boundary;
    work.film += t0.seconds();
}

void RingContact::linerLoad(const RingRadialStep& r, Eigen::VectorXd& load) const {
    // Each face's nodes at their piston-frame z: a face across the ring's height about its middle,
    // or the lands about it, half their separation below and above; flooded, the one film stands
    // for every land.
    const lube::FilmGrid& g = *loadGrid_;
    const lube::RingFaceProfile& f = radial_.film().profile();
    const double middle = 0.5 * (ring_.groove.lowerFlank + ring_.top()), row = ring_.height / (kLoadRows - 1);
    Eigen::VectorXd force = Eigen::VectorXd::Zero(kLoadRows);  // N/m of circumference per row
    for (int k = 0; k < faces_; ++k) {
        const lube::RingFilmResult& film = r.faces[std::min<std::size_t>(static_cast<std::size_t>(k), r.faces.size() - 1)];
        const double centre = faces_ > 1 ? middle + (k == 0 ? -0.5 : 0.5) * ring_.lands->separation
                                         : middle - 0.5 * (f.lower() + f.upper());
        const Eigen::Index n = film.x.size();
        for (Eigen::Index i = 0; i < n; ++i) {
            const double dx = i == 0 ? 0.5 * (film.x[1] - film.x[0])
                              : i == n - 1 ? 0.5 * (film.x[n - 1] - film.x[n - 2])
                                           : 0.5 * (film.x[i + 1] - film.x[i - 1]);
            const double pressure = film.p[i] + asperity_.pressure(r.minimumGap + f.drop(film.x[i]));
            const double z = centre + film.x[i];
            const int j = std::clamp(static_cast<int>(std::lround((z - ring_.groove.lowerFlank) / row)), 0, kLoadRows - 1);
            force[j] += pressure * dx;
        }
    }
    load.resize(g.size());
    for (int k = 0; k < g.size(); ++k) load[k] = force[g.axialIndex(k)] / g.axialWidth(g.axialIndex(k));
}

void RingContact::addModalLoad(const ContactStep& step, const ContactIterate& it, Eigen::VectorXd& f,
                               WorkTally& work) const {
    if (!linerSurface_) return;
    const fem::Stopwatch t0;
    Eigen::VectorXd fl;
    linerSurface_->modalForce(it.linerLoad, step.linerOffset, fl);
    f.tail(fl.size()) += fl;
    work.mapping += t0.seconds();
}

void RingContact::linearize(const ContactStep& /*step*/, const ContactState& /*now*/, const Eigen::Vector2d& /*x*/,
                            const ContactIterate& /*it*/, ContactJacobian& J, WorkTally& /*work*/) {
    J = ContactJacobian{};
    J.motionColumns = true;
}

ContactState RingContact::accepted(const ContactStep& step, const ContactState& now, const ContactIterate& it) const {
    ContactState s;
    s.h = s.hRigid = s.hTotal = it.h;
    s.p = it.p;
    s.linerOffset = step.linerOffset;
    s.minGap = it.minGap;
    s.axialForce = it.action.fz;
    s.openGap = it.openGap;
    s.fraction = it.fraction;
    s.oilBalance = afterStep(now.oilBalance, it, step.dt);
    return s;
}

void RingContact::exchangeOil(const ContactState& now, const ContactState& next, const ContactIterate& it,
                              LinerOilExchange& ex) const {
    if (oil_) oil_->exchange(ex, now.linerOffset, next.linerOffset, it.inflowLow, it.inflowHigh);
}

const std::vector<std::string>& RingContact::figureNames() {
    static const std::vector<std::string> names{"min_film_m", "friction_power_mean_w", "fmep_pa",
                                                "boundary_friction_power_mean_w", "gas_below_max_pa",
                                                "gas_flow_mean_kg_per_s", "gas_flow_mean_l_per_min",
                                                "lifts_per_cycle", "gas_behind_max_pa", "face_opening_max_m",
                                                "open_to_gas_share"};
    return names;
}

const std::vector<std::string>& RingContact::blowByFigures() {
    static const std::vector<std::string> names{"blow_by.mean_kg_per_s", "blow_by.mean_l_per_min"};
    return names;
}

bool RingContact::isFigureKey(const std::string& key) {
    if (std::find(blowByFigures().begin(), blowByFigures().end(), key) != blowByFigures().end()) return true;
    const std::string prefix = "rings.";
    const auto dot = key.find('.', prefix.size());
    if (key.rfind(prefix, 0) != 0 || dot == std::string::npos || dot == prefix.size()) return false;
    const std::string figure = key.substr(dot + 1);
    return std::find(figureNames().begin(), figureNames().end(), figure) != figureNames().end();
}

std::vector<ContactColumn> RingContact::columns() const {
    const std::string column = "ring_" + ring_.name + "_", figure = "rings." + ring_.name + ".";
    const std::vector<std::string>& f = figureNames();
    std::vector<ContactColumn> all{
            {column + "min_film_m", {{figure + f[0], CycleStatistic::Minimum}}},
            {column + "friction_force_n", {}},
            {column + "friction_power_w", {{figure + f[1], CycleStatistic::Mean}, {figure + f[2], CycleStatistic::Fmep}}},
            {column + "boundary_friction_power_w", {{figure + f[3], CycleStatistic::Mean}}}};
    if (oil_) {
        all.push_back({column + "oil_left_m", {}});
        all.push_back({column + "face_open_to_gas", {{figure + f[10], CycleStatistic::Mean}}});
    }
    if (gasIndex_ >= 0) {
        all.push_back({column + "gas_below_pa", {{figure + f[4], CycleStatistic::Maximum}}});
        all.push_back({column + "gas_flow_kg_per_s", {{figure + f[5], CycleStatistic::Mean}}});
        all.push_back({column + "gas_flow_l_per_min", {{figure + f[6], CycleStatistic::Mean}}});
        if (lastInPack_)  // the gas through the last ring's gap is the blow-by
            for (std::size_t k = 0; k < 2; ++k)
                all[all.size() - 2 + k].figures.push_back({blowByFigures()[k], CycleStatistic::Mean});
        if (lift_) {
            all.push_back({column + "axial_position_m",
                           {{figure + f[7], CycleStatistic::Departures}, {figure + "lift_deg", CycleStatistic::DepartureAngles}}});
            all.push_back({column + "gas_behind_pa", {{figure + f[8], CycleStatistic::Maximum}}});
            all.push_back({column + "face_opening_m", {{figure + f[9], CycleStatistic::Maximum}}});
        }
    }
    return all;
}

void RingContact::columnValues(const ContactIterate& it, std::vector<double>& values) const {
    values.push_back(it.minGap);
    values.push_back(it.action.fz);
    values.push_back(it.loads.viscousDissipation + it.loads.boundaryFrictionPower);
    values.push_back(it.loads.boundaryFrictionPower);
    if (oil_) {
        values.push_back(it.layerLeft);
        values.push_back(it.openToGas);
    }
    if (gasIndex_ >= 0) {
        values.push_back(gas_.below + crankcasePressure_);
        values.push_back(gas_.flow);
        values.push_back(InterRingGas::litresPerMinute(gas_.flow, GasProperties{}));
        if (lift_) {
            values.push_back(gas_.position);
            values.push_back(gas_.behind + crankcasePressure_);
            values.push_back(gas_.faceOpening);
        }
    }
}

}  // namespace flexehd::cosim
