#pragma once
// CouplingAccelerator: convergence acceleration of the fixed point y = H(y) between the film and
// the elastic bodies, with y the modal coordinates of the flexible bodies (docs/coupling.md).
//
//  * IQN-ILS (interface quasi-Newton, inverse Jacobian from a least-squares model; Degroote,
//    Bathe & Vierendeels 2009): with residuals r_k = H(y_k) − y_k and the differences
//    V = [Δr_i], W = [ΔH_i] of the iterations so far, solve min ‖V c + r_k‖ and set
//    y_{k+1} = H(y_k) + W c. The first iteration is a relaxed step y + ω₀ r. Columns that make
//    V numerically rank-deficient (QR filter) are dropped, oldest first.
//  * Aitken Δ² dynamic relaxation (Irons & Tuck 1969; Küttler & Wall 2008):
//    ω_k = −ω_{k−1} r_{k−1}ᵀ(r_k − r_{k−1}) / ‖r_k − r_{k−1}‖², y_{k+1} = y_k + ω_k r_k.

#include "cosim/case/EngineCase.hpp"

#include <Eigen/Core>

#include <vector>

namespace flexehd::cosim {

class CouplingAccelerator {
public:
    CouplingAccelerator(CouplingAcceleration method, double initialRelaxation = 0.5, int maxColumns = 20);

    /// Forgets the iteration history (new time step).
    void reset();
    /// Next iterate from the current one y and its image Hy = H(y).
    Eigen::VectorXd next(const Eigen::VectorXd& y, const Eigen::VectorXd& Hy);

private:
    CouplingAcceleration method_;
    double omega0_, omega_;
    int maxColumns_;
    bool first_ = true;
    Eigen::VectorXd lastR_, lastH_;
    std::vector<Eigen::VectorXd> V_, W_;
};

}  // namespace flexehd::cosim
