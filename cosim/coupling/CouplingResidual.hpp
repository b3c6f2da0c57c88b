#pragma once
// CouplingResidual: the coupling residual r_h of an iterate, max over the films of
// |Δh(H(y) − y)| (docs/coupling.md §1), computed only where a test needs its value. Its bound,
// Σ_j |(H(y) − y)_j| max|Ψ_j| (each modal coordinate's change times the largest film change of
// its shape), costs no product over the grid and settles every test it lies on the right side
// of: a pass whose motion residual alone keeps it from converging and sets its measure needs no
// more. The decisions are those of the exact value.
#include <algorithm>
#include <functional>
#include <utility>

namespace flexehd::cosim {

class CouplingResidual {
public:
    /// Rigid bodies: zero.
    CouplingResidual() = default;
    /// bound ≥ r_h (m); exact() computes r_h (m), at most once.
    CouplingResidual(double bound, std::function<double()> exact) : upper_(bound), exact_(std::move(exact)) {}

    /// r_h (m).
    double value() const {
        if (exact_) {
            upper_ = exact_();
            exact_ = nullptr;
        }
        return upper_;
    }
    /// r_h ≤ limit.
    bool atMost(double limit) const { return upper_ <= limit || value() <= limit; }
    /// max(r_h / unit, floor): the residual in units of `unit`, or the floor where that is larger.
    double measure(double unit, double floor) const {
        return upper_ / unit <= floor ? floor : std::max(value() / unit, floor);
    }

private:
    mutable double upper_ = 0.0;             // m: the bound, r_h itself once formed
    mutable std::function<double()> exact_;  // forms r_h; empty once it has
};

}  // namespace flexehd::cosim
