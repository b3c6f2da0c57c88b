// RingPackGas: the pack's lands, grooves and end gaps as InterRingGas's network (docs/ring-pack.md,
// "The pack's gas in a run").
#include "cosim/ringpack/RingPackGas.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace flexehd::cosim {

namespace {

constexpr double kPi = std::numbers::pi;

// Ring r's groove space behind it (its back clearance over the groove's width) and beside it (its
// side clearance over its radial width).
double grooveVolume(const EngineCase& c, const RingSpec& r) {
    const double bore = c.engine.bore;
    const double width = r.height + r.groove.sideClearance;
    const double backDiameter = bore - 2.0 * r.radialWidth - r.groove.backClearance;
    const double back = kPi * backDiameter * width * r.groove.backClearance;
    const double side = kPi * (bore - r.radialWidth) * r.radialWidth * r.groove.sideClearance;
    return back + side;
}

// The width of ring r's running faces together (m): its face, or the oil-control ring's two lands.
double runningWidth(const RingSpec& r) {
    if (r.lands) return 2.0 * r.lands->width;
    if (r.face.table.empty()) return r.height;
    return r.face.table.back().first - r.face.table.front().first;
}

// Land i: the annulus of the land's height between ring i's groove and ring i + 1's.
double landAnnulus(const EngineCase& c, std::size_t i) {
    const RingSpec &upper = c.rings[i], &lower = c.rings[i + 1];
    const double height = upper.groove.lowerFlank - lower.grooveTop();
    if (!(height > 0.0))
        throw std::invalid_argument(fmt::format("ring_gas: no land between rings '{}' and '{}' (their grooves meet)",
                                                upper.name, lower.name));
    return kPi * c.engine.bore * height * c.ringGas.landClearance;
}

}  // namespace

RingPackGas::RingPackGas(const EngineCase& c)
    : crankcase_(c.engine.crankcasePressure),
      circumference_(kPi * c.engine.bore),
      dischargeCoefficient_(c.ringGas.dischargeCoefficient),
      lift_(c.ringGas.ringLift) {
    const RingGasSpec& g = c.ringGas;
    const std::size_t n = c.rings.size();
    if (n == 0) throw std::invalid_argument("ring_gas: needs a ring pack (rings)");
    if (!g.landTemperatures.empty() && g.landTemperatures.size() != n - 1)
        throw std::invalid_argument(fmt::format("ring_gas.land_temperatures: expected one temperature per land "
                                                "between the rings ({}), got {}",
                                                n - 1, g.landTemperatures.size()));
    auto landTemperature = [&](std::size_t i) {
        return g.landTemperatures.empty() ? RingGasSpec::kLandTemperature : g.landTemperatures[i];
    };
    std::vector<GasOrifice> orifices;
    for (std::size_t i = 0; i < n; ++i) {
        const RingSpec& r = c.rings[i];
        gaps_.push_back(g.dischargeCoefficient * r.closedGap * g.landClearance);
        rings_.push_back({kPi * (c.engine.bore - r.radialWidth) * r.radialWidth, kPi * (c.engine.bore - r.radialWidth),
                          r.mass, r.groove.sideClearance, r.tensionPerLength / runningWidth(r), runningWidth(r)});
    }
    for (std::size_t i = 0; i + 1 < n; ++i) {
        // Without lift ring i + 1's groove is part of the land above it.
        volumes_.push_back(landAnnulus(c, i) + (lift_ ? 0.0 : grooveVolume(c, c.rings[i + 1])));
        temperatures_.push_back(landTemperature(i));
    }
    std::vector<double> all = volumes_, temperatures = temperatures_;
    if (lift_)
        for (std::size_t i = 0; i < n; ++i) {
            // Each groove at the metal temperature of the land below it (the last: of the land above).
            grooves_.push_back(grooveVolume(c, c.rings[i]));
            all.push_back(grooves_.back());
            temperatures.push_back(n == 1 ? RingGasSpec::kLandTemperature : landTemperature(std::min(i, n - 2)));
            motion_.emplace_back(c.rings[i].mass / circumference_, c.rings[i].groove.sideClearance);
            collapse_.emplace_back(c.rings[i].mass / circumference_, c.rings[i].groove.backClearance);
        }
    // Orifices: each ring's end gap (index i), then with lift its upper and lower flank clearances
    // (n + 2i, n + 2i + 1), closed while the ring rests on its lower flank, and its face (3n + i
    // with lift, else n + i): an orifice closed while the ring is on the liner, and the laminar
    // channel of the gap its oil leaves open (none on a flooded liner).
    for (std::size_t i = 0; i < n; ++i) orifices.push_back({above(i), below(i), gaps_[i]});
    if (lift_)
        for (std::size_t i = 0; i < n; ++i) {
            orifices.push_back({above(i), behind(i), dischargeCoefficient_ * rings_[i].flankLength * rings_[i].sideClearance});
            orifices.push_back({behind(i), below(i), 0.0});
        }
    for (std::size_t i = 0; i < n; ++i) orifices.push_back({above(i), below(i), 0.0});
    if (!all.empty()) accepted_.emplace(GasProperties{}, all, temperatures, orifices, crankcase_);
    around_.resize(n);
}

int RingPackGas::above(std::size_t i) const { return i == 0 ? GasOrifice::kCylinder : static_cast<int>(i) - 1; }

int RingPackGas::below(std::size_t i) const {
    return i + 1 == rings_.size() ? GasOrifice::kCrankcase : static_cast<int>(i);
}

int RingPackGas::behind(std::size_t i) const {
    return lift_ ? static_cast<int>(volumes_.size() + i) : above(i);
}

double RingPackGas::pressure(int node, const InterRingGas* gas, double cylinder) const {
    if (node == GasOrifice::kCylinder) return cylinder;
    if (node == GasOrifice::kCrankcase) return crankcase_;
    return gas->pressures()[node];
}

void RingPackGas::moveRings(double dt, double cylinderPressure, double acceleration,
                            const std::vector<double>& friction) {
    // The net upward force on each ring (N), per unit of the bore's circumference: the gas on its
    // side faces — on each face the mean of the pressures at its outer and inner edges (the space
    // beside the face and the groove behind the ring: linear across a seated flank, the groove's
    // own across an open one, where the groove takes the pressure of the side it opens to), which
    // nets to the faces' area times half the pressure difference below − above — its inertia
    // −m A and the liner film's friction at the last accepted step.
    trialMotion_ = motion_;
    trialCollapse_ = collapse_;
    const std::size_t n = rings_.size();
    for (std::size_t i = 0; i < n; ++i) {
        const double pAbove = pressure(above(i), &*accepted_, cylinderPressure);
        const double pBelow = pressure(below(i), &*accepted_, cylinderPressure);
        const double force = 0.5 * rings_[i].faceArea * (pBelow - pAbove) - rings_[i].mass * acceleration +
                             (i < friction.size() ? friction[i] : 0.0);
        trialMotion_[i].step(dt, force / circumference_);
        const double z = trialMotion_[i].position(), clearance = rings_[i].sideClearance;
        const double opening = dischargeCoefficient_ * rings_[i].flankLength;
        trial_->setOrificeArea(static_cast<int>(n + 2 * i), opening * (clearance - z));
        trial_->setOrificeArea(static_cast<int>(n + 2 * i + 1), opening * z);
        // Off the liner: the gas on the face beyond what its tension and the gas behind it hold,
        // over its running width, drives it inwards (+) across the back clearance.
        trialCollapse_[i].step(dt, -rings_[i].runningWidth * margin(i, *accepted_, cylinderPressure));
        trial_->setOrificeArea(face(i), dischargeCoefficient_ * circumference_ * trialCollapse_[i].position());
    }
}

std::pair<double, double> RingPackGas::faceChannel(std::size_t i, const std::vector<RingOpenGap>& openGaps) const {
    if (i >= openGaps.size() || !(openGaps[i].resistance > 0.0) || !std::isfinite(openGaps[i].resistance)) return {0.0, 0.0};
    if (lift_ && trialCollapse_[i].position() > 0.0) return {0.0, 0.0};  // the face's orifice takes it
    return {circumference_ / openGaps[i].resistance, dischargeCoefficient_ * circumference_ * openGaps[i].narrowest};
}

void RingPackGas::setFaceChannels(const std::vector<RingOpenGap>& openGaps) {
    for (std::size_t i = 0; i < rings_.size(); ++i) {
        const auto [conductance, area] = faceChannel(i, openGaps);
        trial_->setChannel(face(i), conductance, area);
    }
}

const std::vector<RingGas>& RingPackGas::trial(double dt, double cylinderPressure, double acceleration,
                                               const std::vector<double>& friction,
                                               const std::vector<RingOpenGap>& openGaps) {
    const std::size_t n = around_.size();
    if (accepted_) {
        trial_ = *accepted_;
        if (lift_) moveRings(dt, cylinderPressure, acceleration, friction);
        setFaceChannels(openGaps);
        trial_->advance(dt, cylinderPressure, crankcase_);
    }
    const InterRingGas* gas = trial_ ? &*trial_ : nullptr;
    for (std::size_t i = 0; i < n; ++i) {
        RingGas& r = around_[i];
        r.above = pressure(above(i), gas, cylinderPressure) - crankcase_;
        r.behind = pressure(behind(i), gas, cylinderPressure) - crankcase_;
        r.below = pressure(below(i), gas, cylinderPressure) - crankcase_;
        const auto k = static_cast<int>(i);
        if (gas) {
            r.flow = gas->flow(k) + (lift_ ? gas->flow(static_cast<int>(n) + 2 * k + 1) : 0.0) + gas->flow(face(i));
        } else {  // a single ring without lift: its end gap and its face's open gap, cylinder to crankcase
            const double t = RingGasSpec::kLandTemperature;
            const auto [conductance, area] = faceChannel(i, openGaps);
            r.flow = orificeFlow(GasProperties{}, gaps_[i], cylinderPressure, crankcase_, t, t) +
                     channelFlow(GasProperties{}, conductance, area, cylinderPressure, crankcase_, t, t);
        }
        r.position = lift_ ? trialMotion_[i].position() : 0.0;
        r.flankForce = lift_ ? trialMotion_[i].flankForce() : 0.0;
        r.faceOpening = lift_ ? trialCollapse_[i].position() : 0.0;
        r.faceOpeningBefore = lift_ ? collapse_[i].position() : 0.0;
    }
    return around_;
}

double RingPackGas::margin(std::size_t i, const InterRingGas& gas, double cylinderPressure) const {
    return rings_[i].faceMargin + pressure(behind(i), &gas, cylinderPressure) -
           0.5 * (pressure(above(i), &gas, cylinderPressure) + pressure(below(i), &gas, cylinderPressure));
}

void RingPackGas::accept() {
    if (trial_) accepted_ = *trial_;
    if (lift_) {
        motion_ = trialMotion_;
        collapse_ = trialCollapse_;
    }
}

double RingPackGas::inflow() const {
    // From the cylinder: the top ring's end gap (orifice 0) and, with lift, its upper flank (n).
    if (!trial_) return around_.empty() ? 0.0 : around_.front().flow;
    return trial_->flow(0) + (lift_ ? trial_->flow(static_cast<int>(around_.size())) : 0.0) + trial_->flow(face(0));
}

double RingPackGas::blowBy() const {
    if (!trial_) return around_.empty() ? 0.0 : around_.back().flow;
    return trial_->blowBy();
}

std::vector<double> RingPackGas::landPressures() const {
    std::vector<double> p;
    if (accepted_)
        for (std::size_t i = 0; i < volumes_.size(); ++i) p.push_back(accepted_->pressures()[static_cast<Eigen::Index>(i)]);
    return p;
}

}  // namespace flexehd::cosim
