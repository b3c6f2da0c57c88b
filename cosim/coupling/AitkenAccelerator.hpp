#pragma once
// AitkenAccelerator: Aitken Δ² dynamic relaxation of the film–structure fixed point y = H(y)
// (Irons & Tuck 1969; Küttler & Wall 2008; docs/coupling.md §1): with residuals r_k = H(y_k) − y_k,
//
//   ω_k = −ω_{k−1} r_{k−1}ᵀ(r_k − r_{k−1}) / ‖r_k − r_{k−1}‖²,   y_{k+1} = y_k + ω_k r_k,
//
// the first iteration the relaxed step y + ω₀ r (ω kept where r_k = r_{k−1}): lube's
// AitkenRelaxation without bounds on ω.

#include "cosim/coupling/CouplingAccelerator.hpp"
#include "lube/AitkenRelaxation.hpp"

namespace flexehd::cosim {

class AitkenAccelerator final : public CouplingAccelerator {
public:
    explicit AitkenAccelerator(double initialRelaxation = 0.5);

    void reset() override;
    Eigen::VectorXd next(const Eigen::VectorXd& y, const Eigen::VectorXd& Hy) override;

private:
    lube::AitkenRelaxation relaxation_;
};

}  // namespace flexehd::cosim
