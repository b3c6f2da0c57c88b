#include "lube/JfoSolver.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>

#include "lube/PsorSolver.hpp"
#include "lube/ReynoldsSolver.hpp"
#include "lube/ReynoldsSystem.hpp"

namespace flexehd::lube {

namespace {

using JfoMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using JfoLU = Eigen::SparseLU<JfoMatrix, Eigen::COLAMDOrdering<int>>;

// One face of the finite-volume scheme, volumetric: flow a → b = c (p_a − p_b) + q φ_up,
// φ_up = φ_a if q > 0 else φ_b.
struct Face {
    int a, b;
    double c, q;
};

std::vector<Face> buildFaces(const FilmGrid& g, const FilmState& film, double eta) {
    std::vector<Face> faces;
    faces.reserve(static_cast<std::size_t>(2 * g.size()));
    const double Uz = film.sumAxial(), Ut = film.sumCircumferential();
    forEachFace(g, [&](int a, int b, bool axial, double L, double d) {
        if (g.kind(a) != NodeKind::Film && g.kind(b) != NodeKind::Film) return;
        const double hf = faceValue(g, film.h, a, b);
        faces.push_back({a, b, hf * hf * hf * L / (12.0 * eta * d), 0.5 * (axial ? Uz : Ut) * hf * L});
    });
    return faces;
}

}  // namespace

JfoSolver::JfoSolver(FilmGrid grid, Lubricant lubricant, JfoOptions options)
    : grid_(std::move(grid)), lubricant_(lubricant), options_(options),
      inlet_(static_cast<std::size_t>(grid_.size()), 1.0) {
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
    if (!(fraction > 0.0 && fraction <= 1.0))
        throw std::invalid_argument("JfoSolver::setInletFraction: fraction must be in (0, 1], got " +
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
    const double pcav = options_.cavitationPressure, pAmb = g.ambientPressure();
    const std::vector<Face> faces = buildFaces(g, film, lubricant_.referenceViscosity());

    // Node → faces adjacency (CSR).
    std::vector<int> start(static_cast<std::size_t>(n) + 1, 0), adj(2 * faces.size());
    for (const Face& f : faces) {
        ++start[static_cast<std::size_t>(f.a) + 1];
        ++start[static_cast<std::size_t>(f.b) + 1];
    }
    for (int k = 0; k < n; ++k) start[static_cast<std::size_t>(k) + 1] += start[static_cast<std::size_t>(k)];
    {
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (std::size_t i = 0; i < faces.size(); ++i) {
            adj[static_cast<std::size_t>(fill[static_cast<std::size_t>(faces[i].a)]++)] = static_cast<int>(i);
            adj[static_cast<std::size_t>(fill[static_cast<std::size_t>(faces[i].b)]++)] = static_cast<int>(i);
        }
    }

    JfoResult res;
    const bool warm = warmStart && warmStart->pressure.size() == n && warmStart->fraction.size() == n;
    if (warm) {
        res.pressure = warmStart->pressure;
        res.fraction = warmStart->fraction;
    } else {
        res.pressure = Eigen::VectorXd::Constant(n, std::max(pcav, pAmb));
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
            res.fraction[k] = g.kind(k) == NodeKind::Void ? 0.0 : inlet_[static_cast<std::size_t>(k)];
        }
    }
    // Non-Film neighbours supply their inlet fraction (Void: a relief open to oil mist, 1).
    auto supplyFraction = [&](int m) {
        return g.kind(m) == NodeKind::Film ? res.fraction[m] : inlet_[static_cast<std::size_t>(m)];
    };
    double* p = res.pressure.data();
    double* phi = res.fraction.data();
    const double w = options_.omega > 0.0 ? options_.omega : PsorSolver::automaticOmega(g);

    // Balance of node k: F = D p_k − S + B φ_k − Sin (see header).
    struct Balance { double D, S, B, Sin; };
    auto balance = [&](int k) {
        Balance bl{0.0, 0.0, 0.0, 0.0};
        for (int q = start[static_cast<std::size_t>(k)]; q < start[static_cast<std::size_t>(k) + 1]; ++q) {
            const Face& f = faces[static_cast<std::size_t>(adj[static_cast<std::size_t>(q)])];
            const bool out = f.a == k;
            const int m = out ? f.b : f.a;
            const double qo = out ? f.q : -f.q;  // Couette coefficient of the flow out of k
            bl.D += f.c;
            bl.S += f.c * p[m];
            if (qo > 0.0) bl.B += qo;
            else bl.Sin -= qo * supplyFraction(m);
        }
        if (dt > 0.0) {
            const double V = g.area(k);
            bl.B += V * film.h[k] / dt;
            bl.Sin += V * previous->fraction[k] * previous->h[k] / dt;
        }
        return bl;
    };

    // The convergence criterion (header): scaled mass residual of the current iterate.
    auto residual = [&]() {
        double scale = 0.0, rmax = 0.0;
        for (int k = 0; k < n; ++k) scale = std::max(scale, std::abs(p[k] - pAmb));
        for (int k : rows) {
            const Balance bl = balance(k);
            const double F = bl.D * p[k] - bl.S + bl.B * phi[k] - bl.Sin;
            const bool full = phi[k] >= 1.0 && p[k] > pcav;
            const double r = (full || !(bl.B > 0.0)) ? std::abs(F) / bl.D / std::max(scale, 1e-300)
                                                     : std::abs(F) / bl.B;
            rmax = std::max(rmax, r);
        }
        return rmax;
    };

    if (options_.method == JfoMethod::ActiveSet) {
        if (!warm) {
            // Cold start from the Reynolds-condition solution (multigrid, nested): on a flooded
            // film its cavitated set is the JFO one but for the reformation fronts, so the
            // partition below is nearly right and a few factorizations suffice. (Should that
            // solve fail, the flooded start stays: more factorizations, same answer.)
            try {
                ReynoldsOptions ro;
                ro.solver = SolverKind::Multigrid;
                ro.cavitationPressure = pcav;
                ro.control.tolerance = 1e-6;
                ReynoldsSolver rs(g, lubricant_, ro);
                const Eigen::VectorXd pr = rs.solve(film).pressure;
                for (int k : rows) {
                    p[k] = std::max(pr[k], pcav);
                    phi[k] = pr[k] > pcav ? 1.0 : 0.5;
                }
            } catch (const std::exception&) {
            }
        }
        // Unknown of Film node k: p_k (full film) or φ_k (cavitated). Row k of the linear system
        // is the balance F_k = D p_k − Σ c_f p_m + B φ_k − Σ_in a_f φ_m − s_k = 0 (B: Couette
        // outflow + storage, a_f: Couette inflow coefficients, s_k: previous oil); known p, φ
        // (the other state's variable, non-Film neighbours) go to the right-hand side.
        const int nf = static_cast<int>(rows.size());
        std::vector<int> idx(static_cast<std::size_t>(n), -1);
        for (int r = 0; r < nf; ++r) idx[static_cast<std::size_t>(rows[static_cast<std::size_t>(r)])] = r;
        struct Link { int m; double c, a; double* value; };  // neighbour, Poiseuille, inflow Couette
        std::vector<Link> links;
        std::vector<int> linkStart(static_cast<std::size_t>(nf) + 1, 0);
        std::vector<double> D(static_cast<std::size_t>(nf)), B(static_cast<std::size_t>(nf)),
            known(static_cast<std::size_t>(nf)), store(static_cast<std::size_t>(nf));
        std::vector<Eigen::Triplet<double, int>> trip;
        for (int r = 0; r < nf; ++r) {
            const int k = rows[static_cast<std::size_t>(r)];
            double d = 0.0, b = 0.0, kn = 0.0;
            for (int q = start[static_cast<std::size_t>(k)]; q < start[static_cast<std::size_t>(k) + 1]; ++q) {
                const Face& f = faces[static_cast<std::size_t>(adj[static_cast<std::size_t>(q)])];
                const bool out = f.a == k;
                const int m = out ? f.b : f.a;
                const double qo = out ? f.q : -f.q;
                d += f.c;
                const double a = qo > 0.0 ? 0.0 : -qo;
                if (qo > 0.0) b += qo;
                if (g.kind(m) == NodeKind::Film) {
                    links.push_back({m, f.c, a, nullptr});
                    trip.emplace_back(r, idx[static_cast<std::size_t>(m)], 0.0);
                } else {
                    kn -= f.c * p[m] + a * inlet_[static_cast<std::size_t>(m)];
                }
            }
            double s0 = 0.0;
            if (dt > 0.0) {
                const double V = g.area(k);
                b += V * film.h[k] / dt;
                s0 = V * previous->fraction[k] * previous->h[k] / dt;
            }
            D[static_cast<std::size_t>(r)] = d;
            B[static_cast<std::size_t>(r)] = b;
            known[static_cast<std::size_t>(r)] = kn;
            store[static_cast<std::size_t>(r)] = s0;
            trip.emplace_back(r, r, 0.0);
            linkStart[static_cast<std::size_t>(r) + 1] = static_cast<int>(links.size());
        }
        JfoMatrix M(nf, nf);
        M.setFromTriplets(trip.begin(), trip.end());
        M.makeCompressed();
        std::vector<double*> diag(static_cast<std::size_t>(nf));
        for (int r = 0; r < nf; ++r) {
            diag[static_cast<std::size_t>(r)] = &M.coeffRef(r, r);
            for (int l = linkStart[static_cast<std::size_t>(r)]; l < linkStart[static_cast<std::size_t>(r) + 1]; ++l)
                links[static_cast<std::size_t>(l)].value = &M.coeffRef(r, idx[static_cast<std::size_t>(links[static_cast<std::size_t>(l)].m)]);
        }
        // Partition: cavitated where the film is partial (and a Couette outflow or storage term
        // can carry it: B > 0), full film elsewhere.
        std::vector<char> cav(static_cast<std::size_t>(nf));
        for (int r = 0; r < nf; ++r)
            cav[static_cast<std::size_t>(r)] = B[static_cast<std::size_t>(r)] > 0.0 && phi[rows[static_cast<std::size_t>(r)]] < 1.0;
        JfoLU lu;
        Eigen::VectorXd rhs(nf);
        for (int it = 1; it <= options_.maxActiveSetIterations; ++it) {
            for (int r = 0; r < nf; ++r) {
                const auto sr = static_cast<std::size_t>(r);
                const bool c = cav[sr];
                *diag[sr] = c ? B[sr] : D[sr];
                double kn = known[sr] + (c ? D[sr] * pcav : B[sr]);  // p_k = p_cav, or φ_k = 1
                for (int l = linkStart[sr]; l < linkStart[sr + 1]; ++l) {
                    Link& lk = links[static_cast<std::size_t>(l)];
                    if (cav[static_cast<std::size_t>(idx[static_cast<std::size_t>(lk.m)])]) {
                        *lk.value = -lk.a;
                        kn -= lk.c * pcav;
                    } else {
                        *lk.value = -lk.c;
                        kn -= lk.a;
                    }
                }
                rhs[r] = store[sr] - kn;
            }
            if (it == 1) lu.analyzePattern(M);  // fill-reducing ordering, once per solve
            lu.factorize(M);
            if (lu.info() != Eigen::Success)
                throw std::runtime_error("JfoSolver: sparse LU failed in active-set step " +
                                         std::to_string(it) + " (singular: a closed film-fraction "
                                         "loop with no supply, e.g. a steady film without inlet?)");
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
                    if (y[r] < pcav && B[sr] > 0.0) cav[sr] = 1, changed = true;
                }
            }
            if (!std::isfinite(y.sum()))
                throw std::runtime_error("JfoSolver: active-set step " + std::to_string(it) +
                                         " gave a non-finite solution");
            if (changed) continue;
            // Partition settled: the balances hold to round-off. Bounds as the Gauss–Seidel
            // iteration keeps them (a film fraction below 0 would be a dry node it clips).
            for (int r = 0; r < nf; ++r) {
                const int k = rows[static_cast<std::size_t>(r)];
                p[k] = std::max(p[k], pcav);
                phi[k] = std::clamp(phi[k], 0.0, 1.0);
            }
            res.residual = residual();
            if (res.residual <= options_.control.tolerance) return res;
            break;  // polish with Gauss–Seidel sweeps
        }
        for (int r = 0; r < nf; ++r) {  // the sweeps start from a feasible iterate
            const int k = rows[static_cast<std::size_t>(r)];
            p[k] = std::max(p[k], pcav);
            phi[k] = std::clamp(phi[k], 0.0, 1.0);
        }
    }

    const int checkEvery = 10;
    double first = -1.0;
    for (int it = 1; it <= options_.control.maxIterations; ++it) {
        for (int k : rows) {
            const Balance bl = balance(k);
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
        if (it % checkEvery != 0 && it != options_.control.maxIterations) continue;
        const double rmax = residual();
        res.iterations = it;
        res.residual = rmax;
        if (first < 0.0) first = rmax;
        if (!std::isfinite(rmax) || rmax > 1e8 * std::max(first, 1.0))
            throw std::runtime_error("JfoSolver: diverged after " + std::to_string(it) +
                                     " sweeps (residual " + std::to_string(rmax) + ", omega " +
                                     std::to_string(w) + ")");
        if (rmax <= options_.control.tolerance) return res;
    }
    throw std::runtime_error("JfoSolver: not converged after " +
                             std::to_string(options_.control.maxIterations) +
                             " sweeps (residual " + std::to_string(res.residual) +
                             " > tolerance " + std::to_string(options_.control.tolerance) +
                             ", omega " + std::to_string(w) + ")");
}

double JfoSolver::oilVolume(const FilmState& film, const Eigen::VectorXd& fraction) const {
    double v = 0.0;
    for (int k = 0; k < grid_.size(); ++k)
        if (grid_.kind(k) == NodeKind::Film) v += grid_.area(k) * fraction[k] * film.h[k];
    return v;
}

double JfoSolver::boundaryInflow(const FilmState& film, const JfoResult& r) const {
    const std::vector<Face> faces = buildFaces(grid_, film, lubricant_.referenceViscosity());
    double q = 0.0;
    for (const Face& f : faces) {
        const bool fa = grid_.kind(f.a) == NodeKind::Film, fb = grid_.kind(f.b) == NodeKind::Film;
        if (fa == fb) continue;
        const double phiA = fa ? r.fraction[f.a] : inlet_[static_cast<std::size_t>(f.a)];
        const double phiB = fb ? r.fraction[f.b] : inlet_[static_cast<std::size_t>(f.b)];
        const double ab = f.c * (r.pressure[f.a] - r.pressure[f.b]) + f.q * (f.q > 0.0 ? phiA : phiB);
        q += fb ? ab : -ab;  // into the Film node
    }
    return q;
}

}  // namespace flexehd::lube
