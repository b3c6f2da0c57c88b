#pragma once
// AitkenRelaxation: Aitken Δ² dynamic relaxation of a fixed point x = G(x) (Irons & Tuck 1969;
// Küttler & Wall, Comput. Mech. 43 (2008) 61): with residuals r_k = G(x_k) − x_k,
//
//   ω_k = −ω_{k−1} r_{k−1}ᵀ(r_k − r_{k−1}) / ‖r_k − r_{k−1}‖²,   x_{k+1} = x_k + ω_k r_k,
//
// the first iteration the relaxed step x + ω₀ r (ω kept where r_k = r_{k−1}), ω held within
// given bounds. Used by JfoSolver's passes (docs/lube.md §3b) and the coupling's Aitken
// accelerator (docs/coupling.md §1).
#include <Eigen/Core>
#include <limits>

namespace flexehd::lube {

class AitkenRelaxation {
public:
    /// initial: ω₀; lowest, highest: the bounds of ω (none by default).
    explicit AitkenRelaxation(double initial = 1.0, double lowest = -std::numeric_limits<double>::infinity(),
                              double highest = std::numeric_limits<double>::infinity());

    /// Forget the earlier iterations (ω back to ω₀).
    void reset();
    /// The next iterate x + ω r, r = Gx − x, for the iterate x and its image Gx.
    Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& Gx);
    double relaxation() const { return omega_; }

private:
    double omega0_, lowest_, highest_, omega_;
    Eigen::VectorXd lastR_;  // the last iteration's r (none before the first)
};

}  // namespace flexehd::lube
