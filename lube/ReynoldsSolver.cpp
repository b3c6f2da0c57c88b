#include "lube/ReynoldsSolver.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <limits>
#include <stdexcept>
#include <string>

namespace flexehd::lube {

namespace {

// Bilinear prolongation from a grid built by FilmGrid::coarsened to its parent.
Eigen::VectorXd prolong(const Eigen::VectorXd& pc, const FilmGrid& coarse, const FilmGrid& fine,
                        const std::vector<int>& axialMap) {
    Eigen::VectorXd pf(fine.size());
    const int ntc = coarse.nTheta(), ntf = fine.nTheta();
    std::size_t I = 0;
    for (int i = 0; i < fine.nAxial(); ++i) {
        while (I + 2 < axialMap.size() && axialMap[I + 1] <= i) ++I;
        const int i0 = axialMap[I], i1 = axialMap[I + 1];
        const double wz = (fine.z(i) - fine.z(i0)) / (fine.z(i1) - fine.z(i0));
        const double* c0 = pc.data() + coarse.index(static_cast<int>(I), 0);  // rows I, I + 1
        const double* c1 = pc.data() + coarse.index(static_cast<int>(I) + 1, 0);
        double* out = pf.data() + fine.index(i, 0);
        for (int j = 0; j < ntf; ++j) {
            const int J0 = j / 2, J1 = (j % 2 == 0) ? J0 : (J0 + 1 == ntc ? 0 : J0 + 1);
            const double lo = 0.5 * (c0[J0] + c0[J1]);
            const double hi = 0.5 * (c1[J0] + c1[J1]);
            out[j] = (1 - wz) * lo + wz * hi;
        }
    }
    return pf;
}

FilmState inject(const FilmState& f, const FilmGrid& coarse, const FilmGrid& fine,
                 const std::vector<int>& axialMap) {
    FilmState c;
    c.inner = f.inner;
    c.outer = f.outer;
    c.h.resize(coarse.size());
    if (f.dhdt.size()) c.dhdt.resize(coarse.size());
    for (int I = 0; I < coarse.nAxial(); ++I)
        for (int J = 0; J < coarse.nTheta(); ++J) {
            const int kf = fine.index(axialMap[static_cast<std::size_t>(I)], 2 * J);
            c.h[coarse.index(I, J)] = f.h[kf];
            if (f.dhdt.size()) c.dhdt[coarse.index(I, J)] = f.dhdt[kf];
        }
    return c;
}

// Half-Sommerfeld: the Film nodes' pressures below p_cav set to p_cav.
void clipBelow(const FilmGrid& g, double pcav, Eigen::VectorXd& p) {
    for (int k = 0; k < g.size(); ++k)
        if (g.kind(k) == NodeKind::Film && p[k] < pcav) p[k] = pcav;
}

}  // namespace

ReynoldsSolver::ReynoldsSolver(FilmGrid grid, Lubricant lubricant, ReynoldsOptions options)
    : grid_(std::move(grid)), lubricant_(lubricant), options_(options),
      psor_(options.omega) {
    if (!std::isfinite(options_.cavitationPressure))
        throw std::invalid_argument("ReynoldsSolver: cavitationPressure must be finite");
    if (!(options_.control.tolerance > 0.0))
        throw std::invalid_argument("ReynoldsSolver: tolerance must be positive");
    if (options_.control.maxIterations < 1 || options_.maxPicardIterations < 1)
        throw std::invalid_argument("ReynoldsSolver: iteration limits must be >= 1");
    if (!(options_.picardRelaxation > 0.0 && options_.picardRelaxation <= 1.0))
        throw std::invalid_argument("ReynoldsSolver: picardRelaxation must be in (0, 1]");
    if (grid_.filmNodeCount() == 0)
        throw std::invalid_argument("ReynoldsSolver: the grid has no Film node (all pressures "
                                    "prescribed); refine it or change the edge conditions");
    if (options_.gridSequencing && options_.solver != SolverKind::Psor &&
        options_.cavitation == Cavitation::Reynolds) {
        const FilmGrid* g = &grid_;
        std::vector<int> map;
        while (g->size() > 2000) {
            std::optional<FilmGrid> c = g->coarsened(map);
            if (!c || c->filmNodeCount() == 0) break;
            coarse_.push_back(Level{std::move(*c), map, ActiveSetSolver(), MultigridSolver()});
            g = &coarse_.back().grid;
        }
    }
    if (options_.fallback && *options_.fallback != options_.solver) {
        ReynoldsOptions f = options_;
        f.solver = *options_.fallback;
        f.fallback.reset();
        f.control.maxIterations = SolverControl{}.maxIterations;  // the solver of last resort
        fallback_ = std::make_unique<ReynoldsSolver>(grid_, lubricant_, f);
    }
}

Eigen::VectorXd ReynoldsSolver::sequencedStart(const FilmState& film, int& coarseIterations) {
    const int L = static_cast<int>(coarse_.size());
    if (L == 0) return {};
    auto gridAt = [&](int l) -> const FilmGrid& { return l == 0 ? grid_ : coarse_[static_cast<std::size_t>(l - 1)].grid; };
    // states[l − 1]: the film on coarse grid l, injected level by level (the fine film is not
    // copied: it is 16 bytes per fine node of fresh memory).
    std::vector<FilmState> states;
    states.reserve(static_cast<std::size_t>(L));
    for (int l = 1; l <= L; ++l)
        states.push_back(inject(l == 1 ? film : states.back(), gridAt(l), gridAt(l - 1),
                                coarse_[static_cast<std::size_t>(l - 1)].axialMap));
    // Multigrid: the coarse grids are levels of the fine grid's hierarchy, solved with it (one
    // hierarchy, one set of work arrays; a separate solver per grid only if they differ).
    if (options_.solver == SolverKind::Multigrid) multigrid_.prepare(grid_);
    Eigen::VectorXd p;
    try {
        for (int l = L; l >= 1; --l) {
            const FilmGrid& g = gridAt(l);
            const ReynoldsSystem sys(g, states[static_cast<std::size_t>(l - 1)],
                                     lubricant_.referenceDensity(), lubricant_.referenceViscosity());
            Level& lev = coarse_[static_cast<std::size_t>(l - 1)];
            // Nested iteration: a coarse answer is only a start. Residual 1e-3 with at least one
            // iteration per grid: the prolonged start of the next finer grid has a residual of
            // 1e-4 … 2e-3 anyway (the coarse-to-fine discretisation difference), so a tighter
            // coarse solve buys no fine iteration; the one iteration smooths a prolonged start
            // that already meets 1e-3 (without it the fine grid needs a fourth iteration).
            SolverControl coarseControl = options_.control;
            coarseControl.tolerance = std::max(coarseControl.tolerance, 1e-3);
            coarseControl.minIterations = std::max(coarseControl.minIterations, 1);
            MultigridSolver& mg = multigrid_.hasLevel(g) ? multigrid_ : lev.multigrid;
            const SolveReport rep =
                options_.solver == SolverKind::Multigrid
                    ? mg.solve(sys, p, options_.cavitationPressure, coarseControl)
                    : lev.solver.solve(sys, p, options_.cavitationPressure, options_.control);
            coarseIterations += rep.iterations;
            p = prolong(p, g, gridAt(l - 1), coarse_[static_cast<std::size_t>(l - 1)].axialMap);
        }
    } catch (const std::exception&) {
        return {};  // e.g. a coarse grid lost the only pressure datum: start cold instead
    }
    return p;
}

ReynoldsResult ReynoldsSolver::resolve(const Eigen::VectorXd& dhdt, const Eigen::VectorXd& warmStart) {
    if (lastFellBack_) {  // the primary solver has no system of that film: the fallback's
        ReynoldsResult r = fallback_->resolve(dhdt, warmStart);
        r.fellBack = true;
        return r;
    }
    if (!last_)
        throw std::logic_error("ReynoldsSolver::resolve: no system of a constant-property solve to reuse");
    if (warmStart.size() != grid_.size())
        throw std::invalid_argument("ReynoldsSolver::resolve: warm start has " + std::to_string(warmStart.size()) +
                                    " values, grid has " + std::to_string(grid_.size()));
    last_->setSqueezeRate(dhdt);
    ReynoldsResult res;
    res.pressure = warmStart;
    res.picardIterations = 1;
    SolveReport rep;
    try {
        rep = options_.solver == SolverKind::Multigrid
                  ? multigrid_.resolve(*last_, res.pressure, lowerBound(), options_.control)
                  : solveOnce(*last_, res.pressure);
    } catch (const std::runtime_error&) {
        if (!fallback_) throw;
        res.pressure = warmStart;
        rep = fallback_->solveOnce(*last_, res.pressure);
        res.fellBack = true;
    }
    res.iterations = rep.iterations;
    res.residual = rep.residual;
    if (options_.cavitation == Cavitation::HalfSommerfeld) clipBelow(grid_, options_.cavitationPressure, res.pressure);
    return res;
}

double ReynoldsSolver::lowerBound() const {
    return options_.cavitation == Cavitation::Reynolds ? options_.cavitationPressure
                                                       : -std::numeric_limits<double>::infinity();
}

SolveReport ReynoldsSolver::solveOnce(const ReynoldsSystem& sys, Eigen::VectorXd& p) {
    const double lower = lowerBound();
    if (options_.solver == SolverKind::Psor) return psor_.solve(sys, p, lower, options_.control);
    if (options_.solver == SolverKind::Multigrid)
        return multigrid_.solve(sys, p, lower, options_.control);
    return fast_.solve(sys, p, lower, options_.control);
}

ReynoldsResult ReynoldsSolver::solve(const FilmState& film, const Eigen::VectorXd* warmStart) {
    lastFellBack_ = false;
    if (!fallback_) return solveWithPrimary(film, warmStart);
    try {
        return solveWithPrimary(film, warmStart);
    } catch (const std::runtime_error&) {
        ReynoldsResult r = fallback_->solve(film, warmStart);
        r.fellBack = true;
        lastFellBack_ = true;
        return r;
    }
}

ReynoldsResult ReynoldsSolver::solveWithPrimary(const FilmState& film, const Eigen::VectorXd* warmStart) {
    const int n = grid_.size();
    ReynoldsResult res;
    if (warmStart && warmStart->size() == n && warmStart->allFinite()) res.pressure = *warmStart;
    else if (warmStart && warmStart->size() != 0 && warmStart->size() != n)
        throw std::invalid_argument("ReynoldsSolver: warm start has " +
                                    std::to_string(warmStart->size()) + " values, grid has " +
                                    std::to_string(n));

    if (res.pressure.size() != n && !coarse_.empty())
        res.pressure = sequencedStart(film, res.coarseIterations);

    if (!lubricant_.pressureDependent()) {
        last_.reset();  // a throw below leaves none
        auto sys = std::make_unique<ReynoldsSystem>(grid_, film, lubricant_.referenceDensity(),
                                                    lubricant_.referenceViscosity());
        const SolveReport rep = solveOnce(*sys, res.pressure);
        last_ = std::move(sys);
        res.iterations = rep.iterations;
        res.residual = rep.residual;
        res.picardIterations = 1;
    } else {
        // Picard iteration on the pressure-dependent properties.
        Eigen::VectorXd rho(n), eta(n);
        if (res.pressure.size() != n) res.pressure = Eigen::VectorXd::Constant(n, grid_.ambientPressure());
        double change = std::numeric_limits<double>::infinity();
        for (int it = 1; it <= options_.maxPicardIterations; ++it) {
            for (int k = 0; k < n; ++k) {
                const double pg = res.pressure[k] - grid_.ambientPressure();
                rho[k] = lubricant_.density(pg);
                eta[k] = lubricant_.viscosity(pg);
            }
            ReynoldsSystem sys(grid_, film, rho, eta);
            Eigen::VectorXd p = res.pressure;
            const SolveReport rep = solveOnce(sys, p);
            res.iterations += rep.iterations;
            res.residual = rep.residual;
            res.picardIterations = it;
            const double scale = (p.array() - grid_.ambientPressure()).abs().maxCoeff();
            change = (p - res.pressure).cwiseAbs().maxCoeff() / std::max(scale, 1e-300);
            res.pressure += options_.picardRelaxation * (p - res.pressure);
            if (!std::isfinite(change))
                throw std::runtime_error("ReynoldsSolver: Picard iteration on the pressure-"
                                         "dependent lubricant diverged at step " +
                                         std::to_string(it));
            if (change <= options_.picardTolerance || scale == 0.0) break;
            if (it == options_.maxPicardIterations)
                throw std::runtime_error(
                    "ReynoldsSolver: Picard iteration on the pressure-dependent lubricant not "
                    "converged after " + std::to_string(it) + " steps (relative change " +
                    std::to_string(change) + " > " + std::to_string(options_.picardTolerance) +
                    "); try picardRelaxation < 1");
        }
    }
    if (options_.cavitation == Cavitation::HalfSommerfeld) clipBelow(grid_, options_.cavitationPressure, res.pressure);
    return res;
}

}  // namespace flexehd::lube
