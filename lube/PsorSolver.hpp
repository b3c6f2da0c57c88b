#pragma once
// PsorSolver: projected successive over-relaxation (Cryer 1971), the seed's method and our
// reference baseline for the cavitation complementarity problem of ReynoldsSystem:
//   p_k ← max(p_cav, p_k + ω (b_k − Σ_l A_kl p_l) / A_kk)       (Gauss–Seidel order k = 0..N−1)
// Without a bound (pLower = −∞) it is plain SOR. The residual is evaluated every `checkEvery`
// sweeps; a non-finite or exploding residual, or no convergence within maxIterations, throws.
#include <Eigen/Core>

#include "lube/ReynoldsSystem.hpp"
#include "lube/SolverControl.hpp"

namespace flexehd::lube {

class PsorSolver {
public:
    /// omega in (0, 2); 0 selects automaticOmega(grid) at each solve.
    explicit PsorSolver(double omega = 0.0, int checkEvery = 10);

    /// Solves in place; p holds the warm start on entry (its Fixed/Void entries are reset).
    SolveReport solve(const ReynoldsSystem& system, Eigen::VectorXd& p, double pLower,
                      const SolverControl& control) const;

    /// ω = 2/(1 + sin(π/n)), the optimum for a Laplacian on n nodes across the widest
    /// direction (n = nAxial, or nTheta/2 for a periodic circumference, whichever is larger).
    static double automaticOmega(const FilmGrid& grid);

private:
    double omega_;
    int checkEvery_;
};

}  // namespace flexehd::lube
