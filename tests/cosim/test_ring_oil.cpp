// A ring on the liner's oil layer (RingContact with RingOilExchange, docs/ring-pack.md, "The rings
// on the liner's oil layer"), stroked up and down a layer of its own: at every step the oil on
// the liner, in the ring's film and drained through the oil-control ring add up to what there
// was (no oil made or lost by the trade: each film's content changes by its edges' flows, the
// layer by what the edges took and left); a thinner layer leaves each ring a thinner film at
// mid-stroke and more of its load on the asperities. And the example's pack with the skirt on one
// layer (examples/engine86/starved_rings.yaml): each step's oil of liner and films changes by the
// replenished less the drained, the skirt's film to its solver's tolerance; the same with the
// lands' gas and ring lift at 4000 rpm, where the rings' faces open to the gas.
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/contact/MassConservingFilm.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "cosim/oil/LinerOil.hpp"
#include "cosim/ringpack/RingContact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "RingCases.hpp"

using namespace flexehd;
using namespace flexehd::cosim;
using test::barrelRing;

namespace {

constexpr double kStroke = 0.086, kRpm = 1000.0;

EngineCase layerCase(double thickness) {
    EngineCase c = test::ringCase();
    c.lubricant.cavitation = CavitationModel::MassConserving;
    c.lubricant.supply.model = OilSupplyModel::LinerLayer;
    c.lubricant.supply.layer = {{0.0, thickness}};
    c.lubricant.supply.replenish = false;
    return c;
}

RingSpec oilControlRing() {
    RingSpec r = barrelRing(2.43e-3, 0.0, 580.0, 0.3e-6);
    r.name = "oil";
    r.kind = RingKind::OilControl;
    r.lands = OilControlLandsSpec{0.4e-3, 2.03e-3, 4e-6};
    return r;
}

struct Stroked {
    double worstStepError = 0.0;  // m³: |Δ(layer + film) + drained| of a step, the largest
    double moved = 0.0;           // m³ through the ring's edges
    double shortfall = 0.0;       // m³ the film drew beyond the layer
    double drained = 0.0;         // m³ through the ring (the oil-control ring's side flow)
    double midFilm = 0.0;         // m, the ring's mean minimum film where |U| > 0.7 of its peak
    double asperityEnergy = 0.0;  // J, the boundary friction's work
};

// The ring stroked sinusoidally over kStroke at kRpm for `revolutions`, steps of 0.5°, on a layer
// of its own over 36 columns round the bore.
Stroked stroke(const EngineCase& c, const RingSpec& spec, int revolutions) {
    const double omega = kRpm * std::numbers::pi / 30.0, amplitude = 0.5 * kStroke;
    const double dt = 0.5 * std::numbers::pi / 180.0 / omega;
    auto offset = [&](double t) { return amplitude * std::cos(omega * t); };
    auto velocity = [&](double t) { return -amplitude * omega * std::sin(omega * t); };
    LinerFootprint columns;
    columns.zLow = -amplitude;
    columns.zHigh = amplitude;
    columns.width.assign(36, std::numbers::pi * c.engine.bore / 36.0);
    RingContact ring(c, spec, false, 0, &columns);
    const LinerOil oil(c.lubricant.supply, {*ring.linerFootprint()}, -std::numeric_limits<double>::infinity());
    ContactState now = ring.initialState(offset(0.0)), before = now;
    LinerOilState layer = oil.initial(LinerCovers({ring.linerCover(now.linerOffset)}));
    Stroked s;
    double last = std::numeric_limits<double>::quiet_NaN();
    int mid = 0;
    WorkTally work;
    for (int k = 1; k <= 720 * revolutions; ++k) {
        const double t = k * dt;
        ContactStep step;
        step.dt = dt;
        step.pistonVelocity = velocity(t);
        step.linerOffset = offset(t);
        step.oil = &layer;
        ContactIterate it;
        ring.evaluate(step, now, before, Eigen::Vector2d::Zero(), Eigen::VectorXd(), it, work);
        const ContactState next = ring.accepted(step, now, it);
        layer = oil.advance(layer, LinerCovers({ring.linerCover(next.linerOffset)}), dt,
                            [&](LinerOilExchange& ex) { ring.exchangeOil(now, next, it, ex); });
        before = now;
        now = next;
        const double total = LinerOil::volume(layer) + it.oilVolume;
        s.drained -= it.sideInflow * dt;
        if (std::isfinite(last)) s.worstStepError = std::max(s.worstStepError, std::abs(total - last - it.sideInflow * dt));
        last = total;
        s.moved += (it.inflowLow.cwiseAbs().sum() + it.inflowHigh.cwiseAbs().sum()) * dt;
        s.asperityEnergy += it.loads.boundaryFrictionPower * dt;
        if (std::abs(step.pistonVelocity) > 0.7 * amplitude * omega) {
            s.midFilm += it.minGap;
            ++mid;
        }
    }
    s.shortfall = layer.shortfall;
    s.midFilm /= mid;
    return s;
}

}  // namespace

TEST(RingOil, EachStepConservesTheOilOfLinerFilmAndDrain) {
    for (const RingSpec& spec : {barrelRing(1.2e-3, 8e-6, 200.0, 0.3e-6), oilControlRing()}) {
        const Stroked s = stroke(layerCase(3e-6), spec, 1);
        std::printf("%s: worst step error %.3g m^3, moved %.3g m^3, drained %.3g m^3, shortfall %.3g m^3\n",
                    spec.name.c_str(), s.worstStepError, s.moved, s.drained, s.shortfall);
        EXPECT_GT(s.moved, 0.0);
        EXPECT_LT(s.worstStepError, 1e-9 * s.moved) << spec.name;
        EXPECT_EQ(s.shortfall, 0.0) << spec.name;
        if (spec.lands) EXPECT_GT(s.drained, 0.0);  // the second land takes in less than the first lets out
    }
}

// A thinner layer feeds the face less oil: its film at mid-stroke is thinner and its asperities
// carry more, so the boundary friction does more work.
TEST(RingOil, AThinnerLayerThinsTheFilmAndRaisesTheBoundaryFriction) {
    for (const RingSpec& spec : {barrelRing(1.2e-3, 8e-6, 200.0, 0.3e-6), oilControlRing()}) {
        const Stroked thick = stroke(layerCase(3e-6), spec, 1), thin = stroke(layerCase(0.5e-6), spec, 1);
        std::printf("%s: mid-stroke film %.3g -> %.3g m, boundary friction work %.3g -> %.3g J\n", spec.name.c_str(),
                    thick.midFilm, thin.midFilm, thick.asperityEnergy, thin.asperityEnergy);
        EXPECT_LT(thin.midFilm, thick.midFilm) << spec.name;
        EXPECT_GT(thin.asperityEnergy, thick.asperityEnergy) << spec.name;
    }
}

namespace {

// The oil of liner and films over a run's steps: each step's change against the replenished less
// the drained (its error), the oil the films' edges moved and the drained total.
struct OilLedger {
    double moved = 0.0, drained = 0.0, worst = 0.0, drift = 0.0;
};

OilLedger oilLedger(const std::vector<StepRecord>& r) {
    OilLedger l;
    for (std::size_t i = 1; i < r.size(); ++i) {
        const double dt = r[i].time - r[i - 1].time;
        l.moved += dt * (r[i].oilIn + r[i].oilOut);
        l.drained += dt * r[i].sideLeakage;
        const double error = (r[i].linerOil + r[i].filmOil) - (r[i - 1].linerOil + r[i - 1].filmOil) -
                             (r[i].replenishedOil - r[i - 1].replenishedOil) + dt * r[i].sideLeakage;
        l.worst = std::max(l.worst, std::abs(error));
        l.drift += error;
    }
    return l;
}

}  // namespace

TEST(RingOil, TheExamplesPackAndSkirtShareTheLayerAndKeepItsOil) {
    EngineCase c = readCaseFile(std::string(FLEXEHD_SOURCE_DIR) + "/examples/engine86/starved_rings.yaml");
    ASSERT_EQ(c.rings.size(), 3u);
    PistonSimulation sim(c);
    ASSERT_EQ(sim.contacts().size(), 4u);
    std::vector<StepRecord> r;
    SimulationCallbacks cb;
    cb.onStep = [&](const StepRecord& s) { r.push_back(s); };
    sim.run(cb, 720.0);
    ASSERT_GT(r.size(), 700u);
    const OilLedger l = oilLedger(r);
    std::printf("oil moved %.4g m^3, drained and leaked %.4g m^3; largest step error %.3g, cycle %.3g m^3\n", l.moved,
                l.drained, l.worst, l.drift);
    EXPECT_GT(l.drained, 0.0);  // the oil-control ring drains what its second land does not take
    EXPECT_LT(std::abs(l.drift), 10.0 * MassConservingFilm::kTolerance * l.moved);
    EXPECT_LT(l.worst, 10.0 * MassConservingFilm::kTolerance * l.moved);
}

// The example's pack on the layer with the lands' gas and ring lift at 4000 rpm part load (the grid
// coarser): the second ring, lifted onto its upper flank after firing TDC with the second land's
// gas above its face, cannot hold that gas with the film over its edge rounding, and its face
// opens to it (docs/lube.md §9; the partition of a film held against the gas cycles there). The
// faces open to the gas keep the oil as every film does, and so do the dead centres, where the
// sliding reverses within a step and a ring's film takes oil in through the edge that retreats
// (the strip it uncovers holds none of what its cells held before the ring covered them): each
// step's oil of liner and films changes by the replenished less the drained.
TEST(RingOil, WithTheLandsGasTheFacesOpenToItAndTheOilIsKept) {
    EngineCase c = readCaseFile(std::string(FLEXEHD_SOURCE_DIR) + "/examples/engine86/starved_rings.yaml");
    c.engine.speedRpm = 4000.0;
    c.grid.axialNodes = 24;
    c.grid.circumferentialNodes = 72;
    c.output.vtkEveryDeg = 0.0;
    c.ringGas.model = RingGasModel::Lands;
    c.ringGas.ringLift = true;
    PistonSimulation sim(c);
    std::vector<std::string> names;
    for (const ContactColumn& col : sim.contactColumns()) names.push_back(col.name);
    const auto at = std::find(names.begin(), names.end(), "ring_second_face_open_to_gas");
    ASSERT_NE(at, names.end());
    const auto open = static_cast<std::size_t>(at - names.begin());
    std::vector<StepRecord> r;
    SimulationCallbacks cb;
    cb.onStep = [&](const StepRecord& s) { r.push_back(s); };
    sim.run(cb, 720.0);
    ASSERT_GT(r.size(), 700u);
    double openDeg = 0.0;
    for (std::size_t i = 1; i < r.size(); ++i)
        if (r[i].contactValues[open] > 0.0 && r[i].crankDeg > 360.0 && r[i].crankDeg < 540.0)
            openDeg += r[i].crankDeg - r[i - 1].crankDeg;
    const OilLedger l = oilLedger(r);
    std::printf("4000 rpm with the lands' gas: the second ring's face open to the gas over %.1f deg of the "
                "expansion stroke; oil moved %.4g m^3, largest step error %.3g, cycle %.3g m^3\n",
                openDeg, l.moved, l.worst, l.drift);
    EXPECT_GT(openDeg, 0.0);
    EXPECT_LT(std::abs(l.drift), 10.0 * MassConservingFilm::kTolerance * l.moved);
    EXPECT_LT(l.worst, 10.0 * MassConservingFilm::kTolerance * l.moved);
}
