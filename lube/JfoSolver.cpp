#include "lube/JfoSolver.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>

#include "lube/PsorSolver.hpp"
#include "lube/ReynoldsSolver.hpp"
#include "lube/ReynoldsSystem.hpp"
#include "lube/SparseLuFactor.hpp"

namespace flexehd::lube {

namespace {

using JfoMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// One face of the finite-volume scheme, volumetric: flow a → b = c (p_a − p_b) + q φ_up,
// φ_up = φ_a if q > 0 else φ_b.
struct Face {
    int a, b;
    double c, q;
};

}  // namespace

// The faces of the grid's finite volumes that touch a Film node and the node → face adjacency
// (CSR): fixed for a grid, built once per solver.
struct JfoTopology {
    struct FaceGeometry {
        int a, b;
        bool axial;
        double L, d;  // face length and distance (m)
    };
    std::vector<FaceGeometry> faces;
    std::vector<int> start, adj;
    std::vector<double> area;  // control-volume area per node (m²)

    explicit JfoTopology(const FilmGrid& g) {
        for (int k = 0; k < g.size(); ++k) area.push_back(g.area(k));
        forEachFace(g, [&](int a, int b, bool axial, double L, double d) {
            if (g.kind(a) != NodeKind::Film && g.kind(b) != NodeKind::Film) return;
            faces.push_back({a, b, axial, L, d});
        });
        const int n = g.size();
        start.assign(static_cast<std::size_t>(n) + 1, 0);
        adj.resize(2 * faces.size());
        for (const FaceGeometry& f : faces) {
            ++start[static_cast<std::size_t>(f.a) + 1];
            ++start[static_cast<std::size_t>(f.b) + 1];
        }
        for (int k = 0; k < n; ++k) start[static_cast<std::size_t>(k) + 1] += start[static_cast<std::size_t>(k)];
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (std::size_t i = 0; i < faces.size(); ++i) {
            adj[static_cast<std::size_t>(fill[static_cast<std::size_t>(faces[i].a)]++)] = static_cast<int>(i);
            adj[static_cast<std::size_t>(fill[static_cast<std::size_t>(faces[i].b)]++)] = static_cast<int>(i);
        }
    }
};

namespace {

std::vector<Face> buildFaces(const JfoTopology& t, const FilmGrid& g, const FilmState& film, double eta) {
    std::vector<Face> faces;
    faces.reserve(t.faces.size());
    const double Uz = film.sumAxial(), Ut = film.sumCircumferential();
    for (const JfoTopology::FaceGeometry& f : t.faces) {
        const double hf = faceValue(g, film.h, f.a, f.b);
        faces.push_back({f.a, f.b, hf * hf * hf * f.L / (12.0 * eta * f.d), 0.5 * (f.axial ? Uz : Ut) * hf * f.L});
    }
    return faces;
}

// The discrete JFO problem of one solve (docs/lube.md, the JFO scheme): the faces, the node → face
// adjacency and the storage terms; the balance of a node and the scaled mass residual.
class JfoNetwork {
public:
    // Balance of node k: F = D p_k − S + B φ_k − Sin (see the header).
    struct Balance { double D, S, B, Sin; };

    JfoNetwork(const JfoTopology& t, const FilmGrid& g, const FilmState& film, double eta, double dt,
               const JfoState* previous, const std::vector<double>& inlet, double pcav)
        : g_(g), film_(film), dt_(dt), previous_(previous), inlet_(inlet), pcav_(pcav),
          faces_(buildFaces(t, g, film, eta)), start_(t.start), adj_(t.adj), area_(t.area.data()) {}

    // visit(m, c, qo) for each face of node k: its other node m, Poiseuille coefficient c and the
    // Couette coefficient qo of the flow out of k.
    template <class Visit>
    void forFaces(int k, Visit visit) const {
        for (int q = start_[static_cast<std::size_t>(k)]; q < start_[static_cast<std::size_t>(k) + 1]; ++q) {
            const Face& f = faces_[static_cast<std::size_t>(adj_[static_cast<std::size_t>(q)])];
            const bool out = f.a == k;
            visit(out ? f.b : f.a, f.c, out ? f.q : -f.q);
        }
    }
    // Storage V h/dt of node k and the oil V φ_prev h_prev/dt it held (0, 0 when steady).
    double storage(int k) const { return dt_ > 0.0 ? area_[k] * film_.h[k] / dt_ : 0.0; }
    double previousOil(int k) const {
        return dt_ > 0.0 ? area_[k] * previous_->fraction[k] * previous_->h[k] / dt_ : 0.0;
    }
    bool transient() const { return dt_ > 0.0; }
    double area(int k) const { return area_[k]; }
    double inlet(int m) const { return inlet_[static_cast<std::size_t>(m)]; }

    Balance balance(int k, const double* p, const double* phi) const {
        Balance bl{0.0, 0.0, 0.0, 0.0};
        forFaces(k, [&](int m, double c, double qo) {
            bl.D += c;
            bl.S += c * p[m];
            if (qo > 0.0) bl.B += qo;
            else bl.Sin -= qo * (g_.kind(m) == NodeKind::Film ? phi[m] : inlet(m));  // non-Film: its inlet fraction
        });
        if (transient()) {
            bl.B += storage(k);
            bl.Sin += previousOil(k);
        }
        return bl;
    }

    // The convergence criterion (header): scaled mass residual of the iterate.
    double residual(const std::vector<int>& rows, const double* p, const double* phi) const {
        const double pAmb = g_.ambientPressure();
        double scale = 0.0, rmax = 0.0;
        for (int k = 0; k < g_.size(); ++k) scale = std::max(scale, std::abs(p[k] - pAmb));
        for (int k : rows) {
            const Balance bl = balance(k, p, phi);
            const double F = bl.D * p[k] - bl.S + bl.B * phi[k] - bl.Sin;
            const bool full = phi[k] >= 1.0 && p[k] > pcav_;
            const double r = (full || !(bl.B > 0.0)) ? std::abs(F) / bl.D / std::max(scale, 1e-300)
                                                     : std::abs(F) / bl.B;
            rmax = std::max(rmax, r);
        }
        return rmax;
    }

private:
    const FilmGrid& g_;
    const FilmState& film_;
    double dt_;
    const JfoState* previous_;
    const std::vector<double>& inlet_;
    double pcav_;
    std::vector<Face> faces_;
    const std::vector<int>& start_;
    const std::vector<int>& adj_;
    const double* area_;
};

// The iterate a solve starts from (the warm start, else a flooded film) with the bounds and the
// non-Film nodes' values imposed; returns the Film nodes.
std::vector<int> startingIterate(const FilmGrid& g, const JfoResult* warmStart, const std::vector<double>& inlet,
                                 double pcav, JfoResult& res) {
    const int n = g.size();
    if (warmStart) {
        res.pressure = warmStart->pressure;
        res.fraction = warmStart->fraction;
    } else {
        res.pressure = Eigen::VectorXd::Constant(n, std::max(pcav, g.ambientPressure()));
        res.fraction = Eigen::VectorXd::Ones(n);
    }
    std::vector<int> rows;
    for (int k = 0; k < n; ++k) {
        if (g.kind(k) == NodeKind::Film) {
            rows.push_back(k);
            res.pressure[k] = std::max(res.pressure[k], pcav);
            res.fraction[k] = std::clamp(res.fraction[k], 0.0, 1.0);
        } else {
            res.pressure[k] = g.prescribedPressure(k);
            res.fraction[k] = g.kind(k) == NodeKind::Void ? 0.0 : inlet[static_cast<std::size_t>(k)];
        }
    }
    return rows;
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

// The active-set linear system over the Film nodes. Unknown of Film node k: p_k (full film) or
// φ_k (cavitated). Row k is the balance F_k = D p_k − Σ c_f p_m + B φ_k − Σ_in a_f φ_m − s_k = 0
// (B: Couette outflow + storage, a_f: Couette inflow coefficients, s_k: previous oil); known p,
// φ (the other state's variable, non-Film neighbours) go to the right-hand side. The matrix's
// pattern is fixed; each partition rewrites its values through the kept pointers.
class ActiveSetSystem {
public:
    ActiveSetSystem(const JfoNetwork& net, const FilmGrid& g, const std::vector<int>& rows, const double* p)
        : nf_(static_cast<int>(rows.size())) {
        const int n = g.size();
        idx_.assign(static_cast<std::size_t>(n), -1);
        for (int r = 0; r < nf_; ++r) idx_[static_cast<std::size_t>(rows[static_cast<std::size_t>(r)])] = r;
        linkStart_.assign(static_cast<std::size_t>(nf_) + 1, 0);
        D_.resize(static_cast<std::size_t>(nf_));
        B_.resize(static_cast<std::size_t>(nf_));
        known_.resize(static_cast<std::size_t>(nf_));
        store_.resize(static_cast<std::size_t>(nf_));
        std::vector<Eigen::Triplet<double, int>> trip;
        for (int r = 0; r < nf_; ++r) {
            const int k = rows[static_cast<std::size_t>(r)];
            double d = 0.0, b = 0.0, kn = 0.0;
            net.forFaces(k, [&](int m, double c, double qo) {
                d += c;
                const double a = qo > 0.0 ? 0.0 : -qo;
                if (qo > 0.0) b += qo;
                if (g.kind(m) == NodeKind::Film) {
                    links_.push_back({m, c, a, nullptr});
                    trip.emplace_back(r, idx_[static_cast<std::size_t>(m)], 0.0);
                } else {
                    kn -= c * p[m] + a * net.inlet(m);
                }
            });
            b += net.storage(k);
            D_[static_cast<std::size_t>(r)] = d;
            B_[static_cast<std::size_t>(r)] = b;
            known_[static_cast<std::size_t>(r)] = kn;
            store_[static_cast<std::size_t>(r)] = net.previousOil(k);
            trip.emplace_back(r, r, 0.0);
            linkStart_[static_cast<std::size_t>(r) + 1] = static_cast<int>(links_.size());
        }
        M_.resize(nf_, nf_);
        M_.setFromTriplets(trip.begin(), trip.end());
        M_.makeCompressed();
        diag_.resize(static_cast<std::size_t>(nf_));
        for (int r = 0; r < nf_; ++r) {
            diag_[static_cast<std::size_t>(r)] = &M_.coeffRef(r, r);
            for (int l = linkStart_[static_cast<std::size_t>(r)]; l < linkStart_[static_cast<std::size_t>(r) + 1]; ++l)
                links_[static_cast<std::size_t>(l)].value =
                    &M_.coeffRef(r, idx_[static_cast<std::size_t>(links_[static_cast<std::size_t>(l)].m)]);
        }
    }

    int size() const { return nf_; }
    double B(int r) const { return B_[static_cast<std::size_t>(r)]; }

    // The matrix and right-hand side of the partition cav (1: cavitated row).
    void setPartition(const std::vector<char>& cav, double pcav, Eigen::VectorXd& rhs) {
        rhs.resize(nf_);
        for (int r = 0; r < nf_; ++r) {
            const auto sr = static_cast<std::size_t>(r);
            const bool c = cav[sr];
            *diag_[sr] = c ? B_[sr] : D_[sr];
            double kn = known_[sr] + (c ? D_[sr] * pcav : B_[sr]);  // p_k = p_cav, or φ_k = 1
            for (int l = linkStart_[sr]; l < linkStart_[sr + 1]; ++l) {
                Link& lk = links_[static_cast<std::size_t>(l)];
                if (cav[static_cast<std::size_t>(idx_[static_cast<std::size_t>(lk.m)])]) {
                    *lk.value = -lk.a;
                    kn -= lk.c * pcav;
                } else {
                    *lk.value = -lk.c;
                    kn -= lk.a;
                }
            }
            rhs[r] = store_[sr] - kn;
        }
    }
    const JfoMatrix& matrix() const { return M_; }

private:
    struct Link { int m; double c, a; double* value; };  // neighbour, Poiseuille, inflow Couette
    int nf_;
    std::vector<int> idx_, linkStart_;
    std::vector<Link> links_;
    std::vector<double> D_, B_, known_, store_;
    JfoMatrix M_;
    std::vector<double*> diag_;
};

// Clips the Film nodes to the bounds the Gauss–Seidel iteration keeps (a film fraction below 0
// would be a dry node it clips).
void clipToBounds(const std::vector<int>& rows, double pcav, double* p, double* phi) {
    for (int k : rows) {
        p[k] = std::max(p[k], pcav);
        phi[k] = std::clamp(phi[k], 0.0, 1.0);
    }
}

// JfoMethod::ActiveSet: the partition full film / cavitated solved and updated until it settles;
// true when the settled iterate meets the tolerance (else the sweeps polish it, from a feasible
// iterate).
bool activeSetSolve(const JfoNetwork& net, const FilmGrid& g, const std::vector<int>& rows, const JfoOptions& o,
                    SparseLuFactor& lu, JfoResult& res) {
    const double pcav = o.cavitationPressure;
    double* p = res.pressure.data();
    double* phi = res.fraction.data();
    ActiveSetSystem sys(net, g, rows, p);
    const int nf = sys.size();
    // Partition: cavitated where the film is partial (and a Couette outflow or storage term
    // can carry it: B > 0), full film elsewhere.
    std::vector<char> cav(static_cast<std::size_t>(nf));
    for (int r = 0; r < nf; ++r) cav[static_cast<std::size_t>(r)] = sys.B(r) > 0.0 && phi[rows[static_cast<std::size_t>(r)]] < 1.0;
    Eigen::VectorXd rhs;
    for (int it = 1; it <= o.maxActiveSetIterations; ++it) {
        sys.setPartition(cav, pcav, rhs);
        if (!lu.factor(sys.matrix()))  // the ordering kept while the pattern (the Film nodes) is the same
            throw std::runtime_error("JfoSolver: sparse LU failed in active-set step " + std::to_string(it) +
                                     " (singular: a closed film-fraction loop with no supply, e.g. a steady "
                                     "film without inlet?)");
        const Eigen::VectorXd y = lu.solve(rhs);
        res.factorizations = it;
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
        if (!std::isfinite(y.sum()))
            throw std::runtime_error("JfoSolver: active-set step " + std::to_string(it) +
                                     " gave a non-finite solution");
        if (changed) continue;
        // Partition settled: the balances hold to round-off.
        clipToBounds(rows, pcav, p, phi);
        res.residual = net.residual(rows, p, phi);
        if (res.residual <= o.control.tolerance) return true;
        break;  // polish with Gauss–Seidel sweeps
    }
    clipToBounds(rows, pcav, p, phi);
    return false;
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
                             " sweeps (residual " + std::to_string(res.residual) + " > tolerance " +
                             std::to_string(o.control.tolerance) + ", omega " + std::to_string(w) + ")");
}

// The effective squeeze rate that turns the Reynolds-condition problem into the JFO balance of
// every full-film node (docs/lube.md §3b, "the multigrid method"): the content term
// (h − φₙhₙ)/Δt and the Couette inflow an upstream partial film (or starved inlet) does not bring,
// Σ_in q_f (1 − φ_up)/V_k.
void effectiveSqueeze(const JfoNetwork& net, const FilmGrid& g, const FilmState& film, double dt,
                      const JfoState* previous, const std::vector<int>& rows, const double* phi, Eigen::VectorXd& dhdt) {
    dhdt.setZero(g.size());
    for (int k : rows) {
        double missing = 0.0;
        net.forFaces(k, [&](int m, double, double qo) {
            if (qo < 0.0) missing -= qo * (1.0 - (g.kind(m) == NodeKind::Film ? phi[m] : net.inlet(m)));
        });
        dhdt[k] = missing / net.area(k);
        if (dt > 0.0) dhdt[k] += (film.h[k] - previous->fraction[k] * previous->h[k]) / dt;
    }
}

// One Gauss–Seidel pass of the nodal JFO update (Ausas et al.; without over-relaxation) in the
// direction of the Couette flow: each node's upstream neighbours are updated before it, so the
// film fraction is transported through the cavities and a rupture or reformation front moves as
// far as the flow carries it in one pass (repeated until φ no longer changes where the flow has
// a circumferential part; once where it is axial only).
void sweepAlongFlow(const JfoNetwork& net, const FilmGrid& g, const FilmState& film, double pcav, double* p,
                    double* phi) {
    const int nz = g.nAxial(), nt = g.nTheta();
    const bool downZ = film.sumAxial() < 0.0, downT = film.sumCircumferential() < 0.0;
    for (int sweep = 0; sweep < 200; ++sweep) {
        double change = 0.0;
        for (int ii = 0; ii < nz; ++ii) {
            const int i = downZ ? nz - 1 - ii : ii;
            for (int jj = 0; jj < nt; ++jj) {
                const int k = g.index(i, downT ? nt - 1 - jj : jj);
                if (g.kind(k) != NodeKind::Film) continue;
                const JfoNetwork::Balance bl = net.balance(k, p, phi);
                const double phiStar = bl.B > 0.0 ? (bl.S + bl.Sin - bl.D * pcav) / bl.B : 1.0;
                const double before = phi[k];
                if (bl.B > 0.0 && phiStar < 1.0) {  // cavitated: p = p_cav, φ from the balance
                    p[k] = pcav;
                    phi[k] = std::max(phiStar, 0.0);
                } else {                            // full film: φ = 1, p from the balance
                    if (bl.B > 0.0) phi[k] = 1.0;
                    p[k] = std::max(pcav, (bl.S + bl.Sin - bl.B * phi[k]) / bl.D);
                }
                change = std::max(change, std::abs(phi[k] - before));
            }
        }
        if (change <= 1e-15 || film.sumCircumferential() == 0.0) return;
    }
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
    for (int outer = 1; outer <= o.maxMultigridPasses; ++outer) {
        effectiveSqueeze(net, g, film, dt, previous, rows, res.fraction.data(), eff.dhdt);
        // Cold, the first pass is the multigrid's own cold start (nested from the coarse grids).
        res.pressure = rs.solve(eff, warmStarted || outer > 1 ? &warm : nullptr).pressure;
        warm = res.pressure;
        sweepAlongFlow(net, g, film, pcav, res.pressure.data(), res.fraction.data());
        res.iterations = outer;
        res.residual = net.residual(rows, res.pressure.data(), res.fraction.data());
        if (res.residual <= o.control.tolerance) return true;
        // Stalled (a front alternating between two nodes, as at the meniscus of a steady starved
        // film): the active set takes over.
        history.push_back(res.residual);
        if (history.size() >= 4 && res.residual > 0.5 * history[history.size() - 4]) return false;
    }
    return false;
}

}  // namespace


JfoSolver::JfoSolver(FilmGrid grid, Lubricant lubricant, JfoOptions options)
    : grid_(std::move(grid)), lubricant_(lubricant), options_(options),
      inlet_(static_cast<std::size_t>(grid_.size()), 1.0), lu_(std::make_unique<SparseLuFactor>()) {
    topology_ = std::make_unique<JfoTopology>(grid_);
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
    const JfoNetwork net(*topology_, g, film, lubricant_.referenceViscosity(), dt, previous, inlet_, pcav);
    JfoResult res;
    const bool warm = warmStart && warmStart->pressure.size() == n && warmStart->fraction.size() == n;
    const std::vector<int> rows = startingIterate(g, warm ? warmStart : nullptr, inlet_, pcav, res);
    if (options_.method == JfoMethod::Multigrid) {
        if (!multigrid_) {
            ReynoldsOptions ro;
            ro.solver = SolverKind::Multigrid;
            ro.fallback = SolverKind::ActiveSet;
            ro.cavitationPressure = pcav;
            ro.control.tolerance = options_.control.tolerance;
            multigrid_ = std::make_unique<ReynoldsSolver>(g, lubricant_, ro);
        }
        if (multigridSolve(net, g, film, dt, previous, rows, options_, warm, *multigrid_, res)) return res;
    }
    if (options_.method != JfoMethod::GaussSeidel) {
        if (!warm && options_.method == JfoMethod::ActiveSet)
            reynoldsConditionStart(g, lubricant_, film, pcav, rows, res.pressure.data(), res.fraction.data());
        if (activeSetSolve(net, g, rows, options_, *lu_, res)) return res;
    }
    const double w = options_.omega > 0.0 ? options_.omega : PsorSolver::automaticOmega(g);
    gaussSeidelSolve(net, rows, options_, w, res);
    return res;
}

JfoSolver::~JfoSolver() = default;
JfoSolver::JfoSolver(JfoSolver&&) noexcept = default;

double JfoSolver::oilVolume(const FilmState& film, const Eigen::VectorXd& fraction) const {
    double v = 0.0;
    for (int k = 0; k < grid_.size(); ++k)
        if (grid_.kind(k) == NodeKind::Film) v += grid_.area(k) * fraction[k] * film.h[k];
    return v;
}

double JfoSolver::boundaryInflow(const FilmState& film, const JfoResult& r) const {
    return boundaryFlows(film, r).sum();
}

Eigen::VectorXd JfoSolver::boundaryFlows(const FilmState& film, const JfoResult& r) const {
    const std::vector<Face> faces = buildFaces(*topology_, grid_, film, lubricant_.referenceViscosity());
    Eigen::VectorXd q = Eigen::VectorXd::Zero(grid_.size());
    for (const Face& f : faces) {
        const bool fa = grid_.kind(f.a) == NodeKind::Film, fb = grid_.kind(f.b) == NodeKind::Film;
        if (fa == fb) continue;
        const double phiA = fa ? r.fraction[f.a] : inlet_[static_cast<std::size_t>(f.a)];
        const double phiB = fb ? r.fraction[f.b] : inlet_[static_cast<std::size_t>(f.b)];
        const double ab = f.c * (r.pressure[f.a] - r.pressure[f.b]) + f.q * (f.q > 0.0 ? phiA : phiB);
        if (fb) q[f.a] += ab;  // from the boundary node a into the Film node b
        else q[f.b] -= ab;
    }
    return q;
}

}  // namespace flexehd::lube
