#include "lube/JfoSolver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "lube/PsorSolver.hpp"
#include "lube/ReynoldsSystem.hpp"

namespace flexehd::lube {

namespace {

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
    if (warmStart && warmStart->pressure.size() == n && warmStart->fraction.size() == n) {
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
