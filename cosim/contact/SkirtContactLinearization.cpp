// SkirtContact::linearize: the change of the skirt film's loads with the modal coordinates y for
// the coupled Newton method (docs/coupling.md §1, §3). With h = h_rigid(x) + Ψ y and, with
// coupling.elastic_squeeze, δḣ_j = (a0/Δt) Ψ_j, the modal column j follows from the film-change
// shape Ψ_j: δp_j from the film's linearisation with its cavitated set held
// (FilmEquation::linearize — a generalized Jacobian of the semismooth equation), δp_c,j =
// p_c'(h) Ψ_j, the load change by the gradient of the (affine in p, smooth in h) film integrals
// (lube::FilmLoadGradient), and the modal load of the mapped δp_j + δp_c,j. Each part is affine in
// the rate r = a0/Δt: δp_j = δp_j^h + r δp_j^ḣ.
#include "cosim/contact/SkirtContact.hpp"

#include "fem/Stopwatch.hpp"
#include "lube/FilmIntegrals.hpp"
#include "lube/FilmLoadGradient.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace flexehd::cosim {

void SkirtContact::filmChangeColumns(const ContactStep& step, const Eigen::Vector2d& x) {
    const lube::FilmGrid& g = film_.grid();
    const int n = g.size(), k = 2 + mp_ + ml_;
    // δh per unknown: the rigid thickness is linear in (e, β); the modal columns are Ψ (zero on
    // Void nodes; the piston's are constant and written once). Kept between calls: n × k.
    Eigen::MatrixXd& Dh = jacobianDh_;
    if (Dh.rows() != n || Dh.cols() != k) {
        Dh.resize(n, k);
        if (piston_) Dh.middleCols(2, mp_) = psiPiston_;
    }
    {
        const double reach = std::max(case_.piston.skirtTop, -case_.piston.skirtBottom);
        const Eigen::Vector2d d(1e-3 * case_.piston.clearance, 1e-3 * case_.piston.clearance / reach);
        Eigen::VectorXd h0, h1;
        film_.rigidThickness(x[0], x[1], h0);
        for (int i = 0; i < 2; ++i) {
            Eigen::Vector2d xi = x;
            xi[i] += d[i];
            film_.rigidThickness(xi[0], xi[1], h1);
            for (int r = 0; r < n; ++r) Dh(r, i) = g.kind(r) == lube::NodeKind::Void ? 0.0 : (h1[r] - h0[r]) / d[i];
        }
    }
    if (liner_ && !(psiLinerOffset_ == step.linerOffset)) {  // once per step (the offset is the step's)
        liner_->filmChangeShapes(step.linerOffset, psiLiner_);
        Dh.rightCols(ml_) = psiLiner_;
        psiLinerOffset_ = step.linerOffset;
    }
}

void SkirtContact::linearize(const ContactStep& step, const ContactState& now, const Eigen::Vector2d& x,
                             const ContactIterate& it,
                             ContactJacobian& J, WorkTally& work) {
    const lube::FilmGrid& g = film_.grid();
    const int n = g.size(), m = mp_ + ml_;
    const bool elasticRate = case_.coupling.elasticSqueeze;
    fem::Stopwatch t0;

    filmChangeColumns(step, x);
    const Eigen::MatrixXd& Dh = jacobianDh_;
    J.filmChangePerUnknown = Dh.colwise().lpNorm<Eigen::Infinity>().transpose();
    // The modal columns, and the (e, β) columns where the film's linearisation follows a rigid
    // motion as differences of full solves do (otherwise the master takes them by differences).
    // The film sees the floored thickness (no δh where the floor holds); the rate sees the
    // unfloored one, and the modes only with coupling.elastic_squeeze.
    const bool ratePart = elasticRate && !equation_->rateChangeIsZero();
    J.motionColumns = equation_->linearizationFollowsRigidMotion() && !ratePart;
    const int first = J.motionColumns ? 0 : 2, k = 2 + m - first;  // columns of Dh taken
    const auto Cols = Dh.rightCols(k);
    Eigen::MatrixXd flooredCols;
    if (it.floored > 0) {
        flooredCols = Cols;
        for (int r = 0; r < n; ++r)
            if (it.h[r] != it.hTotal[r]) flooredCols.row(r).setZero();
    }

    // δp from the film's linearisation at the iterate's solution: the thickness part and the
    // rate part (per unit a0/Δt, the master's rate) apart.
    lube::FilmState fs;
    fs.h = it.h;
    fs.dhdt = it.dhdt;
    fs.outer.axial = -step.pistonVelocity;
    const lube::Lubricant& lub = equation_->lubricant();
    equation_->linearize(step, now, it);
    const Eigen::Ref<const Eigen::MatrixXd> filmCols = [&]() -> Eigen::Ref<const Eigen::MatrixXd> {
        if (it.floored > 0) return flooredCols;
        return Cols;
    }();
    const lube::NodeColumns dPh = equation_->pressureChangeOnNodes(filmCols);
    // The rate part, where the film has one (a mass-conserving film's content term is in dPh).
    const Eigen::MatrixXd dPrate = ratePart ? equation_->rateChange(step, Dh.rightCols(m)) : Eigen::MatrixXd(n, 0);
    // Contact pressure of the unfloored h, as evaluate(): δp_c = p_c'(h) δh on the nodes in contact
    // (the load is p + p_c); its slope once per node.
    // (None where no node is in contact.)
    lube::NodeColumns dPc;
    if (contact_) {
        std::vector<std::pair<double, double>> slopes;  // (slope, rate slope) per node in contact
        for (int r = 0; r < n; ++r) {
            if (g.kind(r) == lube::NodeKind::Void) continue;
            double rateSlope = 0.0;
            const double slope = contactSlope(step, it, r, rateSlope);
            if (slope == 0.0 && rateSlope == 0.0) continue;
            dPc.nodes.push_back(r);
            slopes.emplace_back(slope, rateSlope);
        }
        dPc.values.resize(static_cast<Eigen::Index>(dPc.nodes.size()), k);
        for (std::size_t i = 0; i < dPc.nodes.size(); ++i) {
            const auto row = static_cast<Eigen::Index>(i);
            const auto [slope, rateSlope] = slopes[i];
            dPc.values.row(row) = slope * Cols.row(dPc.nodes[i]);
            // The damped hard contact's rate: of every column with the elastic squeeze, else of
            // the motion's columns only (SkirtContact::approachSpeed).
            if (rateSlope == 0.0) continue;
            if (case_.coupling.elasticSqueeze) dPc.values.row(row) += rateSlope * Cols.row(dPc.nodes[i]);
            else if (J.motionColumns) dPc.values.row(row).head(2) += rateSlope * Cols.row(dPc.nodes[i]).head(2);
        }
    }
    work.film += t0.seconds();
    t0.restart();

    // The load's gradient in (p, h, p_c) applied to all columns at once, the friction's change
    // included (at high sliding speed its moment about the pin is a large part of the motion's
    // dependence on the deformation). (The film fraction's change, mass-conserving, is held in
    // the shear.)
    lube::FilmIntegralOptions io = integralOptions();
    io.filmFraction = it.fraction.size() ? &it.fraction : nullptr;
    const lube::FilmLoadGradient G = lube::filmLoadGradient(g, fs, lub, it.p, io);
    const Eigen::MatrixXd L = G.change(dPh, filmCols, dPc);
    J.loadH = L.rightCols(m);
    J.loadRate = ratePart      ? G.change(dPrate, Eigen::MatrixXd(), Eigen::MatrixXd())
                 : elasticRate ? Eigen::MatrixXd::Zero(6, m)
                               : Eigen::MatrixXd(6, 0);

    // The modal loads of the mapped δp + δp_c, piston rows then liner rows.
    const lube::NodeColumns dLoad = lube::NodeColumns::sum(dPh, dPc);
    Eigen::MatrixXd modal(m, k);
    J.modalRate.setZero(elasticRate ? m : 0, m);
    Eigen::MatrixXd F;
    if (piston_) {
        piston_->modalForces(dLoad, n, 0.0, F);
        modal.topRows(mp_) = F;
        if (ratePart) {
            piston_->modalForces(dPrate, 0.0, F);
            J.modalRate.topRows(mp_) = F;
        }
    }
    if (liner_) {
        liner_->modalForces(dLoad, n, step.linerOffset, F);
        modal.bottomRows(ml_) = F;
        if (ratePart) {
            liner_->modalForces(dPrate, step.linerOffset, F);
            J.modalRate.bottomRows(ml_) = F;
        }
    }
    J.modalH = modal.rightCols(m);
    if (J.motionColumns) {
        J.loadX = L.leftCols(2);
        J.modalX = modal.leftCols(2);
    }
    work.modal += t0.seconds();
}

}  // namespace flexehd::cosim
