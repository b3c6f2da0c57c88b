// The liner's oil layer is the master's, and every contact on it is a cover (docs/coupling.md §6,
// "The liner's oil layer and its covers"): a contact added to a run as new code only reads the
// layer, trades oil with it at its edges and appears in the run's oil balance. The contact here is
// a scraping band around the piston below the skirt, of no film load: on the down-stroke its lower
// edge leads into the untouched supply layer t₀ and takes all of it; it keeps the share 1 − α and
// leaves α spread on the strip its upper edge uncovers. So over the down-stroke it holds
// (1 − α) t₀ W Δs (W the layer's width round the bore, Δs the stroke), and the liner between it
// and the skirt carries α t₀.
#include "cosim/contact/FilmContact.hpp"
#include "cosim/contact/MassConservingFilm.hpp"
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

// The band between piston-frame z low and high on the columns of `width` (m per column); keeps
// 1 − alpha of what its leading edge takes in. Its oil (m³) is the OilBalance's in − out.
class ScrapingBand final : public FilmContact {
public:
    ScrapingBand(double low, double high, double alpha, LinerFootprint footprint)
        : low_(low), high_(high), alpha_(alpha), footprint_(std::move(footprint)) {}

    ContactState initialState(double linerOffset) const override {
        ContactState s;
        s.linerOffset = linerOffset;
        return s;
    }
    void evaluate(const ContactStep& step, const ContactState& now, const ContactState&, const Eigen::Vector2d&,
                  const Eigen::VectorXd&, ContactIterate& it, WorkTally&) override {
        it = ContactIterate{};
        it.minGap = 1.0;
        const int n = static_cast<int>(footprint_.width.size());
        it.inflowLow = it.inflowHigh = Eigen::VectorXd::Zero(n);
        const bool down = step.linerOffset < now.linerOffset;
        const double lead = down ? low_ : high_;  // the leading edge's piston-frame z
        const double a = std::min(now.linerOffset, step.linerOffset) + lead;
        const double b = std::max(now.linerOffset, step.linerOffset) + lead;
        double taken = 0.0;
        for (int j = 0; j < n; ++j) {
            const double v = step.oil->layer->volume(j, a, b, step.oil->covers);
            (down ? it.inflowLow : it.inflowHigh)[j] = v / step.dt;
            (down ? it.inflowHigh : it.inflowLow)[j] = -alpha_ * v / step.dt;
            taken += v;
        }
        it.oilVolume = held(now) + (1.0 - alpha_) * taken;
    }
    void addModalLoad(const ContactStep&, const ContactIterate&, Eigen::VectorXd&, WorkTally&) const override {}
    double filmChange(const ContactStep&, const Eigen::VectorXd&, WorkTally&) const override { return 0.0; }
    void linearize(const ContactStep&, const ContactState&, const Eigen::Vector2d&, const ContactIterate&,
                   ContactJacobian&, WorkTally&) override {}
    ContactState accepted(const ContactStep& step, const ContactState& now, const ContactIterate& it) const override {
        ContactState s = initialState(step.linerOffset);
        s.oilBalance = now.oilBalance;
        for (Eigen::Index j = 0; j < it.inflowLow.size(); ++j)
            for (double q : {it.inflowLow[j], it.inflowHigh[j]})
                (q > 0.0 ? s.oilBalance.edgeIn : s.oilBalance.edgeOut) += std::abs(q) * step.dt;
        return s;
    }

    std::vector<ContactColumn> columns() const override { return {{"band_oil_m3", {}}}; }
    void columnValues(const ContactIterate& it, std::vector<double>& values) const override {
        values.push_back(it.oilVolume);
    }

    std::optional<LinerFootprint> linerFootprint() const override { return footprint_; }
    LinerCover linerCover(double linerOffset) const override { return {linerOffset + low_, linerOffset + high_}; }
    void exchangeOil(const ContactState& now, const ContactState& next, const ContactIterate& it,
                     LinerOilExchange& ex) const override {
        // What the leading edge covered, the film took whole (no bank); the trailing edge leaves
        // its outflow on the strip it uncovered.
        const bool down = next.linerOffset < now.linerOffset;
        const double trail = down ? high_ : low_;
        const double a = std::min(now.linerOffset, next.linerOffset) + trail;
        const double b = std::max(now.linerOffset, next.linerOffset) + trail;
        const Eigen::VectorXd& out = down ? it.inflowHigh : it.inflowLow;
        for (Eigen::Index j = 0; j < out.size(); ++j) ex.next.deposit(static_cast<int>(j), a, b, -out[j] * ex.dt, ex.before);
    }

private:
    static double held(const ContactState& s) { return s.oilBalance.edgeIn - s.oilBalance.edgeOut; }

    double low_, high_, alpha_;
    LinerFootprint footprint_;
};

// The band is taller than two of the layer's cells (the skirt grid's spacing, 1.6 mm), so its
// trailing edge never deposits into a cell its leading edge still takes from.
constexpr double kLayer = 3e-6, kAlpha = 0.5, kGap = 6e-3, kHeight = 4e-3;

}  // namespace

TEST(LinerOilCovers, AnAddedContactTradesWithTheMastersLayerAndJoinsTheOilBalance) {
    EngineCase c = test::smallCase();
    c.lubricant.cavitation = CavitationModel::MassConserving;
    c.lubricant.supply.model = OilSupplyModel::LinerLayer;
    c.lubricant.supply.layer = {{0.0, kLayer}};
    c.lubricant.supply.replenish = false;
    c.output.vtkEveryDeg = 180.0;
    ASSERT_EQ(c.time.startDeg, 0.0);
    PistonSimulation sim(c);

    // The band below the skirt's grid, on its columns.
    const lube::FilmGrid& g = sim.contact<SkirtContact>().film().grid();
    const double high = g.z(0) - kGap, low = high - kHeight;
    LinerFootprint f;
    f.zLow = sim.linerOffset(180.0) + low;
    f.zHigh = sim.linerOffset(0.0) + high;
    f.cell = (g.z(g.nAxial() - 1) - g.z(0)) / (g.nAxial() - 1);
    double around = 0.0;
    for (int j = 0; j < g.nTheta(); ++j) {
        const bool on = g.kind(g.index(0, j)) != lube::NodeKind::Void;
        f.width.push_back(on ? g.radius() * g.angularWidth(j) : 0.0);
        around += f.width.back();
    }
    sim.addContact(std::make_unique<ScrapingBand>(low, high, kAlpha, f));

    std::vector<Snapshot> snaps;
    SimulationCallbacks cb;
    cb.onSnapshot = [&](const Snapshot& s) { snaps.push_back(s); };
    const std::vector<StepRecord> r = sim.run(cb, 180.0);
    ASSERT_GT(r.size(), 50u);
    ASSERT_NEAR(r.back().crankDeg, 180.0, 1e-9);

    // The band's oil after the down-stroke: all it swept of the untouched layer, less what it left.
    const double stroke = sim.linerOffset(0.0) - sim.linerOffset(180.0);
    const double expected = (1.0 - kAlpha) * kLayer * around * stroke;
    ASSERT_EQ(r.back().contactValues.size(), 1u);
    std::printf("band oil %.6g m^3, expected %.6g m^3 (stroke %.4g m, width %.4g m)\n", r.back().contactValues[0],
                expected, stroke, around);
    EXPECT_NEAR(r.back().contactValues[0], expected, 1e-9 * expected);

    // The liner it left between itself and the skirt at BDC carries alpha t0: the cells wholly in
    // the gap, but the one next to the skirt's edge (where the skirt's bank lies).
    ASSERT_FALSE(snaps.empty());
    const Snapshot& bdc = snaps.back();
    ASSERT_NEAR(bdc.crankDeg, 180.0, 1e-9);
    const int columns = g.nTheta();
    int cells = 0;
    double worst = 0.0;
    const double cell = bdc.linerOilZ.size() > 1 ? bdc.linerOilZ[1] - bdc.linerOilZ[0] : 0.0;
    for (std::size_t k = 0; k < bdc.linerOilZ.size(); ++k) {
        const double z = bdc.linerOilZ[k];
        if (z - 0.5 * cell < bdc.linerOffset + high || z + 1.5 * cell > bdc.linerOffset + g.z(0)) continue;
        ++cells;
        for (int j = 0; j < columns; ++j)
            if (f.width[static_cast<std::size_t>(j)] > 0.0)
                worst = std::max(worst, std::abs(bdc.linerOil[static_cast<Eigen::Index>(k) * columns + j] - kAlpha * kLayer));
    }
    EXPECT_GE(cells, 2);
    EXPECT_LT(worst, 1e-12 * kLayer);

    // The run's oil balance holds with the band in it: liner and films change by the leakage only
    // (no replenishment), to the skirt film's tolerance of the volume through its edges.
    double leaked = 0.0, moved = 0.0;
    for (std::size_t i = 1; i < r.size(); ++i) {
        leaked += (r[i].time - r[i - 1].time) * r[i].sideLeakage;
        moved += (r[i].time - r[i - 1].time) * (r[i].oilIn + r[i].oilOut);
    }
    const StepRecord &a = r.front(), &b = r.back();
    EXPECT_EQ(b.replenishedOil, 0.0);
    const double change = (b.linerOil + b.filmOil) - (a.linerOil + a.filmOil);
    std::printf("liner %.5g -> %.5g m^3, films %.5g -> %.5g m^3, leaked %.4g, change %.4g\n", a.linerOil, b.linerOil,
                a.filmOil, b.filmOil, leaked, change);
    // The band's oil is in the films' sum (the skirt's film holds the rest); without it the balance
    // would miss (1 − α) t₀ W Δs, ten orders above its tolerance.
    EXPECT_GT(b.filmOil, r.back().contactValues[0]);
    EXPECT_NEAR(change, -leaked, 10.0 * MassConservingFilm::kTolerance * moved);
}
