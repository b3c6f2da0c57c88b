#pragma once
// CouplingAccelerator: convergence acceleration of the fixed point y = H(y) between the film and
// the elastic bodies, with y the modal coordinates of the flexible bodies (docs/coupling.md §1,
// "Otherwise"). One interface, one method per class: IqnIlsAccelerator (interface quasi-Newton,
// Degroote, Bathe & Vierendeels 2009) and AitkenAccelerator (Aitken Δ² dynamic relaxation,
// Irons & Tuck 1969; Küttler & Wall 2008), made by makeCouplingAccelerator from
// coupling.acceleration.

#include "cosim/case/EngineCase.hpp"

#include <Eigen/Core>

#include <memory>

namespace flexehd::cosim {

class CouplingAccelerator {
public:
    virtual ~CouplingAccelerator() = default;

    /// Forgets the iteration history (new time step).
    virtual void reset() = 0;
    /// Next iterate from the current one y and its image Hy = H(y).
    virtual Eigen::VectorXd next(const Eigen::VectorXd& y, const Eigen::VectorXd& Hy) = 0;
};

/// The accelerator of coupling.acceleration: ω₀ the relaxation of the first iteration (and
/// Aitken's initial ω), maxColumns the most IQN-ILS difference columns kept.
std::unique_ptr<CouplingAccelerator> makeCouplingAccelerator(CouplingAcceleration method,
                                                             double initialRelaxation = 0.5, int maxColumns = 20);

}  // namespace flexehd::cosim
