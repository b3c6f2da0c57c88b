// RingPackGas: the pack's lands and end gaps as InterRingGas's chain (docs/ring-pack.md, "The
// pack's gas in a run").
#include "cosim/ringpack/RingPackGas.hpp"

#include <fmt/format.h>

#include <numbers>
#include <stdexcept>

namespace flexehd::cosim {

namespace {

// Land i: the annulus of the land's height between ring i's groove and ring i + 1's, and ring
// i + 1's groove space above it (its side clearance) and behind it (its back clearance).
double landVolume(const EngineCase& c, std::size_t i) {
    const RingSpec &upper = c.rings[i], &lower = c.rings[i + 1];
    const double bore = c.engine.bore, pi = std::numbers::pi;
    const double height = upper.groove.lowerFlank - lower.grooveTop();
    if (!(height > 0.0))
        throw std::invalid_argument(fmt::format("ring_gas: no land between rings '{}' and '{}' (their grooves meet)",
                                                upper.name, lower.name));
    const double land = pi * bore * height * c.ringGas.landClearance;
    const double width = lower.height + lower.groove.sideClearance;
    const double backDiameter = bore - 2.0 * lower.radialWidth - lower.groove.backClearance;
    const double back = pi * backDiameter * width * lower.groove.backClearance;
    const double side = pi * (bore - lower.radialWidth) * lower.radialWidth * lower.groove.sideClearance;
    return land + back + side;
}

}  // namespace

RingPackGas::RingPackGas(const EngineCase& c) : crankcase_(c.engine.crankcasePressure) {
    const RingGasSpec& g = c.ringGas;
    const std::size_t n = c.rings.size();
    if (n == 0) throw std::invalid_argument("ring_gas: needs a ring pack (rings)");
    if (!g.landTemperatures.empty() && g.landTemperatures.size() != n - 1)
        throw std::invalid_argument(fmt::format("ring_gas.land_temperatures: expected one temperature per land "
                                                "between the rings ({}), got {}",
                                                n - 1, g.landTemperatures.size()));
    for (std::size_t i = 0; i < n; ++i) gaps_.push_back(g.dischargeCoefficient * c.rings[i].closedGap * g.landClearance);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        volumes_.push_back(landVolume(c, i));
        temperatures_.push_back(g.landTemperatures.empty() ? RingGasSpec::kLandTemperature : g.landTemperatures[i]);
    }
    if (!volumes_.empty()) accepted_.emplace(GasProperties{}, volumes_, temperatures_, gaps_, crankcase_);
    around_.resize(n);
}

const std::vector<RingGas>& RingPackGas::trial(double dt, double cylinderPressure) {
    const std::size_t n = around_.size();
    std::vector<double> p(n + 1);  // absolute: above ring 0, the lands, below the last ring
    p.front() = cylinderPressure;
    p.back() = crankcase_;
    if (accepted_) {
        trial_ = *accepted_;
        trial_->advance(dt, cylinderPressure, crankcase_);
        for (std::size_t i = 0; i + 1 < n; ++i) p[i + 1] = trial_->pressures()[static_cast<Eigen::Index>(i)];
    }
    for (std::size_t i = 0; i < n; ++i) {
        RingGas& r = around_[i];
        r.above = p[i] - crankcase_;
        r.behind = r.above;  // the ring on its groove's lower flank: its back open to the land above
        r.below = p[i + 1] - crankcase_;
        r.flow = trial_ ? trial_->flow(static_cast<int>(i))
                        : orificeFlow(GasProperties{}, gaps_[i], p[i], p[i + 1], RingGasSpec::kLandTemperature,
                                      RingGasSpec::kLandTemperature);
    }
    return around_;
}

void RingPackGas::accept() {
    if (trial_) accepted_ = *trial_;
}

std::vector<double> RingPackGas::landPressures() const {
    std::vector<double> p;
    if (accepted_)
        for (Eigen::Index i = 0; i < accepted_->pressures().size(); ++i) p.push_back(accepted_->pressures()[i]);
    return p;
}

}  // namespace flexehd::cosim
