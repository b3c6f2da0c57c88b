// SkirtContact: construction and one iterate of the skirt film as stages (docs/coupling.md §1,
// §4) — the film thickness (rigid motion + clearance terms + elastic change), contact pressure and
// the film floor, the film solve with its loads — and what the master asks of it besides: the
// modal load, the film change of a modal update, the state kept and the load-mapping check.
#include "cosim/contact/SkirtContact.hpp"

#include "cosim/clearance/ClearanceTerms.hpp"
#include "cosim/contact/LinerOffsetRange.hpp"
#include "cosim/contact/MassConservingFilm.hpp"
#include "cosim/contact/ReynoldsFilm.hpp"
#include "cosim/mapping/FlexibleBodyLoader.hpp"
#include "fem/Stopwatch.hpp"
#include "lube/MinimumFilmRegion.hpp"
#include "lube/ShearStressFactor.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <utility>
#include <cmath>
#include <limits>

namespace flexehd::cosim {


SkirtContact::SkirtContact(const EngineCase& c, const CaseBodies& bodies, std::function<double(double)> linerOffset)
    : case_(c),
      linerOffset_(std::move(linerOffset)),
      film_(c.engine, c.piston, c.grid) {
    if (c.lubricant.cavitation == CavitationModel::MassConserving)
        equation_ = std::make_unique<MassConservingFilm>(c, film_.grid(), linerOffset_);
    else
        equation_ = std::make_unique<ReynoldsFilm>(c, film_.grid());
    if (c.contact.compositeModulus > 0.0) {
        contact_.emplace(c.contact.sigma, c.contact.beta, c.contact.asperityDensity, c.contact.compositeModulus);
        foundation_.emplace(c.contact.hardContactStiffness > 0.0
                                ? c.contact.hardContactStiffness
                                : lube::ElasticFoundation::layerStiffness(c.contact.coatingModulus, c.contact.coatingPoisson,
                                                                          c.contact.coatingThickness),
                            c.contact.restitution);
    }
    if (bodies.piston) {
        piston_ = facingSurface(c, bodies.piston, c.pistonBody, "piston", FlexibleSurface::Side::Piston, film_.grid());
        mp_ = piston_->modes();
    }
    if (bodies.liner) {
        // The grid slides over the liner between BDC and TDC (plus a margin of two grid rows).
        const double lo = std::min(linerOffset_(180.0), linerOffset_(0.0));
        const double hi = std::max(linerOffset_(180.0), linerOffset_(0.0));
        const double margin = 2.0 * film_.grid().length() / (film_.grid().nAxial() - 1);
        liner_ = facingSurface(c, bodies.liner, c.linerBody, "liner", FlexibleSurface::Side::Liner, film_.grid(),
                                     lo + c.piston.skirtBottom - margin, hi + c.piston.skirtTop + margin);
        ml_ = liner_->modes();
    }
    if (ClearanceTerms::wanted(c)) {
        // Liner offsets the grid visits: the extremes of the crank-slider over a revolution.
        const LinerOffsetRange visited = linerOffsetRange(linerOffset_);
        clearance_ = std::make_unique<ClearanceTerms>(c, film_.grid(), visited.low, visited.high);
    }
}

SkirtContact::~SkirtContact() = default;

namespace {

// The largest film change of each shape (grid × modes): its column's largest |Ψ_ij|.
Eigen::VectorXd shapeMaxima(const Eigen::MatrixXd& Psi) { return Psi.colwise().lpNorm<Eigen::Infinity>().transpose(); }

}  // namespace

void SkirtContact::prepare(const CouplingNeeds& needs) {
    if (!piston_) return;
    Eigen::MatrixXd Psi;
    piston_->filmChangeShapes(0.0, Psi);
    pistonShapeMax_ = shapeMaxima(Psi);
    if (needs.modalJacobian) psiPiston_ = std::move(Psi);
}

ContactState SkirtContact::initialState(double linerOffset) const {
    ContactState s;
    film_.rigidThickness(0.0, 0.0, s.h);
    if (clearance_) clearance_->add(linerOffset, s.h);
    s.hRigid = s.h;
    s.hTotal = s.h;  // undeformed bodies at the start
    s.linerOffset = linerOffset;
    for (int k = 0; k < film_.grid().size(); ++k)
        if (film_.grid().kind(k) != lube::NodeKind::Void) s.minGap = std::min(s.minGap, s.hTotal[k]);
    equation_->initialize(s);
    return s;
}

void SkirtContact::evaluate(const ContactStep& step, const ContactState& now, const ContactState& before,
                            const Eigen::Vector2d& x, const Eigen::VectorXd& y, ContactIterate& it, WorkTally& work) {
    filmThickness(step, x, y, it, work);
    const fem::Stopwatch t0;
    contactAndFloor(step, now, before, it);
    solveFilm(step, now, before, it, work);
    work.film += t0.seconds();
}

void SkirtContact::filmThickness(const ContactStep& step, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                                 ContactIterate& it, WorkTally& work) {
    fem::Stopwatch t0;
    film_.rigidThickness(x[0], x[1], it.hRigid);
    if (clearance_) clearance_->add(step.linerOffset, it.hRigid);  // distortion, thermal (seed eq. 2)
    it.h = it.hRigid;
    const double rigidSeconds = t0.seconds();
    if (piston_ || liner_) {
        // Elastic Δh of y at this offset; the Jacobian's evaluations reuse the pass's (y frozen).
        t0.restart();
        if (!(elasticOffset_ == step.linerOffset && elasticY_.size() == y.size() && elasticY_ == y)) {
            if (piston_) piston_->filmChange(y.head(mp_), 0.0, pistonDh_);
            if (liner_) liner_->filmChange(y.tail(ml_), step.linerOffset, linerDh_);
            elasticY_ = y;
            elasticOffset_ = step.linerOffset;
        }
        if (piston_) it.h += pistonDh_;
        if (liner_) it.h += linerDh_;
        work.mapping += t0.seconds();
    }
    work.film += rigidSeconds;
}

void SkirtContact::contactAndFloor(const ContactStep& step, const ContactState& now, const ContactState& before,
                                   ContactIterate& it) const {
    const lube::FilmGrid& g = film_.grid();
    // Where the surfaces touch or overlap, the contact pressure of the unfloored h (asperities,
    // and the coating's hard contact below h = 0) carries the load; the Reynolds equation sees h
    // floored at a fluid film of 0.05σ (0.01 c_r without contact). Counted in `floored`; the
    // outputs show the unfloored thickness (hTotal, minGap).
    const double floor = contact_ ? 0.05 * case_.contact.sigma : 0.01 * case_.piston.clearance;
    it.hTotal = it.h;
    it.pc = Eigen::VectorXd::Zero(g.size());
    it.pcHard = Eigen::VectorXd::Zero(g.size());
    if (foundation_ && foundation_->damped()) {
        it.impactSpeed = Eigen::VectorXd::Zero(g.size());
        it.approach = Eigen::VectorXd::Zero(g.size());
    } else {
        it.impactSpeed.resize(0);
        it.approach.resize(0);
    }
    it.minGap = std::numeric_limits<double>::infinity();
    it.hardForce = 0.0;
    it.floored = 0;
    for (int k = 0; k < g.size(); ++k) {
        if (g.kind(k) == lube::NodeKind::Void) continue;
        it.minGap = std::min(it.minGap, it.h[k]);
        if (contact_) {
            double asperity = 0.0, hard = 0.0;
            contactPressure(step, now, before, k, it, asperity, hard);
            it.pc[k] = asperity + hard;
            if (hard > 0.0) {
                it.pcHard[k] = hard;
                it.hardForce -= hard * g.surfaceArea(k) * std::cos(g.theta(g.thetaIndex(k)));
            }
        }
        if (it.h[k] < floor) {
            it.h[k] = floor;
            ++it.floored;
        }
    }
}

lube::FilmIntegralOptions SkirtContact::integralOptions() const {
    lube::FilmIntegralOptions io;
    io.referencePoint = Eigen::Vector3d(case_.engine.pinOffset, 0.0, 0.0);
    io.cavitationPressure = case_.lubricant.cavitationPressure;
    io.boundaryFriction = contact_ ? case_.contact.boundaryFriction : 0.0;
    // The Couette shear between the rough surfaces (docs/lube.md §4): finite where they touch.
    io.roughness = contact_ ? case_.contact.sigma : 0.0;
    return io;
}

void SkirtContact::solveFilm(const ContactStep& step, const ContactState& now, const ContactState& before,
                             ContactIterate& it, WorkTally& work) {
    lube::FilmState fs;
    equation_->solve(step, now, before, it, fs, work);
    lube::FilmIntegralOptions io = integralOptions();
    io.contactPressure = contact_ ? &it.pc : nullptr;
    io.filmFraction = it.fraction.size() ? &it.fraction : nullptr;
    it.loads = lube::integrateFilm(film_.grid(), fs, equation_->lubricant(), it.p, io);
    const Eigen::Vector3d F = it.loads.totalForce();
    it.action = {F.x(), F.z(), it.loads.moment.y()};
}

void SkirtContact::addModalLoad(const ContactStep& step, const ContactIterate& it, Eigen::VectorXd& f,
                                WorkTally& work) const {
    const fem::Stopwatch t0;
    const Eigen::VectorXd ptot = it.p + it.pc;
    Eigen::VectorXd fb;
    if (piston_) {  // load mapping: Φᵀ A p
        piston_->modalForce(ptot, 0.0, fb);
        f.head(mp_) += fb;
    }
    if (liner_) {
        liner_->modalForce(ptot, step.linerOffset, fb);
        f.tail(ml_) += fb;
    }
    work.mapping += t0.seconds();
}

double SkirtContact::filmChange(const ContactStep& step, const Eigen::VectorXd& dy, WorkTally& work) const {
    // max |Δh| over the grid, per body.
    const fem::Stopwatch t0;
    double res = 0.0;
    Eigen::VectorXd dh;
    if (piston_) {
        piston_->filmChange(dy.head(mp_), 0.0, dh);
        res = dh.cwiseAbs().maxCoeff();
    }
    if (liner_) {
        liner_->filmChange(dy.tail(ml_), step.linerOffset, dh);
        res = std::max(res, dh.cwiseAbs().maxCoeff());
    }
    work.mapping += t0.seconds();
    return res;
}

double SkirtContact::filmChangeBound(const Eigen::VectorXd& dy) const {
    if (liner_ || (piston_ && pistonShapeMax_.size() != mp_)) return std::numeric_limits<double>::infinity();
    if (!piston_) return 0.0;
    // The products' rounding (about m · 2⁻⁵³ of the terms' sum) under a relative margin of 1e-12,
    // far below any tolerance.
    return (1.0 + 1e-12) * dy.head(mp_).cwiseAbs().dot(pistonShapeMax_);
}

Eigen::VectorXd SkirtContact::modalFilmChangeScale() const {
    // The piston's shapes are fixed to the grid; the liner's at its mid-stroke offset.
    Eigen::VectorXd s(mp_ + ml_);
    Eigen::MatrixXd Psi;
    if (piston_ && pistonShapeMax_.size() == mp_) {
        s.head(mp_) = pistonShapeMax_;  // prepared
    } else if (piston_) {
        piston_->filmChangeShapes(0.0, Psi);
        s.head(mp_) = shapeMaxima(Psi);
    }
    if (liner_) {
        liner_->filmChangeShapes(linerOffset_(90.0), Psi);
        s.tail(ml_) = shapeMaxima(Psi);
    }
    return s;
}

ContactState SkirtContact::accepted(const ContactStep& step, const ContactState& now, const ContactIterate& it) const {
    ContactState s;
    s.h = it.h;
    s.hRigid = it.hRigid;
    s.hTotal = it.hTotal;
    s.p = it.p;
    s.linerOffset = step.linerOffset;
    s.minGap = it.minGap;
    s.impactSpeed = it.impactSpeed;
    equation_->accept(step, now, it, s);
    return s;
}

LinerCover SkirtContact::linerCover(double linerOffset) const {
    const lube::FilmGrid& g = film_.grid();
    if (!panelColumns_) {  // the columns the skirt's panels reach: it covers the liner there only
        auto panels = std::make_shared<std::vector<char>>(static_cast<std::size_t>(g.nTheta()), 0);
        for (int j = 0; j < g.nTheta(); ++j) (*panels)[static_cast<std::size_t>(j)] = g.kind(g.index(0, j)) != lube::NodeKind::Void;
        panelColumns_ = std::move(panels);
    }
    return {linerOffset + g.z(0), linerOffset + g.z(g.nAxial() - 1), panelColumns_};
}

void SkirtContact::checkLoadMapping(const ContactIterate& it, double& worstDiff, double& largestForce) const {
    if (!piston_) return;
    const Eigen::Matrix<double, 6, 1> r =
        piston_->resultant(it.p + it.pc, 0.0, Eigen::Vector3d(case_.engine.pinOffset, 0.0, 0.0));
    const Eigen::Vector3d film = it.loads.pressureForce + it.loads.contactForce;
    worstDiff = std::max(worstDiff, (r.head<3>() - film).norm());
    largestForce = std::max(largestForce, film.norm());
}

double SkirtContact::approachSpeed(const ContactStep& step, const ContactState& now, const ContactState& before,
                                   const ContactIterate& it, int k) const {
    // As the Reynolds film's squeeze term (docs/coupling.md §3): the elastic rate only with
    // coupling.elastic_squeeze.
    const bool total = case_.coupling.elasticSqueeze || !(piston_ || liner_);
    const Eigen::VectorXd& h = total ? it.hTotal : it.hRigid;
    const Eigen::VectorXd& hNow = total ? now.hTotal : now.hRigid;
    double rate = step.a0 * h[k] + step.a1 * hNow[k];
    if (step.a2 != 0.0) rate += step.a2 * (total ? before.hTotal : before.hRigid)[k];
    return -rate / step.dt;
}

void SkirtContact::contactPressure(const ContactStep& step, const ContactState& now, const ContactState& before, int k,
                                   ContactIterate& it, double& asperity, double& hard) const {
    const double h = it.hTotal[k];
    asperity = contact_->pressure(std::max(h, 0.0));
    if (h >= 0.0 || !foundation_->damped()) {
        hard = foundation_->pressure(h);
        return;
    }
    // The impact speed: the largest approach speed since the node touched (docs/lube.md §4).
    const double approach = approachSpeed(step, now, before, it, k);
    const double before0 = now.impactSpeed.size() && now.hTotal[k] < 0.0 ? now.impactSpeed[k] : 0.0;
    it.impactSpeed[k] = std::max({before0, approach, lube::ElasticFoundation::kQuasiStaticSpeed});
    it.approach[k] = approach;
    hard = foundation_->pressure(h, approach, it.impactSpeed[k]);
}

double SkirtContact::contactSlope(const ContactStep& step, const ContactIterate& it, int k, double& rateSlope) const {
    rateSlope = 0.0;
    const double h = it.hTotal[k];
    if (h >= 0.0) return contact_->pressureSlope(h);
    if (!foundation_->damped() || it.impactSpeed.size() == 0) return foundation_->pressureSlope(h);
    const double held = foundation_->pressureSlope(h, it.approach[k], it.impactSpeed[k], 0.0);
    rateSlope = foundation_->pressureSlope(h, it.approach[k], it.impactSpeed[k], step.a0 / step.dt) - held;
    return held;
}

ClearanceRange SkirtContact::centredClearance(double linerOffset) const {
    const ContactState s = initialState(linerOffset);
    const lube::FilmGrid& g = film_.grid();
    ClearanceRange r{std::numeric_limits<double>::infinity(), 0.0, -std::numeric_limits<double>::infinity()};
    int n = 0;
    for (int k = 0; k < g.size(); ++k)
        if (g.kind(k) != lube::NodeKind::Void) {
            r.min = std::min(r.min, s.h[k]);
            r.max = std::max(r.max, s.h[k]);
            r.mean += s.h[k];
            ++n;
        }
    r.mean /= std::max(n, 1);
    return r;
}

bool SkirtContact::filmFigures(const ContactIterate& it, FilmFigures& r) const {
    const lube::FilmLoads& l = it.loads;
    r.filmForce = l.pressureForce.x() + l.shearForce.x() + l.boundaryFrictionForce.x();
    r.filmMoment = l.moment.y();
    r.contactForce = l.contactForce.x();
    r.hardContactForce = it.hardForce;
    r.frictionForce = l.frictionForce().z();
    r.linerHydrodynamicFriction = l.outerShearForce.z();
    r.linerBoundaryFriction = -l.boundaryFrictionForce.z();
    r.dissipatedPower = l.dissipatedPower();
    r.boundaryFrictionPower = l.boundaryFrictionPower;
    r.minFilm = it.minGap;  // unfloored: < 0 where the surfaces overlap
    r.maxPressure = it.p.size() ? it.p.maxCoeff() : 0.0;
    const lube::FilmGrid& g = film_.grid();
    // The band of the thinnest film's region: h < 2 h_min in a full film, the roughness where the
    // asperities carry the load (their pressure changes over about σ).
    const double band = std::max({it.minGap, case_.contact.sigma, 1e-3 * case_.piston.clearance});
    const lube::MinimumFilmSpan span = lube::minimumFilmSpan(g, it.hTotal, band);
    r.minFilmNodesCircumferential = span.circumferential;
    r.minFilmNodesAxial = span.axial;
    r.minFilmAtAxialEdge = span.atAxialEdge;
    if (mp_ + ml_ > 0)
        for (int k = 0; k < g.size(); ++k)
            if (g.kind(k) != lube::NodeKind::Void)
                r.elasticFilmChange = std::max(r.elasticFilmChange, std::abs(it.hTotal[k] - it.hRigid[k]));
    if (it.fraction.size()) {  // the mass-conserving film's wetted share
        double wet = 0.0, area = 0.0;
        for (int k = 0; k < g.size(); ++k) {
            if (g.kind(k) != lube::NodeKind::Film) continue;
            area += g.area(k);
            if (it.fraction[k] >= 1.0) wet += g.area(k);
        }
        r.wettedShare = area > 0.0 ? wet / area : 0.0;
    }
    return true;
}

bool SkirtContact::filmFields(const ContactIterate& it, double pistonVelocity, FilmFields& sn) const {
    const lube::FilmGrid& g = film_.grid();
    sn.pressure = it.p;
    sn.filmThickness = it.hTotal;  // unfloored: < 0 where the surfaces overlap
    sn.contactPressure = it.pc;
    sn.cavitation = Eigen::VectorXd::Zero(g.size());
    sn.shearStress = Eigen::VectorXd::Zero(g.size());
    const double eta = lubricant().referenceViscosity();
    const lube::ShearStressFactor shearFactor(integralOptions().roughness);
    for (int k = 0; k < g.size(); ++k) {
        if (g.kind(k) == lube::NodeKind::Void) continue;
        if (it.fraction.size())  // mass-conserving: the film fraction's complement
            sn.cavitation[k] = g.kind(k) == lube::NodeKind::Film ? 1.0 - it.fraction[k] : 0.0;
        else if (g.kind(k) == lube::NodeKind::Film && it.p[k] <= case_.lubricant.cavitationPressure)
            sn.cavitation[k] = 1.0;
        // τ_z on the piston = η (V_liner − V_piston)/h − (h/2) ∂p/∂z (central differences).
        const int i = g.axialIndex(k), j = g.thetaIndex(k);
        const int i0 = std::max(0, i - 1), i1 = std::min(g.nAxial() - 1, i + 1);
        const double dpdz = (it.p[g.index(i1, j)] - it.p[g.index(i0, j)]) / (g.z(i1) - g.z(i0));
        // Couette shear on the oil only: φ, or none where the Reynolds condition cavitates.
        const double phi = it.fraction.size() ? 1.0 - sn.cavitation[k] : (sn.cavitation[k] > 0.0 ? 0.0 : 1.0);
        double c, dcdh;
        shearFactor.couette(it.h[k], c, dcdh);
        sn.shearStress[k] = phi * eta * (-pistonVelocity) * c - 0.5 * it.h[k] * dpdz;
    }
    sn.filmFraction = it.fraction;
    return true;
}

std::vector<std::string> SkirtContact::startReport() const {
    if (!clearance_) return {};
    std::string line = "centred clearance (min / mean / max over the skirt):";
    for (const auto& [name, deg] : {std::pair{"TDC", 0.0}, {"mid-stroke", 90.0}, {"BDC", 180.0}}) {
        const ClearanceRange r = centredClearance(linerOffset_(deg));
        line += fmt::format(" {} {:.1f} / {:.1f} / {:.1f} um{}", name, r.min * 1e6, r.mean * 1e6, r.max * 1e6,
                            deg < 180.0 ? ";" : "");
    }
    return {"film thickness: " + clearance_->summary(), line};
}

}  // namespace flexehd::cosim
