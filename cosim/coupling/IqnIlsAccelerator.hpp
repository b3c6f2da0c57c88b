#pragma once
// IqnIlsAccelerator: interface quasi-Newton acceleration with the inverse Jacobian from a
// least-squares model (IQN-ILS; Degroote, Bathe & Vierendeels 2009; docs/coupling.md §1) of the
// film–structure fixed point y = H(y): with residuals r_k = H(y_k) − y_k and the differences
// V = [Δr_i], W = [ΔH_i] of the iterations so far (newest first, at most maxColumns), solve
// min ‖V c + r_k‖ (Householder QR) and set y_{k+1} = H(y_k) + W c. The first iteration is the
// relaxed step y + ω₀ r. Columns that make V numerically rank-deficient (a diagonal of R at most
// 1e-10 of the largest) are dropped, oldest first.

#include "cosim/coupling/CouplingAccelerator.hpp"

#include <vector>

namespace flexehd::cosim {

class IqnIlsAccelerator final : public CouplingAccelerator {
public:
    explicit IqnIlsAccelerator(double initialRelaxation = 0.5, int maxColumns = 20);

    void reset() override;
    Eigen::VectorXd next(const Eigen::VectorXd& y, const Eigen::VectorXd& Hy) override;

private:
    double omega0_;
    int maxColumns_;
    bool first_ = true;
    Eigen::VectorXd lastR_, lastH_;
    std::vector<Eigen::VectorXd> V_, W_;
};

}  // namespace flexehd::cosim
