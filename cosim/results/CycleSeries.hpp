#pragma once
// CycleSeries: the cycle figures (CycleMetrics) of every completed cycle of a run, an observer of
// it. summary.json reports their cycle-to-cycle mean and spread when the run does not become
// periodic (docs/results-format.md, `cycle_to_cycle`).
#include "cosim/case/EngineCase.hpp"
#include "cosim/coupling/RunObserver.hpp"
#include "cosim/engine/PistonDynamics.hpp"
#include "cosim/results/CycleMetrics.hpp"

#include <vector>

namespace flexehd::cosim {

class CycleSeries final : public RunObserver {
public:
    CycleSeries(const EngineCase& c, const PistonDynamics& dynamics);

    void cycleEnded(const CycleEnd& end) override;

    /// One completed cycle's figures.
    struct Cycle {
        int number = 0;
        CycleMetrics metrics;
    };
    /// The cycles with two records or more, in order.
    const std::vector<Cycle>& cycles() const { return cycles_; }

private:
    const PistonDynamics& dynamics_;
    double displacedVolume_;
    std::vector<Cycle> cycles_;
};

}  // namespace flexehd::cosim
