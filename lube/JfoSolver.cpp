#include "lube/JfoSolver.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>

#include "lube/AitkenRelaxation.hpp"
#include "lube/PsorSolver.hpp"
#include "lube/ReynoldsSolver.hpp"
#include "lube/ReynoldsSystem.hpp"
#include "lube/JfoNetwork.hpp"
#include "lube/SparseLuFactor.hpp"

namespace flexehd::lube {

namespace {

// The iterate a solve starts from (the warm start, else a flooded film) with the bounds and the
// non-Film nodes' values imposed; returns the Film nodes.
const std::vector<int>& startingIterate(const FilmGrid& g, const JfoTopology& t, const JfoResult* warmStart,
                                        const std::vector<double>& inlet, double pcav, JfoResult& res) {
    const int n = g.size();
    if (warmStart) {
        res.pressure = warmStart->pressure;
        res.fraction = warmStart->fraction;
    } else {
        res.pressure = Eigen::VectorXd::Constant(n, std::max(pcav, g.ambientPressure()));
        res.fraction = Eigen::VectorXd::Ones(n);
    }
    for (int k : t.filmRows) {
        res.pressure[k] = std::max(res.pressure[k], pcav);
        res.fraction[k] = std::clamp(res.fraction[k], 0.0, 1.0);
    }
    for (int k : t.otherNodes) {
        res.pressure[k] = g.prescribedPressure(k);
        res.fraction[k] = g.kind(k) == NodeKind::Void ? 0.0 : inlet[static_cast<std::size_t>(k)];
    }
    return t.filmRows;
}

// Cold start of the active set from the Reynolds-condition solution (multigrid, nested): on a
// flooded film its cavitated set is the JFO one but for the reformation fronts, so the partition
// is nearly right and a few factorizations suffice. (Should that solve fail, the flooded start
// stays: more factorizations, same answer.)
void reynoldsConditionStart(const FilmGrid& g, const Lubricant& lubricant, const FilmState& film, double pcav,
                            const std::vector<int>& rows, double* p, double* phi) {
    try {
        ReynoldsOptions ro;
        ro.solver = SolverKind::Multigrid;
        ro.cavitationPressure = pcav;
        ro.control.tolerance = 1e-6;
        ReynoldsSolver rs(g, lubricant, ro);
        const Eigen::VectorXd pr = rs.solve(film).pressure;
        for (int k : rows) {
            p[k] = std::max(pr[k], pcav);
            phi[k] = pr[k] > pcav ? 1.0 : 0.5;
        }
    } catch (const std::exception&) {
    }
}

// Clips the Film nodes to the bounds the Gauss–Seidel iteration keeps (a film fraction below 0
// would be a dry node it clips).
void clipToBounds(const std::vector<int>& rows, double pcav, double* p, double* phi) {
    for (int k : rows) {
        p[k] = std::max(p[k], pcav);
        phi[k] = std::clamp(phi[k], 0.0, 1.0);
    }
}

// How the partition iteration over a set of rows ended.
enum class Partition { Settled, Unsettled, Singular, NonFinite };

// The partition full film / cavitated of the Film nodes `rows` solved and updated until it
// settles (the other nodes held at their p and φ), at most maxActiveSetIterations factorizations
// (counted in factorizations); the iterate is clipped to the bounds.
Partition settlePartition(const JfoNetwork& net, const FilmGrid& g, const std::vector<int>& rows, const JfoOptions& o,
                          SparseLuFactor& lu, double* p, double* phi, int& factorizations) {
    const double pcav = o.cavitationPressure;
    JfoActiveSetSystem sys(net, g, rows, p, phi);
    const int nf = sys.size();
    // Partition: cavitated where the film is partial (and a Couette outflow or storage term
    // can carry it: B > 0), full film elsewhere.
    std::vector<char> cav(static_cast<std::size_t>(nf));
    for (int r = 0; r < nf; ++r) cav[static_cast<std::size_t>(r)] = sys.B(r) > 0.0 && phi[rows[static_cast<std::size_t>(r)]] < 1.0;
    Eigen::VectorXd rhs;
    Partition outcome = Partition::Unsettled;
    for (int it = 1; it <= o.maxActiveSetIterations; ++it) {
        sys.setPartition(cav, pcav, rhs);
        ++factorizations;
        if (!lu.factor(sys.matrix())) return Partition::Singular;  // the ordering kept while the pattern is the same
        const Eigen::VectorXd y = lu.solve(rhs);
        if (!std::isfinite(y.sum())) return Partition::NonFinite;
        bool changed = false;
        for (int r = 0; r < nf; ++r) {
            const auto sr = static_cast<std::size_t>(r);
            const int k = rows[sr];
            if (cav[sr]) {
                p[k] = pcav;
                phi[k] = y[r];
                if (y[r] > 1.0) cav[sr] = 0, changed = true;
            } else {
                p[k] = y[r];
                phi[k] = 1.0;
                if (y[r] < pcav && sys.B(r) > 0.0) cav[sr] = 1, changed = true;
            }
        }
        if (!changed) {  // settled: the balances hold to round-off
            outcome = Partition::Settled;
            break;
        }
    }
    clipToBounds(rows, pcav, p, phi);
    return outcome;
}

// JfoMethod::ActiveSet: the partition of all Film nodes; true when the settled iterate meets the
// tolerance (else the sweeps polish it, from a feasible iterate).
bool activeSetSolve(const JfoNetwork& net, const FilmGrid& g, const std::vector<int>& rows, const JfoOptions& o,
                    SparseLuFactor& lu, JfoResult& res) {
    double* p = res.pressure.data();
    double* phi = res.fraction.data();
    res.factorizations = 0;
    const Partition outcome = settlePartition(net, g, rows, o, lu, p, phi, res.factorizations);
    if (outcome == Partition::Singular)
        throw std::runtime_error("JfoSolver: sparse LU failed in active-set step " + std::to_string(res.factorizations) +
                                 " (singular: a closed film-fraction loop with no supply, e.g. a steady "
                                 "film without inlet?)");
    if (outcome == Partition::NonFinite)
        throw std::runtime_error("JfoSolver: active-set step " + std::to_string(res.factorizations) +
                                 " gave a non-finite solution");
    if (outcome != Partition::Settled) return false;
    res.residual = net.residual(rows, p, phi);
    return res.residual <= o.control.tolerance;
}

// The projected Gauss–Seidel sweeps (Ausas et al.) with over-relaxation w of the full-film
// pressure, the residual checked every 10 sweeps; throws when they diverge or do not converge.
void gaussSeidelSolve(const JfoNetwork& net, const std::vector<int>& rows, const JfoOptions& o, double w,
                      JfoResult& res) {
    const double pcav = o.cavitationPressure;
    double* p = res.pressure.data();
    double* phi = res.fraction.data();
    const int checkEvery = 10;
    double first = -1.0;
    for (int it = 1; it <= o.control.maxIterations; ++it) {
        for (int k : rows) {
            const JfoNetwork::Balance bl = net.balance(k, p, phi);
            const double phiStar = bl.B > 0.0 ? (bl.S + bl.Sin - bl.D * pcav) / bl.B : 1.0;
            if (bl.B > 0.0 && phiStar < 1.0) {  // cavitated: p = p_cav, φ from the balance
                p[k] = pcav;
                phi[k] = std::max(phiStar, 0.0);
            } else {                            // full film: φ = 1, p from the balance (SOR)
                if (bl.B > 0.0) phi[k] = 1.0;
                const double pgs = (bl.S + bl.Sin - bl.B * phi[k]) / bl.D;
                p[k] = std::max(pcav, p[k] + w * (pgs - p[k]));
            }
        }
        if (it % checkEvery != 0 && it != o.control.maxIterations) continue;
        const double rmax = net.residual(rows, p, phi);
        res.iterations = it;
        res.residual = rmax;
        if (first < 0.0) first = rmax;
        if (!std::isfinite(rmax) || rmax > 1e8 * std::max(first, 1.0))
            throw std::runtime_error("JfoSolver: diverged after " + std::to_string(it) + " sweeps (residual " +
                                     std::to_string(rmax) + ", omega " + std::to_string(w) + ")");
        if (rmax <= o.control.tolerance) return;
    }
    throw std::runtime_error("JfoSolver: not converged after " + std::to_string(o.control.maxIterations) +
                             " sweeps (residual " + messageNumber(res.residual) + " > tolerance " +
                             messageNumber(o.control.tolerance) + ", omega " + std::to_string(w) + ")");
}

// The effective squeeze rate that turns the Reynolds-condition problem into the JFO balance of
// every full-film node (docs/lube.md §3b, "the multigrid method"): the content term
// (h − φₙhₙ)/Δt (`content`, per node, none when steady) and the Couette inflow an upstream
// partial film (or starved inlet) does not bring, Σ_in q_f (1 − φ_up)/V_k (`missing`, per node:
// JfoNetwork::balance).
void effectiveSqueeze(const JfoNetwork& net, const FilmGrid& g, const std::vector<int>& rows,
                      const Eigen::VectorXd& missing, const Eigen::VectorXd* content, Eigen::VectorXd& dhdt) {
    dhdt.setZero(g.size());
    for (int k : rows) {
        dhdt[k] = missing[k] / net.area(k);
        if (content) dhdt[k] += (*content)[k];
    }
}

// The content term (h − φₙhₙ)/Δt of every row (the same in every pass of a solve).
Eigen::VectorXd contentRate(const FilmGrid& g, const FilmState& film, double dt, const JfoState& previous,
                            const std::vector<int>& rows) {
    Eigen::VectorXd content = Eigen::VectorXd::Zero(g.size());
    for (int k : rows) content[k] = (film.h[k] - previous.fraction[k] * previous.h[k]) / dt;
    return content;
}

// The missing Couette inflow of every row at the iterate (p, φ) (JfoNetwork::balance).
void missingInflow(const JfoNetwork& net, const std::vector<int>& rows, const double* p, const double* phi,
                   Eigen::VectorXd& missing) {
    missing.setZero(static_cast<Eigen::Index>(net.topology().area.size()));
    for (int k : rows) net.balance<true>(k, p, phi, &missing[k]);
}

// The nodal JFO update of node k (Ausas et al.; without over-relaxation), its neighbours frozen.
// It reads the neighbours' p (and its own φ where B = 0) and the film fraction of the
// neighbours whose Couette flow enters k, not its own p.
inline void nodalUpdate(const JfoNetwork& net, int k, double pcav, double* p, double* phi) {
    const JfoNetwork::Balance bl = net.balance(k, p, phi);
    const bool carried = bl.B > 0.0;  // a Couette outflow or storage can carry a partial film
    const double phiStar = carried ? (bl.S + bl.Sin - bl.D * pcav) / bl.B : 1.0;
    const bool cavitated = carried && phiStar < 1.0;  // p = p_cav, φ from the balance
    const double phiFull = carried ? 1.0 : phi[k];    // full film: φ = 1, p from the balance
    const double pFull = std::max(pcav, (bl.S + bl.Sin - bl.B * phiFull) / bl.D);
    // Both candidates computed and one kept, without a branch: at the fronts the choice changes
    // from node to node.
    p[k] = cavitated ? pcav : pFull;
    phi[k] = cavitated ? std::max(phiStar, 0.0) : phiFull;
}

bool sameBits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// Marks in `stale` the nodes whose nodal update reads a value of node k that changed: all its
// neighbours when p_k changed, those its Couette flow enters when φ_k changed.
void markReaders(const JfoNetwork& net, int k, bool pChanged, bool phiChanged, std::vector<char>& stale) {
    if (!pChanged && !phiChanged) return;
    net.forFaces(k, [&](int m, double, double qo) {
        if (pChanged || qo > 0.0) stale[static_cast<std::size_t>(m)] = 1;
    });
}

// One Gauss–Seidel pass of the nodal JFO update in the direction of the Couette flow: each
// node's upstream neighbours are updated before it, so the film fraction is transported through
// the cavities and a rupture or reformation front moves as far as the flow carries it in one pass
// (repeated until φ no longer changes where the flow has a circumferential part; once where it is
// axial only). Nodes marked in `held` keep their values. With `stale`, only the nodes marked
// there are updated (the update of any other gives its value bit for bit, its inputs unchanged
// since it was last updated), and the nodes reading a value that changes are marked.
void sweepAlongFlow(const JfoNetwork& net, const FilmGrid& g, const FilmState& film, double pcav, double* p,
                    double* phi, const std::vector<char>* held = nullptr, std::vector<char>* stale = nullptr) {
    const JfoTopology& t = net.topology();
    const int nz = g.nAxial();
    const bool downZ = film.sumAxial() < 0.0, downT = film.sumCircumferential() < 0.0;
    for (int sweep = 0; sweep < 200; ++sweep) {
        double change = 0.0;
        for (int ii = 0; ii < nz; ++ii) {
            const auto i = static_cast<std::size_t>(downZ ? nz - 1 - ii : ii);
            const int b = t.ringStart[i], e = t.ringStart[i + 1];
            for (int jj = 0; jj < e - b; ++jj) {
                const int k = t.filmRows[static_cast<std::size_t>(downT ? e - 1 - jj : b + jj)];
                const auto sk = static_cast<std::size_t>(k);
                if (held && (*held)[sk]) continue;
                if (stale && !(*stale)[sk]) continue;
                const double pBefore = p[k], before = phi[k];
                nodalUpdate(net, k, pcav, p, phi);
                change = std::max(change, std::abs(phi[k] - before));
                if (!stale) continue;
                (*stale)[sk] = 0;
                markReaders(net, k, !sameBits(p[k], pBefore), !sameBits(phi[k], before), *stale);
            }
        }
        if (change <= 1e-15 || film.sumCircumferential() == 0.0) return;
    }
}

// After the partition of the pad changed its nodes: they and their neighbours are to be updated.
void markPad(const JfoNetwork& net, const std::vector<int>& pad, std::vector<char>& stale) {
    for (int k : pad) {
        stale[static_cast<std::size_t>(k)] = 1;
        net.forFaces(k, [&](int m, double, double) { stale[static_cast<std::size_t>(m)] = 1; });
    }
}

// The rank of each node in one fill-reducing elimination order of all Film nodes' graph (AMD),
// computed once per grid: each pad, its nodes taken in this order, needs no ordering of its own
// (docs/lube.md §3b). Non-Film nodes rank last.
std::vector<int> filmEliminationRank(const JfoTopology& t, int n) {
    std::vector<int> idx(static_cast<std::size_t>(n), -1);
    const int nf = static_cast<int>(t.filmRows.size());
    for (int r = 0; r < nf; ++r) idx[static_cast<std::size_t>(t.filmRows[static_cast<std::size_t>(r)])] = r;
    std::vector<Eigen::Triplet<double, int>> trip;
    for (int r = 0; r < nf; ++r) {
        const auto k = static_cast<std::size_t>(t.filmRows[static_cast<std::size_t>(r)]);
        trip.emplace_back(r, r, 1.0);
        for (int q = t.start[k]; q < t.start[k + 1]; ++q)
            if (t.otherFilm[static_cast<std::size_t>(q)])
                trip.emplace_back(r, idx[static_cast<std::size_t>(t.other[static_cast<std::size_t>(q)])], 1.0);
    }
    JfoMatrix A(nf, nf);
    A.setFromTriplets(trip.begin(), trip.end());
    A.makeCompressed();
    const std::vector<int> order = SparseLuFactor::fillReducingOrder(A);
    std::vector<int> rank(static_cast<std::size_t>(n), n);
    for (int i = 0; i < nf; ++i)
        rank[static_cast<std::size_t>(t.filmRows[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])])] = i;
    return rank;
}

// The full-film pad of a starved film and its rim: the Film nodes within kPadRim faces of a
// full-film node (φ = 1, p > p_cav), marked in inPad; in the order of rank (the elimination order).
constexpr int kPadRim = 2;
std::vector<int> fullFilmPad(const JfoNetwork& net, const FilmGrid& g, const std::vector<int>& rows, const double* p,
                             const double* phi, double pcav, const std::vector<int>& rank, std::vector<char>& inPad) {
    inPad.assign(static_cast<std::size_t>(g.size()), 0);
    std::vector<int> pad;
    for (int k : rows)
        if (phi[k] >= 1.0 && p[k] > pcav) inPad[static_cast<std::size_t>(k)] = 1, pad.push_back(k);
    std::size_t from = 0;
    for (int layer = 0; layer < kPadRim; ++layer) {
        const std::size_t to = pad.size();
        for (std::size_t i = from; i < to; ++i)
            net.forFaces(pad[i], [&](int m, double, double) {
                if (g.kind(m) == NodeKind::Film && !inPad[static_cast<std::size_t>(m)])
                    inPad[static_cast<std::size_t>(m)] = 1, pad.push_back(m);
            });
        from = to;
    }
    std::sort(pad.begin(), pad.end(),
              [&](int a, int b) { return rank[static_cast<std::size_t>(a)] < rank[static_cast<std::size_t>(b)]; });
    return pad;
}

// The first stage of JfoMethod::Multigrid from a warm start where the full film is a small pad
// (a starved film: docs/lube.md §3b, "the full-film pad"): the nodal update along the flow, then
// until the residual meets the tolerance: the partition of the pad and its rim solved as the
// active set does (sparse LU of a few hundred unknowns), the other nodes held; the nodal update
// along the flow of the nodes outside it, which carries the pad's outflow downstream and moves
// the cavities' fronts. The pad is taken anew each time (it grows where a node outside it turned
// full film). False (the multigrid passes continue from the iterate) when the pad and rim are more
// than kPadShare of the Film nodes, its partition does not settle, or kPadRounds do not converge.
constexpr double kPadShare = 0.25;
constexpr int kPadRounds = 8;
bool fullFilmPadSolve(const JfoNetwork& net, const FilmGrid& g, const FilmState& film, const std::vector<int>& rows,
                      const JfoOptions& o, const std::vector<int>& rank, SparseLuFactor& lu, JfoResult& res) {
    const double pcav = o.cavitationPressure;
    double* p = res.pressure.data();
    double* phi = res.fraction.data();
    // A warm start whose full film alone is beyond the share (a flooded film): the passes.
    int full = 0;
    for (int k : rows) full += phi[k] >= 1.0 && p[k] > pcav;
    if (static_cast<double>(full) > kPadShare * static_cast<double>(rows.size())) return false;
    std::vector<char> stale(static_cast<std::size_t>(g.size()), 1);
    sweepAlongFlow(net, g, film, pcav, p, phi, nullptr, &stale);
    std::vector<char> inPad;
    int factorizations = 0;
    for (int round = 1; round <= kPadRounds; ++round) {
        const std::vector<int> pad = fullFilmPad(net, g, rows, p, phi, pcav, rank, inPad);
        if (static_cast<double>(pad.size()) > kPadShare * static_cast<double>(rows.size())) return false;
        if (!pad.empty() && settlePartition(net, g, pad, o, lu, p, phi, factorizations) != Partition::Settled)
            return false;
        markPad(net, pad, stale);
        sweepAlongFlow(net, g, film, pcav, p, phi, &inPad, &stale);
        res.iterations = round;
        res.padNodes = static_cast<int>(pad.size());
        res.residual = net.residual(rows, p, phi);
        if (res.residual <= o.control.tolerance) return true;
    }
    return false;
}

// JfoMethod::Multigrid: the fixed point of the Reynolds-condition problem with the effective
// squeeze rate (multigrid, warm-started) and a sweep of the nodal update along the flow, which
// transports the film fraction through the cavities and moves the fronts.
// A node the Reynolds problem leaves at the bound has F(φ = 1) ≥ 0, i.e. φ* ≤ 1: the JFO rule, so
// a fixed point is the JFO solution. True when the residual meets the tolerance within the
// outer iterations; false (the active set takes over from the iterate) when they run out or the
// residual has not halved over three passes.
bool multigridSolve(const JfoNetwork& net, const FilmGrid& g, const FilmState& film, double dt,
                    const JfoState* previous, const std::vector<int>& rows, const JfoOptions& o, bool warmStarted,
                    ReynoldsSolver& rs, JfoResult& res) {
    const double pcav = o.cavitationPressure;
    FilmState eff = film;
    Eigen::VectorXd warm = res.pressure;
    std::vector<double> history;  // the residual of each pass
    Eigen::VectorXd missing;      // each row's missing Couette inflow at the iterate (m³/s)
    missingInflow(net, rows, res.pressure.data(), res.fraction.data(), missing);
    const Eigen::VectorXd content = dt > 0.0 ? contentRate(g, film, dt, *previous, rows) : Eigen::VectorXd();
    // Aitken's relaxation of the missing inflow, x = G(x) of the passes: where a front moves they
    // converge about tenfold each, and it saves about a tenth of them (docs/lube.md §3b).
    AitkenRelaxation aitken(1.0, 0.05, 4.0);
    for (int outer = 1; outer <= o.maxMultigridPasses; ++outer) {
        effectiveSqueeze(net, g, rows, missing, dt > 0.0 ? &content : nullptr, eff.dhdt);
        // Cold, the first pass is the multigrid's own cold start (nested from the coarse grids);
        // the later ones change only the squeeze rate: the assembled system is reused.
        res.pressure = outer == 1 ? rs.solve(eff, warmStarted ? &warm : nullptr).pressure
                                  : rs.resolve(eff.dhdt, warm).pressure;
        warm = res.pressure;
        sweepAlongFlow(net, g, film, pcav, res.pressure.data(), res.fraction.data());
        res.iterations = outer;
        const Eigen::VectorXd used = missing;
        res.residual = net.residual(rows, res.pressure.data(), res.fraction.data(), missing.data());
        if (res.residual <= o.control.tolerance) return true;
        missing = aitken.next(used, missing);
        // Stalled (a front alternating between two nodes, as at the meniscus of a steady starved
        // film): the active set takes over.
        history.push_back(res.residual);
        if (history.size() >= 4 && res.residual > 0.5 * history[history.size() - 4]) return false;
    }
    return false;
}

// The net flow (m³/s) from each boundary (Fixed or Void) node into the Film nodes next to it, with
// the scheme's face fluxes at the solution r (0 on Film nodes).
Eigen::VectorXd boundaryFlowsOf(const JfoNetwork& net, const FilmGrid& g, const std::vector<double>& inlet,
                                const JfoResult& r) {
    Eigen::VectorXd q = Eigen::VectorXd::Zero(g.size());
    for (int i : net.topology().boundaryFaces) {
        const JfoFace& f = net.faces()[static_cast<std::size_t>(i)];
        const bool fa = g.kind(f.a) == NodeKind::Film;
        const double phiA = fa ? r.fraction[f.a] : inlet[static_cast<std::size_t>(f.a)];
        const double phiB = fa ? inlet[static_cast<std::size_t>(f.b)] : r.fraction[f.b];
        const double ab = f.c * (r.pressure[f.a] - r.pressure[f.b]) + f.q * (f.q > 0.0 ? phiA : phiB);
        if (fa) q[f.b] -= ab;  // from the Film node a into the boundary node b
        else q[f.a] += ab;
    }
    return q;
}

}  // namespace


JfoSolver::JfoSolver(FilmGrid grid, Lubricant lubricant, JfoOptions options)
    : grid_(std::move(grid)), lubricant_(lubricant), options_(options),
      inlet_(static_cast<std::size_t>(grid_.size()), 1.0), lu_(std::make_unique<SparseLuFactor>()) {
    topology_ = std::make_unique<JfoTopology>(grid_);
    netStorage_ = std::make_unique<JfoNetworkStorage>();
    if (lubricant_.pressureDependent())
        throw std::invalid_argument("JfoSolver: only a constant-property lubricant is supported");
    if (!std::isfinite(options_.cavitationPressure))
        throw std::invalid_argument("JfoSolver: cavitationPressure must be finite");
    if (!(options_.control.tolerance > 0.0) || options_.control.maxIterations < 1)
        throw std::invalid_argument("JfoSolver: tolerance must be positive, maxIterations >= 1");
    if (options_.omega != 0.0 && !(options_.omega > 0.0 && options_.omega < 2.0))
        throw std::invalid_argument("JfoSolver: omega must be in (0, 2) or 0 (automatic)");
    if (options_.maxActiveSetIterations < 1)
        throw std::invalid_argument("JfoSolver: maxActiveSetIterations must be >= 1");
    if (grid_.filmNodeCount() == 0)
        throw std::invalid_argument("JfoSolver: the grid has no Film node");
}

void JfoSolver::setInletFraction(int node, double fraction) {
    if (node < 0 || node >= grid_.size())
        throw std::out_of_range("JfoSolver::setInletFraction: node " + std::to_string(node) +
                                " outside the grid");
    if (!(fraction >= 0.0 && fraction <= 1.0))
        throw std::invalid_argument("JfoSolver::setInletFraction: fraction must be in [0, 1], got " +
                                    std::to_string(fraction));
    inlet_[static_cast<std::size_t>(node)] = fraction;
}

JfoResult JfoSolver::solve(const FilmState& film, double dt, const JfoState* previous,
                           const JfoResult* warmStart) const {
    const FilmGrid& g = grid_;
    validateFilmState(g, film);
    const int n = g.size();
    if (!(dt >= 0.0) || !std::isfinite(dt))
        throw std::invalid_argument("JfoSolver: time step must be >= 0 and finite");
    if (dt > 0.0 && (!previous || previous->h.size() != n || previous->fraction.size() != n))
        throw std::invalid_argument("JfoSolver: a transient step needs the previous h and film "
                                    "fraction on every node");
    const double pcav = options_.cavitationPressure;
    const JfoNetwork net(*topology_, g, film, lubricant_.referenceViscosity(), dt, previous, inlet_, pcav,
                         netStorage_.get());
    JfoResult res;
    const bool warm = warmStart && warmStart->pressure.size() == n && warmStart->fraction.size() == n;
    const std::vector<int>& rows = startingIterate(g, *topology_, warm ? warmStart : nullptr, inlet_, pcav, res);
    bool solved = false;
    if (options_.method == JfoMethod::Multigrid) {
        if (!multigrid_) {
            ReynoldsOptions ro;
            ro.solver = SolverKind::Multigrid;
            ro.fallback = SolverKind::ActiveSet;
            ro.cavitationPressure = pcav;
            ro.control.tolerance = options_.control.tolerance;
            multigrid_ = std::make_unique<ReynoldsSolver>(g, lubricant_, ro);
        }
        if (warm) {
            if (!padLu_) {
                padRank_ = filmEliminationRank(*topology_, n);
                padLu_ = std::make_unique<SparseLuFactor>(SparseLuFactor::Ordering::Given);
            }
            solved = res.padStage = fullFilmPadSolve(net, g, film, rows, options_, padRank_, *padLu_, res);
            if (!solved) res.padNodes = 0;
        }
        if (!solved) solved = multigridSolve(net, g, film, dt, previous, rows, options_, warm, *multigrid_, res);
    }
    if (!solved && options_.method != JfoMethod::GaussSeidel) {
        if (!warm && options_.method == JfoMethod::ActiveSet)
            reynoldsConditionStart(g, lubricant_, film, pcav, rows, res.pressure.data(), res.fraction.data());
        solved = activeSetSolve(net, g, rows, options_, *lu_, res);
    }
    if (!solved) gaussSeidelSolve(net, rows, options_, options_.omega > 0.0 ? options_.omega : PsorSolver::automaticOmega(g), res);
    res.boundaryFlow = boundaryFlowsOf(net, g, inlet_, res);
    return res;
}

JfoSolver::~JfoSolver() = default;
JfoSolver::JfoSolver(JfoSolver&&) noexcept = default;

double JfoSolver::oilVolume(const FilmState& film, const Eigen::VectorXd& fraction) const {
    double v = 0.0;
    for (int k : topology_->filmRows) v += topology_->area[static_cast<std::size_t>(k)] * fraction[k] * film.h[k];
    return v;
}

double JfoSolver::boundaryInflow(const FilmState& film, const JfoResult& r) const {
    return boundaryFlows(film, r).sum();
}

Eigen::VectorXd JfoSolver::boundaryFlows(const FilmState& film, const JfoResult& r) const {
    const JfoNetwork net(*topology_, grid_, film, lubricant_.referenceViscosity(), 0.0, nullptr, inlet_,
                         options_.cavitationPressure);
    return boundaryFlowsOf(net, grid_, inlet_, r);
}

}  // namespace flexehd::lube
