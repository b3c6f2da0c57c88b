#include "lube/JfoLinearization.hpp"

#include <algorithm>
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

    // The partition of the solution (the active set's, settled) and the rows δp depends on.
    const std::vector<char> cavitated = partition(net, g, p, phi);
    sys_ = dependentRows(net, g, cavitated);
    if (sys_.empty()) {  // no full film: no pressure to change
        dFdh_.resize(0, 0);
        return;
    }
    JfoActiveSetSystem sys(net, g, sys_, p, phi);
    sysCav_.resize(sys_.size());
    for (std::size_t r = 0; r < sys_.size(); ++r) sysCav_[r] = cavitated[static_cast<std::size_t>(sys_[r])];
    Eigen::VectorXd rhs;
    sys.setPartition(sysCav_, pcav, rhs);
    if (!lu_->factor(sys.matrix()))
        throw std::runtime_error("JfoLinearization: the film's balances on its full-film / cavitated partition are "
                                 "singular (a cavity with no supply?)");

    // ∂F/∂h of those rows by colour (ColouredDifference).
    const bool flux = inlets_ == InletResponse::FluxHeldWherePartial;
    const Eigen::VectorXd F0 = balances(net, g, sys_, p, phi, flux);
    const Eigen::SparseMatrix<double> dFdh = colouredThicknessDerivative(g, colouring_, film, sys_, F0, [&](const FilmState& fc) {
        const JfoNetwork nc(topo, g, fc, eta, dt, previous, inlet, pcav);
        return balances(nc, g, sys_, p, phi, flux);
    });
    keepReachedColumns(dFdh);
}

void JfoLinearization::keepReachedColumns(const Eigen::SparseMatrix<double>& dFdh) {
    // Only the nodes next to the system's rows enter ∂F/∂h: its columns there, numbered anew.
    dFdhNodes_.clear();
    std::vector<int> column(static_cast<std::size_t>(dFdh.cols()), -1);
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(static_cast<std::size_t>(dFdh.nonZeros()));
    for (Eigen::Index c = 0; c < dFdh.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator e(dFdh, c); e; ++e) {
            const auto node = static_cast<std::size_t>(e.col());
            if (column[node] < 0) column[node] = static_cast<int>(dFdhNodes_.size()), dFdhNodes_.push_back(e.col());
            entries.emplace_back(e.row(), column[node], e.value());
        }
    dFdh_.resize(dFdh.rows(), static_cast<Eigen::Index>(dFdhNodes_.size()));
    dFdh_.setFromTriplets(entries.begin(), entries.end());
}

std::vector<char> JfoLinearization::partition(const JfoNetwork& net, const FilmGrid& g, const double* p,
                                              const double* phi) {
    std::vector<char> cavitated(static_cast<std::size_t>(g.size()), 0);
    cavitated_ = 0;
    for (int k : rows_) {
        // The active set's rule: cavitated where the film is partial and a Couette outflow or the
        // storage term can carry it (B > 0).
        const JfoNetwork::Balance bl = net.balance(k, p, phi);
        const bool cav = bl.B > 0.0 && phi[k] < 1.0;
        cavitated[static_cast<std::size_t>(k)] = cav;
        cavitated_ += cav;
    }
    return cavitated;
}

std::vector<int> JfoLinearization::dependentRows(const JfoNetwork& net, const FilmGrid& g,
                                                 const std::vector<char>& cavitated) const {
    // The full-film rows and, transitively, the rows their system's entries reach: a full-film
    // neighbour's pressure (Poiseuille), a cavitated neighbour's film fraction where its Couette
    // flow comes in (upstream). No other row enters these, so their part of M δy = −(∂F/∂h) δh is
    // a system of its own (docs/lube.md §3b, "Linearisation").
    std::vector<char> in(static_cast<std::size_t>(g.size()), 0);
    std::vector<int> rows;
    for (int k : rows_)
        if (!cavitated[static_cast<std::size_t>(k)]) in[static_cast<std::size_t>(k)] = 1, rows.push_back(k);
    for (std::size_t i = 0; i < rows.size(); ++i)
        net.forFaces(rows[i], [&](int m, double, double qo) {
            const auto sm = static_cast<std::size_t>(m);
            if (g.kind(m) != NodeKind::Film || in[sm]) return;
            if (!cavitated[sm] || qo < 0.0) in[sm] = 1, rows.push_back(m);
        });
    std::sort(rows.begin(), rows.end());
    return rows;
}

Eigen::MatrixXd JfoLinearization::pressureChange(const Eigen::Ref<const Eigen::MatrixXd>& dh) const {
    return pressureChangeOnNodes(dh).dense(solver_->grid().size());
}

NodeColumns JfoLinearization::pressureChangeOnNodes(const Eigen::Ref<const Eigen::MatrixXd>& dh) const {
    const int n = solver_->grid().size();
    if (dh.rows() != n)
        throw std::invalid_argument("JfoLinearization::pressureChange: columns of " + std::to_string(n) +
                                    " nodes expected, got " + std::to_string(dh.rows()));
    NodeColumns out;
    out.values.resize(0, dh.cols());
    if (sys_.empty() || dFdh_.rows() == 0) return out;
    // −(∂F/∂h) δh over the nodes ∂F/∂h reaches, then all columns in one pass over the factors.
    Eigen::MatrixXd dhReached(static_cast<Eigen::Index>(dFdhNodes_.size()), dh.cols());
    for (Eigen::Index c = 0; c < dh.cols(); ++c)  // column by column: dh is column-major
        for (std::size_t i = 0; i < dFdhNodes_.size(); ++i) dhReached(static_cast<Eigen::Index>(i), c) = dh(dFdhNodes_[i], c);
    Eigen::MatrixXd dy = -(dFdh_ * dhReached);
    lu_->solveInPlace(dy);
    for (std::size_t r = 0; r < sys_.size(); ++r)
        if (!sysCav_[r]) out.nodes.push_back(sys_[r]);
    out.values.resize(static_cast<Eigen::Index>(out.nodes.size()), dh.cols());
    for (Eigen::Index c = 0; c < dh.cols(); ++c) {
        Eigen::Index i = 0;
        for (std::size_t r = 0; r < sys_.size(); ++r)
            if (!sysCav_[r]) out.values(i++, c) = dy(static_cast<Eigen::Index>(r), c);
    }
    return out;
}

}  // namespace flexehd::lube
