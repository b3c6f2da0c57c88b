#include "cosim/ringpack/RingContact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

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
    if (c.lubricant.supply.model == OilSupplyModel::LinerLayer) refuse("a liner oil layer (lubricant.supply)");
    if (c.linerBody.model == BodyModel::Flexible) refuse("a flexible liner (the rings' pressure on its modes)");
    return r;
}

}  // namespace

RingContact::RingContact(const EngineCase& c, const RingSpec& ring, bool top, int faceNodes)
    : ring_(supported(c, ring)),
      top_(top),
      faces_(ring.lands ? 2 : 1),
      circumference_(std::numbers::pi * c.engine.bore),
      boundaryFriction_(c.contact.boundaryFriction),
      asperity_(asperityLaw(c, ring)),
      radial_(lube::RingFilm(faceProfile(ring), lube::Lubricant(c.lubricant.viscosity, c.lubricant.density),
                             nodesAcross(ring, faceNodes),
                             c.lubricant.cavitationPressure, ring.roughness),
              asperity_, ring.tensionPerLength / faces_) {}

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
    return s;
}

const RingRadialStep& RingContact::radialStep(const ContactStep& step, double gapNow, double guess) {
    const double pressure = top_ ? step.cylinderPressure : 0.0;
    const Cached key{gapNow, step.dt, step.pistonVelocity, pressure};
    if (cachedFor_ == key) return cached_;
    lube::RingFilmState conditions;
    conditions.slidingSpeed = -step.pistonVelocity;  // the liner relative to the ring, + towards the crown
    conditions.pressureAbove = pressure;
    conditions.pressureBelow = 0.0;
    cachedFor_.reset();  // a failed step leaves no stale result behind
    cached_ = radial_.step(gapNow, step.dt, conditions, pressure, guess);
    cachedFor_ = key;
    return cached_;
}

void RingContact::evaluate(const ContactStep& step, const ContactState& now, const ContactState& before,
                           const Eigen::Vector2d& /*x*/, const Eigen::VectorXd& /*y*/, ContactIterate& it,
                           WorkTally& work) {
    const fem::Stopwatch t0;
    // The balance looked for from the last two gaps' linear extrapolation (steps of like size).
    const double guess = std::isfinite(before.minGap) ? 2.0 * now.minGap - before.minGap : now.minGap;
    const RingRadialStep& r = radialStep(step, now.minGap, guess);
    it = ContactIterate{};
    it.h = it.hRigid = it.hTotal = r.film.h;
    it.p = r.film.p;
    it.dhdt = Eigen::VectorXd::Constant(r.film.h.size(), r.squeezeRate);
    it.minGap = r.minimumGap;
    const double v = step.pistonVelocity;
    const double perFace = faces_ * circumference_;
    const double hydro = perFace * r.film.friction;
    const double boundary = -perFace * boundaryFriction_ * r.asperityLoad * (v > 0.0 ? 1.0 : v < 0.0 ? -1.0 : 0.0);
    it.loads.shearForce.z() = hydro;
    it.loads.boundaryFrictionForce.z() = boundary;
    it.loads.contactLoad = perFace * r.asperityLoad;
    it.loads.viscousDissipation = -hydro * v;
    it.loads.boundaryFrictionPower = -boundary * v;
    it.loads.minFilm = r.minimumGap;
    it.loads.maxPressure = r.film.p.size() ? r.film.p.maxCoeff() : 0.0;
    it.action.fz = hydro + boundary;
    work.film += t0.seconds();
}

void RingContact::linearize(const ContactStep& /*step*/, const ContactState& /*now*/, const Eigen::Vector2d& /*x*/,
                            const ContactIterate& /*it*/, ContactJacobian& J, WorkTally& /*work*/) {
    J = ContactJacobian{};
    J.motionColumns = true;
}

ContactState RingContact::accepted(const ContactStep& step, const ContactState& /*now*/,
                                   const ContactIterate& it) const {
    ContactState s;
    s.h = s.hRigid = s.hTotal = it.h;
    s.p = it.p;
    s.linerOffset = step.linerOffset;
    s.minGap = it.minGap;
    return s;
}

const std::vector<std::string>& RingContact::figureNames() {
    static const std::vector<std::string> names{"min_film_m", "friction_power_mean_w", "fmep_pa",
                                                "boundary_friction_power_mean_w"};
    return names;
}

bool RingContact::isFigureKey(const std::string& key) {
    const std::string prefix = "rings.";
    const auto dot = key.find('.', prefix.size());
    if (key.rfind(prefix, 0) != 0 || dot == std::string::npos || dot == prefix.size()) return false;
    const std::string figure = key.substr(dot + 1);
    return std::find(figureNames().begin(), figureNames().end(), figure) != figureNames().end();
}

std::vector<ContactColumn> RingContact::columns() const {
    const std::string column = "ring_" + ring_.name + "_", figure = "rings." + ring_.name + ".";
    const std::vector<std::string>& f = figureNames();
    return {{column + "min_film_m", {{figure + f[0], CycleStatistic::Minimum}}},
            {column + "friction_force_n", {}},
            {column + "friction_power_w", {{figure + f[1], CycleStatistic::Mean}, {figure + f[2], CycleStatistic::Fmep}}},
            {column + "boundary_friction_power_w", {{figure + f[3], CycleStatistic::Mean}}}};
}

void RingContact::columnValues(const ContactIterate& it, std::vector<double>& values) const {
    values.push_back(it.minGap);
    values.push_back(it.action.fz);
    values.push_back(it.loads.viscousDissipation + it.loads.boundaryFrictionPower);
    values.push_back(it.loads.boundaryFrictionPower);
}

}  // namespace flexehd::cosim
