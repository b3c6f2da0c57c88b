// MassConservingFilm: the mass-conserving film of a contact at an iterate, its edge flows and the
// liner oil it leaves (docs/coupling.md §6).
#include "cosim/contact/MassConservingFilm.hpp"

#include "cosim/contact/LinerOffsetRange.hpp"

#include "cosim/contact/ReynoldsFilm.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace flexehd::cosim {

namespace {

lube::JfoOptions jfoOptions(const LubricantSpec& l) {
    lube::JfoOptions o;
    o.method = lube::JfoMethod::Multigrid;
    o.cavitationPressure = l.cavitationPressure;
    o.control.tolerance = MassConservingFilm::kTolerance;
    o.control.maxIterations = 20000;
    return o;
}

// The liner-frame z range the skirt's edges sweep over a revolution.
void skirtReach(const lube::FilmGrid& g, const std::function<double(double)>& linerOffset, double& lo, double& hi) {
    const LinerOffsetRange r = linerOffsetRange(linerOffset);
    lo = r.low + g.z(0);
    hi = r.high + g.z(g.nAxial() - 1);
}

}  // namespace

MassConservingFilm::MassConservingFilm(const EngineCase& c, const lube::FilmGrid& grid,
                                       const std::function<double(double)>& linerOffset)
    : grid_(grid), lubricant_(makeLubricant(c.lubricant)), solver_(grid, lubricant_, jfoOptions(c.lubricant)),
      inlet_(static_cast<std::size_t>(grid.size()), 1.0) {
    const OilSupplySpec& sp = c.lubricant.supply;
    if (sp.model == OilSupplyModel::LinerLayer) {
        double lo = 0.0, hi = 0.0;
        skirtReach(grid, linerOffset, lo, hi);
        exchange_ = std::make_unique<SkirtOilExchange>(grid, sp, lo, hi);
    }
}

std::optional<LinerFootprint> MassConservingFilm::linerFootprint() const {
    if (!exchange_) return std::nullopt;
    return exchange_->footprint();
}

void MassConservingFilm::initialize(ContactState& s) const {
    if (exchange_) {
        s.fraction = exchange_->initialFraction(s.h, s.linerOffset);
    } else {
        s.fraction = Eigen::VectorXd::Ones(grid_.size());
    }
}

void MassConservingFilm::setInlets(const ContactStep& step, const ContactState& now, const Eigen::VectorXd& h) {
    if (!exchange_) return;
    if (!step.oil || !step.oil->layer)
        throw std::logic_error("MassConservingFilm: the step carries no liner oil layer for a liner_layer supply");
    exchange_->inletFractions(*step.oil->layer, step.oil->covers, now.linerOffset, step.linerOffset, step.dt,
                              -step.pistonVelocity, h, inlet_);
    for (int j = 0; j < grid_.nTheta(); ++j)
        for (int i : {0, grid_.nAxial() - 1}) {
            const int k = grid_.index(i, j);
            if (grid_.kind(k) == lube::NodeKind::Fixed) solver_.setInletFraction(k, inlet_[static_cast<std::size_t>(k)]);
        }
}

void MassConservingFilm::solve(const ContactStep& step, const ContactState& now, const ContactState&,
                               ContactIterate& it, lube::FilmState& fs, WorkTally& work) {
    it.dhdt = (it.h - now.h) / step.dt;  // the rate the backward-Euler content term sees
    fs.h = it.h;
    fs.dhdt.resize(0);                   // the transient term is the solver's (film content)
    fs.inner = {};
    fs.outer = {};
    fs.outer.axial = -step.pistonVelocity;
    setInlets(step, now, it.h);
    const lube::JfoState previous{now.h, now.fraction};
    // The warm start (the active set's first partition): the last solve's, of this step's
    // iterates or the previous step's; else the last accepted state's.
    if (warm_.pressure.size() != grid_.size() && now.p.size() == grid_.size()) {
        warm_.pressure = now.p;
        warm_.fraction = now.fraction;
    }
    const bool haveWarm = warm_.pressure.size() == grid_.size();
    lube::JfoResult r = solver_.solve(fs, step.dt, &previous, haveWarm ? &warm_ : nullptr);
    warm_.pressure = r.pressure;
    warm_.fraction = r.fraction;
    ++work.filmSolves;
    edgeFlows(r, it);
    it.oilVolume = solver_.oilVolume(fs, r.fraction);
    it.p = std::move(r.pressure);
    it.fraction = std::move(r.fraction);
}

void MassConservingFilm::edgeFlows(const lube::JfoResult& r, ContactIterate& it) const {
    const Eigen::VectorXd& q = r.boundaryFlow;
    const int nt = grid_.nTheta(), last = grid_.nAxial() - 1;
    it.inflowLow = Eigen::VectorXd::Zero(nt);
    it.inflowHigh = Eigen::VectorXd::Zero(nt);
    double edges = 0.0;
    for (int j = 0; j < nt; ++j) {
        it.inflowLow[j] = q[grid_.index(0, j)];
        it.inflowHigh[j] = q[grid_.index(last, j)];
        edges += it.inflowLow[j] + it.inflowHigh[j];
    }
    it.sideInflow = q.sum() - edges;
}

void MassConservingFilm::accept(const ContactStep& step, const ContactState& now, const ContactIterate& it,
                                ContactState& s) const {
    s.fraction = it.fraction;
    s.oilBalance = afterStep(now.oilBalance, it, step.dt);
}

void MassConservingFilm::exchangeOil(const ContactState& now, const ContactState& next, const ContactIterate& it,
                                     LinerOilExchange& ex) const {
    if (exchange_) exchange_->exchange(ex, now.linerOffset, next.linerOffset, it.inflowLow, it.inflowHigh);
}

void MassConservingFilm::linearize(const ContactStep& step, const ContactState& now, const ContactIterate& it) {
    // The liner layer's inlets bring a given volume per step (SkirtOilExchange): their flux is held.
    if (!linearization_)
        linearization_ = std::make_unique<lube::JfoLinearization>(
            solver_, exchange_ ? lube::InletResponse::FluxHeldWherePartial : lube::InletResponse::FractionHeld);
    setInlets(step, now, it.h);  // the iterate's (another iterate may have been solved since)
    lube::FilmState fs;
    fs.h = it.h;
    fs.outer.axial = -step.pistonVelocity;
    const lube::JfoState previous{now.h, now.fraction};
    lube::JfoResult solution;
    solution.pressure = it.p;
    solution.fraction = it.fraction;
    linearization_->linearize(fs, step.dt, &previous, solution);
}

Eigen::MatrixXd MassConservingFilm::pressureChange(const Eigen::Ref<const Eigen::MatrixXd>& dh) const {
    return linearization_->pressureChange(dh);
}

lube::NodeColumns MassConservingFilm::pressureChangeOnNodes(const Eigen::Ref<const Eigen::MatrixXd>& dh) const {
    return linearization_->pressureChangeOnNodes(dh);
}

Eigen::MatrixXd MassConservingFilm::rateChange(const ContactStep&, const Eigen::MatrixXd& dhs) const {
    return Eigen::MatrixXd::Zero(dhs.rows(), dhs.cols());
}

}  // namespace flexehd::cosim
