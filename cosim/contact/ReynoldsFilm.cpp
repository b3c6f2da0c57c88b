// ReynoldsFilm: the Reynolds-condition film of a contact at an iterate (docs/coupling.md §3).
#include "cosim/contact/ReynoldsFilm.hpp"

namespace flexehd::cosim {

namespace {

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

}  // namespace

lube::Lubricant makeLubricant(const LubricantSpec& l) {
    lube::Lubricant lub(l.viscosity, l.density);
    if (l.barusAlpha > 0.0) lub.withBarus(l.barusAlpha);
    return lub;
}

ReynoldsFilm::ReynoldsFilm(const EngineCase& c, const lube::FilmGrid& grid)
    : elasticSqueeze_(c.coupling.elasticSqueeze),
      solver_(grid, makeLubricant(c.lubricant), filmSolverOptions(c.lubricant)),
      cavitationPressure_(c.lubricant.cavitationPressure) {}

void ReynoldsFilm::solve(const ContactStep& step, const ContactState& now, const ContactState& before,
                         ContactIterate& it, lube::FilmState& fs, WorkTally& work) {
    // Squeeze term: BDF2 of the whole (unfloored) film thickness with coupling.elastic_squeeze,
    // else of the rigid film thickness only (docs/coupling.md §3: with the elastic rate the
    // partitioned coupling has a gain ∝ 1/Δt and does not converge; it needs the Newton method).
    if (elasticSqueeze_)
        it.dhdt = (step.a0 * it.hTotal + step.a1 * now.hTotal + step.a2 * before.hTotal) / step.dt;
    else
        it.dhdt = (step.a0 * it.hRigid + step.a1 * now.hRigid + step.a2 * before.hRigid) / step.dt;
    fs.h = it.h;
    fs.dhdt = it.dhdt;
    fs.inner = {};
    fs.outer = {};
    fs.outer.axial = -step.pistonVelocity;  // the liner slides past the piston-fixed grid
    const Eigen::VectorXd* warm = now.p.size() == it.h.size() ? &now.p : nullptr;
    lube::ReynoldsResult solved = solver_.solve(fs, warm);
    it.p = std::move(solved.pressure);
    if (solved.fellBack) ++work.fallbackSolves;
    ++work.filmSolves;
}

void ReynoldsFilm::linearize(const ContactStep& step, const ContactState&, const ContactIterate& it) {
    const lube::FilmGrid& g = solver_.grid();
    if (!linearization_) linearization_ = std::make_unique<lube::FilmLinearization>(g);
    lube::FilmState fs;
    fs.h = it.h;
    fs.dhdt = it.dhdt;
    fs.outer.axial = -step.pistonVelocity;
    const lube::Lubricant& lub = solver_.lubricant();
    const int n = g.size();
    Eigen::VectorXd rho(n), eta(n);
    for (int r = 0; r < n; ++r) {
        rho[r] = lub.density(it.p[r]);
        eta[r] = lub.viscosity(it.p[r]);
    }
    linearization_->linearize(fs, rho, eta, it.p, cavitationPressure_);
}

Eigen::MatrixXd ReynoldsFilm::pressureChange(const Eigen::Ref<const Eigen::MatrixXd>& dh) const {
    return linearization_->pressureChange(dh, Eigen::MatrixXd());
}

Eigen::MatrixXd ReynoldsFilm::rateChange(const ContactStep&, const Eigen::MatrixXd& dhs) const {
    // The squeeze term is the BDF2 rate: ∂ḣ/∂h_s = a0/Δt, the master's rate.
    return linearization_->pressureChange(Eigen::MatrixXd(), dhs, 1.0);
}

}  // namespace flexehd::cosim
