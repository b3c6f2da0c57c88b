#pragma once
// ActiveSetSolver: the fast solver for the cavitation complementarity problem of ReynoldsSystem,
// a primal–dual active-set method (Hintermüller, Ito & Kunisch 2003, a semismooth Newton method
// for min(p − p_cav, w) = 0) on a sparse Cholesky factorization (CHOLMOD, supernodal).
//
//   cavitated set  C = { k Film : w_k / A_kk > p_k − p_cav },  w = A p − b
//   solve          p_k = p_cav on C,  (A p)_k = b_k off C         (one factorization)
// until C repeats. For an M-matrix (our A) it converges in finitely many steps from any start
// and monotonically after the first; a warm start with the previous solution typically needs
// 1–3 factorizations. Rows of C are decoupled in place, so the sparsity pattern never changes:
// the symbolic analysis (fill-reducing ordering) is done once per grid and reused.
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "lube/ReynoldsSystem.hpp"
#include "lube/SolverControl.hpp"

namespace flexehd::lube {

class ActiveSetSolver {
public:
    ActiveSetSolver();
    ~ActiveSetSolver();
    ActiveSetSolver(ActiveSetSolver&&) noexcept;
    ActiveSetSolver& operator=(ActiveSetSolver&&) noexcept;

    /// Solves in place; p holds the warm start on entry (empty: cold start, p = p_cav).
    /// pLower = −∞ solves the unconstrained linear system (one factorization).
    SolveReport solve(const ReynoldsSystem& system, Eigen::VectorXd& p, double pLower,
                      const SolverControl& control);

private:
    struct Factor;
    std::unique_ptr<Factor> factor_;
    std::vector<int> outerPattern_, innerPattern_;
};

}  // namespace flexehd::lube
