#include "lube/JfoLinearization.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "lube/ColouredDifference.hpp"
#include "lube/JfoNetwork.hpp"
#include "lube/SparseLuFactor.hpp"

namespace flexehd::lube {

namespace {

// The balance F_k = D p_k − S + B φ_k − Sin of each row at (p, φ); with partialInletFlux, the
// Couette inflow from an inlet of fraction below 1 is left out (a given flux: constant in h).
Eigen::VectorXd balances(const JfoNetwork& net, const FilmGrid& g, const std::vector<int>& rows, const double* p,
                         const double* phi, bool partialInletFlux) {
    Eigen::VectorXd F(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const int k = rows[r];
        const JfoNetwork::Balance bl = net.balance(k, p, phi);
        double given = 0.0;
        if (partialInletFlux)
            net.forFaces(k, [&](int m, double, double qo) {
                if (qo < 0.0 && g.kind(m) != NodeKind::Film && net.inlet(m) < 1.0) given -= qo * net.inlet(m);
            });
        F[static_cast<Eigen::Index>(r)] = bl.D * p[k] - bl.S + bl.B * phi[k] - (bl.Sin - given);
    }
    return F;
}

}  // namespace

JfoLinearization::JfoLinearization(const JfoSolver& solver, InletResponse inlets)
    : solver_(&solver), inlets_(inlets), colouring_(distanceTwoColouring(solver.grid())), lu_(std::make_unique<SparseLuFactor>()) {
    const FilmGrid& g = solver.grid();
    for (int k = 0; k < g.size(); ++k)
        if (g.kind(k) == NodeKind::Film) rows_.push_back(k);
}

JfoLinearization::~JfoLinearization() = default;
JfoLinearization::JfoLinearization(JfoLinearization&&) noexcept = default;

void JfoLinearization::linearize(const FilmState& film, double dt, const JfoState* previous,
                                 const JfoResult& solution) {
    const FilmGrid& g = solver_->grid();
    const int n = g.size();
    if (film.h.size() != n || solution.pressure.size() != n || solution.fraction.size() != n)
        throw std::invalid_argument("JfoLinearization: thickness, pressure and film fraction need " +
                                    std::to_string(n) + " values (the grid's nodes)");
    if (dt > 0.0 && (!previous || previous->h.size() != n || previous->fraction.size() != n))
        throw std::invalid_argument("JfoLinearization: a transient step needs the previous h and film fraction");
    const double eta = solver_->lubricant().referenceViscosity(), pcav = solver_->options().cavitationPressure;
    const JfoTopology& topo = solver_->topology();
    const std::vector<double>& inlet = solver_->inletFractions();
    const double* p = solution.pressure.data();
    const double* phi = solution.fraction.data();
    const JfoNetwork net(topo, g, film, eta, dt, previous, inlet, pcav);

    // The partition of the solution and its system M (the active set's, settled).
    JfoActiveSetSystem sys(net, g, rows_, p);
    const int nf = sys.size();
    cavRow_.assign(static_cast<std::size_t>(nf), 0);
    cavitated_ = 0;
    for (int r = 0; r < nf; ++r) {
        const bool cav = sys.B(r) > 0.0 && phi[rows_[static_cast<std::size_t>(r)]] < 1.0;
        cavRow_[static_cast<std::size_t>(r)] = cav;
        cavitated_ += cav;
    }
    Eigen::VectorXd rhs;
    sys.setPartition(cavRow_, pcav, rhs);
    if (!lu_->factor(sys.matrix()))
        throw std::runtime_error("JfoLinearization: the film's balances on its full-film / cavitated partition are "
                                 "singular (a cavity with no supply?)");

    // ∂F/∂h by colour (ColouredDifference).
    const bool flux = inlets_ == InletResponse::FluxHeldWherePartial;
    const Eigen::VectorXd F0 = balances(net, g, rows_, p, phi, flux);
    dFdh_ = colouredThicknessDerivative(g, colouring_, film, rows_, F0, [&](const FilmState& fc) {
        const JfoNetwork nc(topo, g, fc, eta, dt, previous, inlet, pcav);
        return balances(nc, g, rows_, p, phi, flux);
    });
}

Eigen::MatrixXd JfoLinearization::pressureChange(const Eigen::MatrixXd& dh) const {
    const int n = solver_->grid().size();
    if (dh.rows() != n)
        throw std::invalid_argument("JfoLinearization::pressureChange: columns of " + std::to_string(n) +
                                    " nodes expected, got " + std::to_string(dh.rows()));
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, dh.cols());
    if (rows_.empty() || dFdh_.rows() == 0) return out;
    const Eigen::MatrixXd rhs = -(dFdh_ * dh);
    for (Eigen::Index c = 0; c < dh.cols(); ++c) {
        const Eigen::VectorXd dy = lu_->solve(rhs.col(c));
        for (std::size_t r = 0; r < rows_.size(); ++r)
            if (!cavRow_[r]) out(rows_[r], c) = dy[static_cast<Eigen::Index>(r)];
    }
    return out;
}

}  // namespace flexehd::lube
