// The oil-control ring on the liner's oil layer (docs/coupling.md §6, "The oil-control ring"):
// a band above the skirt that takes the layer its leading edge meets and leaves the ring's
// layer t_r behind. Over the down-stroke from TDC its trailing (upper) edge uncovers the liner
// from its TDC position down to its BDC position, so at BDC that strip carries t_r exactly, the
// liner above the ring's TDC position still the supply layer t₀; what the ring scrapes beyond t_r
// drains to the crankcase and closes the run's oil balance as a side flow.
#include "cosim/contact/MassConservingFilm.hpp"
#include "cosim/contact/OilControlRingBand.hpp"
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "SmallEngineCase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace flexehd;
using namespace flexehd::cosim;

namespace {

constexpr double kSupply = 3e-6, kRing = 1e-6;

EngineCase ringCase(bool replenish) {
    EngineCase c = test::smallCase();
    c.lubricant.cavitation = CavitationModel::MassConserving;
    c.lubricant.supply.model = OilSupplyModel::LinerLayer;
    c.lubricant.supply.layer = {{0.0, kSupply}};
    c.lubricant.supply.replenish = replenish;
    c.lubricant.supply.oilControlRing = OilControlRingSpec{c.piston.skirtTop + 3e-3, c.piston.skirtTop + 5.5e-3, kRing};
    c.output.vtkEveryDeg = 180.0;
    return c;
}

// The oil balance of records a … b: the change of liner and film oil against the replenished and
// the leaked volume, and the volume through the films' edges (the tolerance's scale).
struct Balance {
    double change = 0.0, replenished = 0.0, leaked = 0.0, moved = 0.0;
};

Balance balance(const std::vector<StepRecord>& r) {
    Balance b;
    for (std::size_t i = 1; i < r.size(); ++i) {
        b.leaked += (r[i].time - r[i - 1].time) * r[i].sideLeakage;
        b.moved += (r[i].time - r[i - 1].time) * (r[i].oilIn + r[i].oilOut);
    }
    b.change = (r.back().linerOil + r.back().filmOil) - (r.front().linerOil + r.front().filmOil);
    b.replenished = r.back().replenishedOil - r.front().replenishedOil;
    return b;
}

}  // namespace

TEST(OilControlRing, LeavesItsLayerBehindAndItsDrainClosesTheOilBalance) {
    const EngineCase c = ringCase(false);
    PistonSimulation sim(c);
    ASSERT_EQ(sim.contacts().size(), 2u);
    const OilControlRingSpec& ring = *c.lubricant.supply.oilControlRing;
    std::vector<Snapshot> snaps;
    SimulationCallbacks cb;
    cb.onSnapshot = [&](const Snapshot& s) { snaps.push_back(s); };
    std::vector<StepRecord> r;
    cb.onStep = [&](const StepRecord& s) { r.push_back(s); };
    sim.run(cb, 180.0);
    ASSERT_GT(r.size(), 50u);
    ASSERT_FALSE(snaps.empty());
    const Snapshot& bdc = snaps.back();
    ASSERT_NEAR(bdc.crankDeg, 180.0, 1e-9);

    // The layer's cells wholly in the strip the ring's upper edge uncovered carry t_r; those wholly
    // above its TDC position t₀ (the columns the layer has: the skirt's).
    const lube::FilmGrid& g = sim.contact<SkirtContact>().film().grid();
    const double cell = bdc.linerOilZ[1] - bdc.linerOilZ[0];
    const double low = sim.linerOffset(180.0) + ring.top, high = sim.linerOffset(0.0) + ring.top;
    int strip = 0, above = 0;
    double worstStrip = 0.0, worstAbove = 0.0;
    for (std::size_t k = 0; k < bdc.linerOilZ.size(); ++k) {
        const double z = bdc.linerOilZ[k];
        const bool inStrip = z - 0.5 * cell >= low && z + 0.5 * cell <= high;
        const bool isAbove = z - 0.5 * cell >= high;
        if (!inStrip && !isAbove) continue;
        (inStrip ? strip : above) += 1;
        for (int j = 0; j < g.nTheta(); ++j) {
            if (g.kind(g.index(0, j)) == lube::NodeKind::Void) continue;
            const double t = bdc.linerOil[static_cast<Eigen::Index>(k) * g.nTheta() + j];
            if (inStrip)
                worstStrip = std::max(worstStrip, std::abs(t - kRing));
            else
                worstAbove = std::max(worstAbove, std::abs(t - kSupply));
        }
    }
    std::printf("strip: %d cells, worst |t - t_r| %.3g m; above: %d cells, worst |t - t0| %.3g m\n", strip, worstStrip,
                above, worstAbove);
    EXPECT_GE(strip, 20);
    EXPECT_GE(above, 3);
    EXPECT_LT(worstStrip, 1e-12 * kRing);
    EXPECT_LT(worstAbove, 1e-12 * kSupply);

    // The ring drained oil (it met more than t_r on the way down) and the balance closes with it:
    // without the drain it would miss that volume, orders above the films' tolerance.
    double drained = 0.0;
    for (std::size_t i = 1; i < r.size(); ++i) drained += (r[i].time - r[i - 1].time) * r[i].contactValues.at(0);
    const Balance b = balance(r);
    std::printf("drained %.4g m^3; liner + films change %.4g, leaked %.4g, through the edges %.4g m^3\n", drained,
                b.change, b.leaked, b.moved);
    EXPECT_GT(drained, 0.0);
    EXPECT_EQ(b.replenished, 0.0);
    EXPECT_GT(drained, 1e3 * MassConservingFilm::kTolerance * b.moved);
    EXPECT_NEAR(b.change, -b.leaked, 10.0 * MassConservingFilm::kTolerance * b.moved);
}

TEST(OilControlRing, AWholeCycleWithReplenishmentKeepsTheOilBalance) {
    PistonSimulation sim(ringCase(true));
    std::vector<StepRecord> r;
    SimulationCallbacks cb;
    cb.onStep = [&](const StepRecord& s) { r.push_back(s); };
    sim.run(cb, 720.0);
    ASSERT_GT(r.size(), 200u);
    const Balance b = balance(r);
    std::printf("liner + films change %.4g, replenished %.4g, leaked %.4g m^3\n", b.change, b.replenished, b.leaked);
    EXPECT_NEAR(b.change, b.replenished - b.leaked, 10.0 * MassConservingFilm::kTolerance * b.moved);
}
