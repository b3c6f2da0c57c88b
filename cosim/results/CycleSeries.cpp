// CycleSeries: every completed cycle's figures (docs/results-format.md, `cycle_to_cycle`).
#include "cosim/results/CycleSeries.hpp"


namespace flexehd::cosim {

CycleSeries::CycleSeries(const EngineCase& c, const PistonDynamics& dynamics)
    : dynamics_(dynamics), displacedVolume_(sweptVolume(c.engine)) {}

void CycleSeries::cycleEnded(const CycleEnd& end) {
    if (!end.records || end.records->size() < 2) return;
    cycles_.push_back({end.cycle, cycleMetrics(*end.records, dynamics_, displacedVolume_)});
}

}  // namespace flexehd::cosim
