// OilControlRingBand: the band's trade with the liner's oil layer (docs/coupling.md §6, "The
// oil-control ring"). Over a step its leading edge sweeps the liner from the step's start to its
// end and takes the layer there (the flow in through that edge); its trailing edge uncovers the
// strip behind it and leaves the ring's layer t_r on it (the flow out); the side flow closes the
// band's balance, so that it holds no oil.
#include "cosim/contact/OilControlRingBand.hpp"

#include <algorithm>
#include <cmath>

namespace flexehd::cosim {
namespace {

// The liner-frame z range an edge at piston-frame z sweeps from one liner offset to the next.
std::pair<double, double> swept(double edge, double from, double to) {
    return {std::min(from, to) + edge, std::max(from, to) + edge};
}

}  // namespace

OilControlRingBand::OilControlRingBand(const OilControlRingSpec& ring, const LinerFootprint& columns, double zLow,
                                       double zHigh)
    : ring_(ring), footprint_(columns) {
    footprint_.zLow = zLow;
    footprint_.zHigh = zHigh;
    // The layer's cells (the finest footprint's) at most half the band's height: its trailing edge
    // never leaves oil in a cell its leading edge still takes from.
    footprint_.cell = 0.5 * (ring_.top - ring_.bottom);
}

ContactState OilControlRingBand::initialState(double linerOffset) const {
    ContactState s;
    s.linerOffset = linerOffset;
    return s;
}

void OilControlRingBand::evaluate(const ContactStep& step, const ContactState& now, const ContactState& /*before*/,
                                  const Eigen::Vector2d& /*x*/, const Eigen::VectorXd& /*y*/, ContactIterate& it,
                                  WorkTally& /*work*/) {
    it = ContactIterate{};
    it.minGap = std::numeric_limits<double>::infinity();  // no film of its own
    const int n = static_cast<int>(footprint_.width.size());
    it.inflowLow = it.inflowHigh = Eigen::VectorXd::Zero(n);
    if (!step.oil || !step.oil->layer || step.linerOffset == now.linerOffset) return;
    const bool down = step.linerOffset < now.linerOffset;
    const auto [a, b] = swept(down ? ring_.bottom : ring_.top, now.linerOffset, step.linerOffset);
    const LinerOilLayer& layer = *step.oil->layer;
    double net = 0.0;
    for (int j = 0; j < n; ++j) {
        const double taken = layer.volume(j, a, b, step.oil->covers) / step.dt;  // m³/s
        const double left = ring_.thickness * layer.width(j) * (b - a) / step.dt;
        (down ? it.inflowLow : it.inflowHigh)[j] = taken;
        (down ? it.inflowHigh : it.inflowLow)[j] = -left;
        net += taken - left;
    }
    it.sideInflow = -net;  // drained to the crankcase (> 0 inflow: laid down from the ring's oil)
}

void OilControlRingBand::linearize(const ContactStep& /*step*/, const ContactState& /*now*/, const Eigen::Vector2d& /*x*/,
                                   const ContactIterate& /*it*/, ContactJacobian& J, WorkTally& /*work*/) {
    J = ContactJacobian{};
    J.motionColumns = true;  // no load: its motion columns are zero
}

ContactState OilControlRingBand::accepted(const ContactStep& step, const ContactState& now,
                                          const ContactIterate& it) const {
    ContactState s = initialState(step.linerOffset);
    s.oilBalance = afterStep(now.oilBalance, it, step.dt);
    return s;
}

std::vector<ContactColumn> OilControlRingBand::columns() const {
    return {{"oil_control_ring_drain_m3_per_s", {{kDrainFigure, CycleStatistic::Mean}}}};
}

void OilControlRingBand::columnValues(const ContactIterate& it, std::vector<double>& values) const {
    values.push_back(-it.sideInflow);
}

void OilControlRingBand::exchangeOil(const ContactState& now, const ContactState& next, const ContactIterate& it,
                                     LinerOilExchange& ex) const {
    if (next.linerOffset == now.linerOffset) return;
    const bool down = next.linerOffset < now.linerOffset;
    const auto [a, b] = swept(down ? ring_.top : ring_.bottom, now.linerOffset, next.linerOffset);
    const Eigen::VectorXd& out = down ? it.inflowHigh : it.inflowLow;
    for (Eigen::Index j = 0; j < out.size(); ++j)
        ex.next.deposit(static_cast<int>(j), a, b, -out[j] * ex.dt, ex.before);
}

}  // namespace flexehd::cosim
