#include "lube/RingFilm.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <string>
#include <utility>

namespace flexehd::lube {

namespace {

// x = A⁻¹ d for the tridiagonal A (sub a, diagonal b, super c), by the Thomas algorithm.
void tridiagonalSolve(const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& c,
                      std::vector<double>& d) {
    const std::size_t n = b.size();
    std::vector<double> cp(n);
    double m = b[0];
    cp[0] = c[0] / m;
    d[0] /= m;
    for (std::size_t i = 1; i < n; ++i) {
        m = b[i] - a[i] * cp[i - 1];
        cp[i] = c[i] / m;
        d[i] = (d[i] - a[i] * d[i - 1]) / m;
    }
    for (std::size_t i = n - 1; i-- > 0;) d[i] -= cp[i] * d[i + 1];
}

// The mass balance of an inner node i of the mass-conserving film (the scheme of JfoSolver,
// docs/lube.md §3b, in one dimension):
//   F = D p_i − c₋ p_{i−1} − c₊ p_{i+1} + B φ_i − a₋ φ_{i−1} − a₊ φ_{i+1} − S = 0,
// c± the faces' conductances, D = c₋ + c₊; the Couette flux of a face carried by its upwind
// node's film fraction: B the outflow coefficients plus the storage Δx h/Δt, a± the inflow ones;
// S the oil the node held, Δx φₙ hₙ/Δt (a step; 0 steady).
struct JfoRow {
    double cm, cp, am, ap, D, B, S;
};

// The row from its faces' conductances and Couette coefficients (U/2) h_f (below: face i − ½,
// above: i + ½), the storage and the oil held.
JfoRow jfoRow(double cBelow, double cAbove, double qBelow, double qAbove, double storage, double held) {
    JfoRow w{cBelow, cAbove, 0.0, 0.0, cBelow + cAbove, storage, held};
    if (-qBelow > 0.0) w.B += -qBelow;  // flow out through the face below
    else w.am = qBelow;
    if (qAbove > 0.0) w.B += qAbove;
    else w.ap = -qAbove;
    return w;
}

// The gas of node i's side of the pressure peak (the edges' p[0], p[n − 1]; the peak the lower).
double sideGas(int i, int peak, const Eigen::VectorXd& p) {
    const Eigen::Index n = p.size();
    return i < peak ? p[0] : i > peak ? p[n - 1] : std::min(p[0], p[n - 1]);
}

// Each node's gas pressure (Jeng, ASLE Trans. 35 (1992) 707, starved ring films: the partial
// film before the meniscus is at the leading side's gas pressure, after the rupture at the
// trailing side's; the edges' values p[0], p[n − 1], neither below p_cav). A cavitated node
// takes the gas it opens to: a run of cavitated nodes reaching one edge that edge's gas. Any other
// node takes the gas of its side of the full film's pressure peak, below it the lower edge's,
// above it the upper edge's, the peak itself the lower of the two: a run between full nodes, a
// run reaching both edges (no full node), and a full node, for which it is the pressure below
// which the film ruptures. peak: the last solution's highest full node (−1: none yet, the full
// nodes' middle).
void gasPressures(const std::vector<char>& cav, const Eigen::VectorXd& p, int peak, std::vector<double>& gas) {
    const int n = static_cast<int>(cav.size()), m = n - 2;
    if (peak < 0) {
        int lo = n - 1, hi = 0;
        for (int i = 1; i <= m; ++i)
            if (!cav[static_cast<std::size_t>(i)]) lo = std::min(lo, i), hi = std::max(hi, i);
        peak = lo <= hi ? (lo + hi) / 2 : n / 2;
    }
    for (int i = 0; i < n; ++i) gas[static_cast<std::size_t>(i)] = sideGas(i, peak, p);
    for (int first = 1; first <= m;) {  // the runs of cavitated nodes [first, last]
        if (!cav[static_cast<std::size_t>(first)]) {
            ++first;
            continue;
        }
        int last = first;
        while (last < m && cav[static_cast<std::size_t>(last) + 1]) ++last;
        if ((first == 1) != (last == m))
            for (int i = first; i <= last; ++i) gas[static_cast<std::size_t>(i)] = first == 1 ? p[0] : p[n - 1];
        first = last + 1;
    }
}

// The partition full film (unknown p, φ = 1) / cavitated (unknown φ, p = its gas pressure,
// gasPressures) of the inner nodes, solved and updated until it settles (a primal–dual active
// set, as JfoSolver's). Between two cavitated nodes no pressure flow: the gas moves, not the oil.
// The update (docs/lube.md §9):
// - a cavitated node with φ > 1 becomes full;
// - a full node below its gas pressure ruptures (becomes cavitated, where an outflow or storage
//   can carry a partial film, B > 0) — unless a cavitated neighbour's gas stands above both its
//   pressure and its own gas while its pressure is at least p_cav: that gas pushes the film,
//   which is under no tension;
// - a cavitated node whose gas drains more oil into a full neighbour than it holds (φ < 0) has
//   emptied: the meniscus moves into that neighbour, which becomes cavitated at the same gas.
// So a gas above the film's pressure displaces the film as the oil leaves ahead of it, rather
// than permeating it. p and φ hold the edges' pressures and fractions and receive the inner
// nodes'; cav the start (per node) and the outcome. A partition's matrix is diagonally dominant
// by columns (a full node's column: Σ c against its neighbours' −c; a cavitated node's: B against
// the −a of its outflow), so the Thomas algorithm needs no interchanges and its growth is bounded
// (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., Thm 9.9).
// The partition update returned to one of its recent partitions (docs/lube.md §9: the face's film
// cannot hold the gas difference within the step).
struct PartitionCycles : std::runtime_error {
    using std::runtime_error::runtime_error;
};

constexpr int kPeakPasses = 8;  // passes over which a move of the pressure peak asks for another
constexpr std::size_t kRecentPartitions = 32;  // partitions kept to see the update cycle

void settleJfoPartition(const std::vector<JfoRow>& rows, double pcav, Eigen::VectorXd& p, Eigen::VectorXd& phi,
                        std::vector<char>& cav) {
    const int m = static_cast<int>(rows.size()), n = m + 2;
    cav.front() = cav.back() = 0;
    for (int i = 1; i <= m; ++i) {
        const auto si = static_cast<std::size_t>(i);
        cav[si] = cav[si] && rows[si - 1].B > 0.0;
    }
    const auto size = static_cast<std::size_t>(m);
    std::vector<double> dl(size), dd(size), du(size), y(size);  // row k's sub, diagonal, super; rhs
    std::vector<double> gas(static_cast<std::size_t>(n));
    int peak = -1;  // the last pass's highest full node
    const int passes = 4 * n;
    std::vector<char> was;  // a pass's partition, before its update
    std::deque<std::pair<int, std::vector<char>>> recent;  // the last partitions the update made, and after which pass
    for (int pass = 0; pass < passes; ++pass) {
        gasPressures(cav, p, peak, gas);
        for (int k = 0; k < m; ++k) {
            const auto sk = static_cast<std::size_t>(k);
            const JfoRow& w = rows[sk];
            const int i = k + 1;
            const auto si = static_cast<std::size_t>(i);
            const bool c = cav[si];
            const bool cavBelow = i > 1 && cav[si - 1], cavAbove = i < m && cav[si + 1];
            dd[sk] = c ? w.B : w.D;
            // p_i = its gas pressure (its pressure flow only through faces to full nodes and the
            // edges), or φ_i = 1.
            double known = c ? (w.D - (cavBelow ? w.cm : 0.0) - (cavAbove ? w.cp : 0.0)) * gas[si] : w.B;
            if (i == 1) known -= w.cm * p[0] + w.am * phi[0];
            else if (cavBelow) dl[sk] = -w.am, known -= c ? 0.0 : w.cm * gas[si - 1];
            else dl[sk] = -w.cm, known -= w.am;
            if (i == m) known -= w.cp * p[n - 1] + w.ap * phi[n - 1];
            else if (cavAbove) du[sk] = -w.ap, known -= c ? 0.0 : w.cp * gas[si + 1];
            else du[sk] = -w.cp, known -= w.ap;
            y[sk] = w.S - known;
        }
        tridiagonalSolve(dl, dd, du, y);
        for (double v : y)
            if (!std::isfinite(v))
                throw std::runtime_error("RingFilm: the mass-conserving film's balance is singular (pass " +
                                         std::to_string(pass + 1) + ")");
        // The peak follows the solution; over the first passes a move asks for another pass.
        bool changed = false;
        int highest = -1;
        for (int i = 1; i <= m; ++i)
            if (!cav[static_cast<std::size_t>(i)] &&
                (highest < 0 || y[static_cast<std::size_t>(i) - 1] > y[static_cast<std::size_t>(highest) - 1]))
                highest = i;
        if (highest >= 0 && highest != peak) {
            changed = pass < kPeakPasses && peak >= 0;
            peak = highest;
        }
        was = cav;  // the pass's partition
        for (int i = 1; i <= m; ++i) {
            const auto si = static_cast<std::size_t>(i);
            const double v = y[si - 1];
            if (was[si]) {
                p[i] = gas[si], phi[i] = v;
                if (v > 1.0) cav[si] = 0, changed = true;
                continue;
            }
            p[i] = v, phi[i] = 1.0;
            const double own = sideGas(i, peak, p);  // peak ≥ 0: this pass has a full node
            auto pushes = [&](int j) {
                return j >= 1 && j <= m && was[static_cast<std::size_t>(j)] && gas[static_cast<std::size_t>(j)] > v &&
                       gas[static_cast<std::size_t>(j)] > own;
            };
            const bool pushed = v >= pcav && (pushes(i - 1) || pushes(i + 1));
            if (v < own && !pushed && rows[si - 1].B > 0.0) cav[si] = 1, changed = true;
        }
        for (int i = 1; i <= m; ++i) {  // emptied cavitated nodes: the meniscus moves on
            const auto si = static_cast<std::size_t>(i);
            if (!was[si] || !(y[si - 1] < 0.0)) continue;
            for (const int b : {i - 1, i + 1}) {
                const auto sb = static_cast<std::size_t>(b);
                if (b >= 1 && b <= m && !was[sb] && y[sb - 1] < gas[si] && rows[sb - 1].B > 0.0 && !cav[sb])
                    cav[sb] = 1, changed = true;
            }
        }
        // A partition that returns to one of the last passes' cycles and will not settle.
        if (cav != was) {
            for (const auto& [when, partition] : recent)
                if (partition == cav)
                    throw PartitionCycles(
                        "RingFilm: the mass-conserving film's full/cavitated partition cycles (it returns after " +
                        std::to_string(pass + 1 - when) +
                        " passes), as where the gas on one side stands above what the film next to it can hold while "
                        "the inflow refills it: the gas blows through the face within the step");
            recent.emplace_back(pass + 1, cav);
            if (recent.size() > kRecentPartitions) recent.pop_front();
        }
        if (!changed) {  // settled: the balances hold to round-off; the bounds as JfoSolver clips them
            for (int i = 1; i <= m; ++i)
                p[i] = std::max(p[i], cav[static_cast<std::size_t>(i)] ? gas[static_cast<std::size_t>(i)] : pcav),
                phi[i] = std::clamp(phi[i], 0.0, 1.0);
            return;
        }
    }
    throw std::runtime_error("RingFilm: the mass-conserving film's full/cavitated partition did not settle in " +
                             std::to_string(passes) + " passes");
}

// The face open to the gas (docs/lube.md §9): the gas passes the face through the gap its oil
// leaves open, its pressure falling from the higher edge's to the lower's along the open
// channel's resistance ∫ dx/h_o³, h_o = (1 − φ) h with the last step's film fraction (at the
// edges the fraction of the node next to them, as openGap; a node the oil filled takes
// h_o = kOpenFloor h, so the fall concentrates there). Per node, not below p_cav.
constexpr double kOpenFloor = 0.01;

std::vector<double> openFaceGas(const Eigen::VectorXd& x, const Eigen::VectorXd& h, const Eigen::VectorXd& previous,
                                double pLow, double pHigh, double pcav) {
    const Eigen::Index n = x.size();
    auto inverseCube = [&](Eigen::Index i) {
        const double open = std::max(1.0 - previous[std::clamp<Eigen::Index>(i, 1, n - 2)], kOpenFloor) * h[i];
        return 1.0 / (open * open * open);
    };
    std::vector<double> resistance(static_cast<std::size_t>(n), 0.0);
    for (Eigen::Index i = 1; i < n; ++i)
        resistance[static_cast<std::size_t>(i)] = resistance[static_cast<std::size_t>(i) - 1] +
                                                  0.5 * (x[i] - x[i - 1]) * (inverseCube(i - 1) + inverseCube(i));
    std::vector<double> gas(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i)
        gas[static_cast<std::size_t>(i)] =
            std::max(pcav, pLow + (pHigh - pLow) * resistance[static_cast<std::size_t>(i)] / resistance.back());
    return gas;
}

// The open face's balance: each inner node full film (unknown p, φ = 1) or partial
// (unknown φ, p its gas). A face between two partial nodes, or between a partial node and an
// edge, carries its pressure flow c (p_j − p_k) in the oil streaks the gas flows between: weighted
// by the upwind node's fraction, as the Couette flux is, so that no node gives more oil than it
// holds (the gas from an edge brings none). Any other face's pressure flow is the full film's.
// The face f between nodes j = f and k = f + 1 carries F = a_j u_j + a_k u_k + b, u the nodes'
// unknowns (the edges' known): φ of a partial node, p of a full one.
struct OpenFace {
    const std::vector<double>& c;  // faces' conductances
    const std::vector<double>& q;  // faces' Couette coefficients (U/2) h_f
    const std::vector<double>& gas;
    const std::vector<char>& partial;
    const Eigen::VectorXd& p;    // the edges' pressures
    const Eigen::VectorXd& phi;  // the edges' fractions
    struct Flux {
        double aj = 0.0, ak = 0.0, b = 0.0;
    };
    Flux flux(int f) const {
        const int n = static_cast<int>(partial.size()), j = f, k = f + 1;
        auto edge = [&](int i) { return i == 0 || i == n - 1; };
        auto part = [&](int i) { return !edge(i) && partial[static_cast<std::size_t>(i)]; };
        Flux F;
        auto carried = [&](int i, double coefficient, double& a) {  // coefficient × φ_i
            if (part(i)) a += coefficient;
            else F.b += coefficient * (edge(i) ? phi[i] : 1.0);
        };
        auto pushed = [&](int i, double coefficient, double& a) {  // coefficient × p_i
            if (edge(i)) F.b += coefficient * p[i];
            else if (part(i)) F.b += coefficient * gas[static_cast<std::size_t>(i)];
            else a += coefficient;
        };
        const auto sf = static_cast<std::size_t>(f);
        if (q[sf] > 0.0) carried(j, q[sf], F.aj);
        else carried(k, q[sf], F.ak);
        if ((part(j) || part(k)) && (part(j) || edge(j)) && (part(k) || edge(k))) {
            const double w = c[sf] * ((edge(j) ? p[j] : gas[sf]) - (edge(k) ? p[k] : gas[sf + 1]));
            const int from = w > 0.0 ? j : k;
            if (!edge(from)) carried(from, w, from == j ? F.aj : F.ak);  // the gas from an edge brings no oil
        } else {
            pushed(j, c[sf], F.aj);
            pushed(k, -c[sf], F.ak);
        }
        return F;
    }
    /// Face f's flow with the nodes' solved values in p and φ (m²/s, from node f to f + 1).
    double flow(int f) const {
        const Flux F = flux(f);
        auto u = [&](int i) { return partial[static_cast<std::size_t>(i)] ? phi[i] : p[i]; };
        return F.aj * u(f) + F.ak * u(f + 1) + F.b;
    }
};

// The open face's partition, settled as settleJfoPartition's without the gas's own
// rules (its pressures are given): a partial node with φ > 1 becomes full, a full node below its
// gas partial. storage Δx h/Δt and held Δx φₙ hₙ/Δt per inner node.
void settleOpenFace(const std::vector<double>& c, const std::vector<double>& q, const std::vector<double>& storage,
                    const std::vector<double>& held, const std::vector<double>& gas, Eigen::VectorXd& p,
                    Eigen::VectorXd& phi, std::vector<char>& partial) {
    const int n = static_cast<int>(p.size()), m = n - 2;
    partial.front() = partial.back() = 0;
    const auto size = static_cast<std::size_t>(m);
    std::vector<double> dl(size), dd(size), du(size), y(size);
    const OpenFace face{c, q, gas, partial, p, phi};
    const int passes = 4 * n;
    for (int pass = 0; pass < passes; ++pass) {
        // Each inner node's balance: storage φ_i − held = F_below − F_above.
        for (int k = 0; k < m; ++k) {
            const bool part = partial[static_cast<std::size_t>(k) + 1];
            dl[static_cast<std::size_t>(k)] = du[static_cast<std::size_t>(k)] = 0.0;
            dd[static_cast<std::size_t>(k)] = part ? storage[static_cast<std::size_t>(k)] : 0.0;
            y[static_cast<std::size_t>(k)] =
                held[static_cast<std::size_t>(k)] - (part ? 0.0 : storage[static_cast<std::size_t>(k)]);
        }
        for (int f = 0; f + 1 < n; ++f) {
            const OpenFace::Flux F = face.flux(f);
            if (f >= 1) {  // node j = f: + F
                const auto r = static_cast<std::size_t>(f) - 1;
                dd[r] += F.aj, y[r] -= F.b;
                if (f + 1 <= m) du[r] += F.ak;
            }
            if (f + 1 <= m) {  // node k = f + 1: − F
                const auto r = static_cast<std::size_t>(f);
                dd[r] -= F.ak, y[r] += F.b;
                if (f >= 1) dl[r] -= F.aj;
            }
        }
        tridiagonalSolve(dl, dd, du, y);
        bool changed = false;
        for (int i = 1; i <= m; ++i) {
            const auto si = static_cast<std::size_t>(i);
            const double v = y[si - 1];
            if (!std::isfinite(v))
                throw std::runtime_error("RingFilm: the face open to the gas: balance is singular (pass " +
                                         std::to_string(pass + 1) + ")");
            if (partial[si]) {
                p[i] = gas[si], phi[i] = v;
                if (v > 1.0) partial[si] = 0, changed = true;
            } else {
                p[i] = v, phi[i] = 1.0;
                if (v < gas[si]) partial[si] = 1, changed = true;
            }
        }
        for (int i = 1; i <= m; ++i) {  // a partial node its full neighbour emptied: the meniscus moves on
            if (!partial[static_cast<std::size_t>(i)] || !(y[static_cast<std::size_t>(i) - 1] < 0.0)) continue;
            for (const int b : {i - 1, i + 1})
                if (b >= 1 && b <= m && !partial[static_cast<std::size_t>(b)] &&
                    storage[static_cast<std::size_t>(b) - 1] > 0.0)
                    partial[static_cast<std::size_t>(b)] = 1, changed = true;
        }
        if (!changed) {
            for (int i = 1; i <= m; ++i) phi[i] = std::clamp(phi[i], 0.0, 1.0);
            return;
        }
    }
    throw std::runtime_error("RingFilm: the face open to the gas: full/partial partition did not settle in " +
                             std::to_string(passes) + " passes");
}

}  // namespace

RingFilm::RingFilm(RingFaceProfile profile, Lubricant lubricant, int nodes, double cavitationPressure, double roughness)
    : profile_(std::move(profile)), lubricant_(lubricant), pcav_(cavitationPressure), shear_(roughness) {
    if (nodes < 5) throw std::invalid_argument("RingFilm: at least 5 nodes across the face, got " + std::to_string(nodes));
    if (lubricant_.pressureDependent())
        throw std::invalid_argument("RingFilm: a constant-property lubricant only (no pressure-dependent viscosity)");
    x_ = Eigen::VectorXd::LinSpaced(nodes, profile_.lower(), profile_.upper());
    drop_.resize(nodes);
    for (int i = 0; i < nodes; ++i) drop_[i] = profile_.drop(x_[i]);
}

OpenGap openGap(const RingFilmResult& r) {
    OpenGap g;
    const Eigen::Index n = r.x.size();
    if (n < 2 || r.fraction.size() != n || r.h.size() != n) return g;
    // The edge nodes' fractions are the boundary's (a full film at the trailing edge's pressure):
    // there the gap is open as far as the oil next to the edge leaves it.
    Eigen::ArrayXd phi = r.fraction.array();
    if (n > 2) phi[0] = phi[1], phi[n - 1] = phi[n - 2];
    const Eigen::ArrayXd open = (1.0 - phi) * r.h.array();
    if (!(open.minCoeff() > 0.0)) return g;  // the oil fills the gap somewhere across the face
    const Eigen::ArrayXd w = open.cube().inverse();
    double integral = 0.0;
    for (Eigen::Index k = 0; k + 1 < n; ++k) integral += 0.5 * (w[k] + w[k + 1]) * (r.x[k + 1] - r.x[k]);
    g.resistance = integral;
    g.narrowest = open.minCoeff();
    return g;
}

RingFilmResult RingFilm::solve(const RingFilmState& s, std::vector<char>* cavitated) const {
    return solveWith(s, 0.0, nullptr, cavitated);
}

RingFilmResult RingFilm::step(const RingFilmState& s, double dt, const Eigen::VectorXd& previousFraction,
                             std::vector<char>* cavitated) const {
    if (std::isnan(s.supplyFilm))
        throw std::invalid_argument("RingFilm::step: a step of the film's content needs the supply film (mass-conserving)");
    if (!(dt > 0.0) || previousFraction.size() != x_.size())
        throw std::invalid_argument("RingFilm::step: a positive step and the previous film fraction on the " +
                                    std::to_string(x_.size()) + " nodes expected");
    return solveWith(s, dt, &previousFraction, cavitated);
}

RingFilmResult RingFilm::solveWith(const RingFilmState& s, double dt, const Eigen::VectorXd* previous,
                                   std::vector<char>* cavitated) const {
    if (!(s.minimumGap > 0.0) || !std::isfinite(s.minimumGap))
        throw std::invalid_argument("RingFilm: the minimum gap must be positive, got " + std::to_string(s.minimumGap));
    if (!std::isfinite(s.slidingSpeed) || !std::isfinite(s.squeezeRate) || !std::isfinite(s.pressureBelow) ||
        !std::isfinite(s.pressureAbove))
        throw std::invalid_argument("RingFilm: sliding speed, squeeze rate and edge pressures must be finite");
    const bool starved = !std::isnan(s.supplyFilm);
    if (starved && !(s.supplyFilm >= 0.0 && std::isfinite(s.supplyFilm)))
        throw std::invalid_argument("RingFilm: the supply film must be >= 0 m (or NaN: flooded), got " +
                                    std::to_string(s.supplyFilm));
    if (starved && s.squeezeRate != 0.0 && !previous)
        throw std::invalid_argument("RingFilm: the film fed by an oil layer solved steady: the squeeze rate must be 0 "
                                    "(RingFilm::step for a squeezing film)");
    const int n = static_cast<int>(x_.size());
    const double dx = x_[1] - x_[0];
    RingFilmResult r;
    r.x = x_;
    r.h = drop_.array() + s.minimumGap;
    if (starved) solveStarved(s, dt, previous, r, cavitated);
    else solveFlooded(s, r, cavitated);
    for (int i = 0; i + 1 < n; ++i) r.load += 0.5 * (r.p[i] + r.p[i + 1]) * dx;  // trapezoids between nodes
    if (s.withFriction) addFriction(s, r);
    return r;
}

void RingFilm::addFriction(const RingFilmState& s, RingFilmResult& r) const {
    const int n = static_cast<int>(x_.size());
    const double eta = lubricant_.referenceViscosity(), dx = x_[1] - x_[0];
    const bool starved = !std::isnan(s.supplyFilm);
    // The Couette shear sees the nominal gap (the film's may be floored): Patir & Cheng's factor
    // φ_f(h/σ)/h of the rough surfaces (docs/lube.md §5), 1/h when smooth.
    const double nominal = std::isnan(s.nominalGap) ? s.minimumGap : s.nominalGap;
    r.friction = 0.0;
    for (int i = 0; i + 1 < n; ++i) {  // trapezoids between nodes
        const double hm = 0.5 * (r.h[i] + r.h[i + 1]), dpdx = (r.p[i + 1] - r.p[i]) / dx;
        // Shear on the ring (u = 0) from the liner's Couette flow, on the oil (φ; none where the
        // Reynolds condition cavitates both nodes), and the Poiseuille flow.
        const bool cavitated = !starved && r.p[i] <= pcav_ && r.p[i + 1] <= pcav_;
        const double phi = cavitated ? 0.0 : 0.5 * (r.fraction[i] + r.fraction[i + 1]);
        double couette = 0.0, slope = 0.0;
        shear_.couette(nominal + 0.5 * (drop_[i] + drop_[i + 1]), couette, slope);
        r.friction += (phi * eta * s.slidingSpeed * couette - 0.5 * hm * dpdx) * dx;
    }
}

void RingFilm::solveStarved(const RingFilmState& s, double dt, const Eigen::VectorXd* previous, RingFilmResult& r,
                            std::vector<char>* cavitated) const {
    const int n = static_cast<int>(x_.size());
    const double eta = lubricant_.referenceViscosity();
    // The leading edge (where the liner comes from) takes in the layer's flux U t: its inlet
    // fraction makes the Couette inflow (|U|/2) h_f φ_in carry it; the other edge's is 1.
    const int lead = s.slidingSpeed >= 0.0 ? 0 : n - 1, next = lead == 0 ? 1 : n - 2;
    const double inlet = std::min(1.0, 2.0 * s.supplyFilm / (0.5 * (r.h[lead] + r.h[next])));
    r.p.resize(n);
    r.fraction.resize(n);
    r.p[0] = std::max(s.pressureBelow, pcav_);
    r.p[n - 1] = std::max(s.pressureAbove, pcav_);
    r.fraction[0] = lead == 0 ? inlet : 1.0;
    r.fraction[n - 1] = lead == n - 1 ? inlet : 1.0;
    // Faces f = i + ½: conductance h_f³/(12 η Δx_f) and Couette coefficient (U/2) h_f.
    std::vector<double> c(static_cast<std::size_t>(n - 1)), q(static_cast<std::size_t>(n - 1));
    for (int f = 0; f + 1 < n; ++f) {
        const double hf = 0.5 * (r.h[f] + r.h[f + 1]);
        c[static_cast<std::size_t>(f)] = hf * hf * hf / (12.0 * eta * (x_[f + 1] - x_[f]));
        q[static_cast<std::size_t>(f)] = 0.5 * s.slidingSpeed * hf;
    }
    // The balance of each inner node (docs/lube.md §3b); a step's content term with the face's
    // last gap h_min − Δt ḣ_min.
    std::vector<JfoRow> rows(static_cast<std::size_t>(n - 2));
    std::vector<double> storage(rows.size()), held(rows.size());
    for (int i = 1; i + 1 < n; ++i) {
        const double width = 0.5 * (x_[i + 1] - x_[i - 1]);
        const auto f = static_cast<std::size_t>(i);  // the face above node i
        storage[f - 1] = previous ? width * r.h[i] / dt : 0.0;
        held[f - 1] = previous ? width * (*previous)[i] * (r.h[i] - dt * s.squeezeRate) / dt : 0.0;
        rows[f - 1] = jfoRow(c[f - 1], c[f], q[f - 1], q[f], storage[f - 1], held[f - 1]);
    }
    std::vector<char> own;
    std::vector<char>& cav = cavitated ? *cavitated : own;
    if (cav.size() != static_cast<std::size_t>(n)) {  // no start given: a step's partial nodes stay partial
        cav.assign(static_cast<std::size_t>(n), 0);
        if (previous)
            for (int i = 1; i + 1 < n; ++i) cav[static_cast<std::size_t>(i)] = (*previous)[i] < 1.0;
    }
    const std::vector<char> start = cav;
    try {
        settleJfoPartition(rows, pcav_, r.p, r.fraction, cav);
        // Partial from edge to edge between two gases: the gas passes the face.
        r.openToGas = previous && r.p[0] != r.p[n - 1] &&
                         std::all_of(cav.begin() + 1, cav.end() - 1, [](char v) { return v != 0; });
    } catch (const PartitionCycles&) {
        if (!previous) throw;  // a steady film has no last fraction to open the gap
        r.openToGas = true;
        cav = start;
    }
    std::vector<double> gas;  // the open face's gas pressures
    if (r.openToGas) {
        gas = openFaceGas(x_, r.h, *previous, r.p[0], r.p[n - 1], pcav_);
        settleOpenFace(c, q, storage, held, gas, r.p, r.fraction, cav);
    }
    r.oil = 0.0;
    for (int i = 1; i + 1 < n; ++i) r.oil += 0.5 * (x_[i + 1] - x_[i - 1]) * r.fraction[i] * r.h[i];
    // The edges' flows into the film with the scheme's face fluxes (Couette flux upwinded).
    if (r.openToGas) {  // the open face's edge fluxes
        const OpenFace face{c, q, gas, cav, r.p, r.fraction};
        r.inflowLow = face.flow(0);
        r.inflowHigh = -face.flow(n - 2);
    } else {
        const double qLow = q.front(), qHigh = q.back();
        r.inflowLow = c.front() * (r.p[0] - r.p[1]) + qLow * (qLow > 0.0 ? r.fraction[0] : r.fraction[1]);
        r.inflowHigh =
            -(c.back() * (r.p[n - 2] - r.p[n - 1]) + qHigh * (qHigh > 0.0 ? r.fraction[n - 2] : r.fraction[n - 1]));
    }
    r.inflow = r.inflowLow + r.inflowHigh;
}

void RingFilm::solveFlooded(const RingFilmState& s, RingFilmResult& r, std::vector<char>* cavitated) const {
    const int n = static_cast<int>(x_.size());
    const double eta = lubricant_.referenceViscosity(), dx = x_[1] - x_[0];
    // Faces f = i + ½: conductance c_f = h_f³/(12 η Δx), Couette flux (U/2) h_f; node i's balance
    // (c₋ + c₊) p_i − c₋ p_{i−1} − c₊ p_{i+1} = −(U/2)(h₊ − h₋) − Δx ∂h/∂t.
    std::vector<double> c(static_cast<std::size_t>(n - 1)), q(static_cast<std::size_t>(n - 1));
    for (int f = 0; f + 1 < n; ++f) {
        const double hf = 0.5 * (r.h[f] + r.h[f + 1]);
        c[static_cast<std::size_t>(f)] = hf * hf * hf / (12.0 * eta * dx);
        q[static_cast<std::size_t>(f)] = 0.5 * s.slidingSpeed * hf;
    }
    const double pLow = std::max(s.pressureBelow, pcav_), pHigh = std::max(s.pressureAbove, pcav_);
    // Primal–dual active set: nodes held at p_cav where the free solution falls below it; released
    // where the balance asks for more pressure than p_cav. The partition settles in a few passes,
    // from none held or from the caller's last one (the same solution: the problem's is unique).
    std::vector<char> own;
    std::vector<char>& held = cavitated ? *cavitated : own;
    if (held.size() != static_cast<std::size_t>(n)) held.assign(static_cast<std::size_t>(n), 0);
    std::vector<double> a(static_cast<std::size_t>(n)), b(static_cast<std::size_t>(n)), up(static_cast<std::size_t>(n)),
        rhs(static_cast<std::size_t>(n)), p(static_cast<std::size_t>(n));
    auto balance = [&](int i, const std::vector<double>& pv) {  // A p − b at node i
        const auto fm = static_cast<std::size_t>(i - 1), fp = static_cast<std::size_t>(i);
        return c[fm] * (pv[static_cast<std::size_t>(i)] - pv[fm]) + c[fp] * (pv[static_cast<std::size_t>(i)] - pv[fp + 1]) +
               q[fp] - q[fm] + dx * s.squeezeRate;
    };
    for (int pass = 0; pass < 4 * n; ++pass) {
        for (int i = 0; i < n; ++i) {
            const auto si = static_cast<std::size_t>(i);
            a[si] = up[si] = 0.0;
            if (i == 0 || i == n - 1 || held[si]) {
                b[si] = 1.0;
                rhs[si] = i == 0 ? pLow : i == n - 1 ? pHigh : pcav_;
                continue;
            }
            b[si] = c[si - 1] + c[si];
            a[si] = -c[si - 1];
            up[si] = -c[si];
            rhs[si] = -(q[si] - q[si - 1]) - dx * s.squeezeRate;
        }
        p = rhs;
        tridiagonalSolve(a, b, up, p);
        bool changed = false;
        for (int i = 1; i + 1 < n; ++i) {
            const auto si = static_cast<std::size_t>(i);
            if (!held[si] && p[si] < pcav_) held[si] = 1, changed = true;
            else if (held[si] && balance(i, p) < 0.0) held[si] = 0, changed = true;  // it wants p > p_cav
        }
        if (!changed) break;
        if (pass == 4 * n - 1) throw std::runtime_error("RingFilm: the cavitated set did not settle");
    }
    r.p = Eigen::Map<const Eigen::VectorXd>(p.data(), n);
    r.fraction = Eigen::VectorXd::Ones(n);
}

}  // namespace flexehd::lube
