#include "lube/PsorSolver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::lube {

PsorSolver::PsorSolver(double omega, int checkEvery) : omega_(omega), checkEvery_(checkEvery) {
    if (omega != 0.0 && !(omega > 0.0 && omega < 2.0))
        throw std::invalid_argument("PsorSolver: omega must be in (0, 2) or 0 (automatic), got " +
                                    std::to_string(omega));
    if (checkEvery < 1)
        throw std::invalid_argument("PsorSolver: checkEvery must be >= 1");
}

double PsorSolver::automaticOmega(const FilmGrid& grid) {
    const double n = std::max<double>(grid.nAxial(), grid.periodic() ? 0.5 * grid.nTheta()
                                                                      : grid.nTheta());
    return 2.0 / (1.0 + std::sin(3.14159265358979323846 / std::max(n, 2.0)));
}

SolveReport PsorSolver::solve(const ReynoldsSystem& sys, Eigen::VectorXd& p, double pLower,
                              const SolverControl& control) const {
    const FilmGrid& g = sys.grid();
    const int n = g.size();
    if (p.size() != n) p = sys.initialGuess(pLower);
    for (int k = 0; k < n; ++k)
        if (!sys.isFilm(k)) p[k] = g.prescribedPressure(k);
        else if (p[k] < pLower) p[k] = pLower;
    const double w = omega_ > 0.0 ? omega_ : automaticOmega(g);
    const SparseMatrix& A = sys.matrix();  // symmetric: column k is row k
    const double* val = A.valuePtr();
    const int* inner = A.innerIndexPtr();
    const int* outer = A.outerIndexPtr();
    const double* b = sys.rhs().data();
    std::vector<int> rows;
    rows.reserve(static_cast<std::size_t>(n));
    std::vector<double> invDiag(static_cast<std::size_t>(n), 0.0);
    for (int k = 0; k < n; ++k)
        if (sys.isFilm(k)) {
            rows.push_back(k);
            invDiag[static_cast<std::size_t>(k)] = 1.0 / sys.diagonal()[k];
        }
    const bool bounded = std::isfinite(pLower);
    double* x = p.data();

    SolveReport rep;
    double first = -1.0;
    for (int it = 1; it <= control.maxIterations; ++it) {
        for (int k : rows) {
            double s = b[k];
            for (int q = outer[k]; q < outer[k + 1]; ++q)
                if (inner[q] != k) s -= val[q] * x[inner[q]];
            double v = x[k] + w * (s * invDiag[static_cast<std::size_t>(k)] - x[k]);
            if (bounded && v < pLower) v = pLower;
            x[k] = v;
        }
        if (it % checkEvery_ == 0 || it == control.maxIterations) {
            rep.iterations = it;
            rep.residual = sys.residual(p, pLower);
            if (first < 0.0) first = rep.residual;
            if (!std::isfinite(rep.residual) || rep.residual > 1e8 * std::max(first, 1.0))
                throw std::runtime_error("PsorSolver: diverged after " + std::to_string(it) +
                                         " sweeps (residual " + messageNumber(rep.residual) +
                                         ", omega " + messageNumber(w) + ")");
            if (rep.residual <= control.tolerance) return rep;
        }
    }
    throw std::runtime_error("PsorSolver: not converged after " +
                             std::to_string(control.maxIterations) + " sweeps (residual " +
                             messageNumber(rep.residual) + " > tolerance " +
                             messageNumber(control.tolerance) + ", omega " +
                             messageNumber(w) + ")");
}

}  // namespace flexehd::lube
