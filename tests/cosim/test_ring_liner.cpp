// A ring on a flexible liner (RingContact, docs/ring-pack.md, "A ring as a film contact"): its
// film and asperity pressure, lumped onto the load grid's rows across its height, is what presses
// the liner — in the radial balance exactly the tension and the gas behind the ring, at the
// ring's height (the barrel's middle at rest; the oil-control ring's lands, nothing between
// them) — and the liner's quasi-static response to that modal load opens the bore there.
#include "cosim/ringpack/RingContact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "fem/MeshReader.hpp"
#include "modal/CraigBamptonReducer.hpp"
#include "RingCases.hpp"

using namespace flexehd;
using namespace flexehd::cosim;
using test::barrelRing;
using test::ringCase;

namespace {

constexpr double kOffsetLow = -0.12, kOffsetHigh = -0.04;  // liner offsets the ring's load grid slides over (m)

// meshes/liner.geo coarse (9 mm), cast iron, both seats tied and held, 20 modes.
std::shared_ptr<const FlexibleBody> reducedLiner() {
    static const std::shared_ptr<const FlexibleBody> liner = [] {
        const fem::Mesh m = fem::readMesh(std::string(FLEXEHD_SOURCE_DIR) + "/meshes/liner.geo", {2, 0.009});
        modal::CraigBamptonReducer reducer(m, fem::ElasticMaterial{1.1e11, 0.26, 7200.0});
        modal::ReductionSettings rs;
        rs.normalModes = 20;
        return std::make_shared<const FlexibleBody>(
            reducer.reduce({modal::parseInterface("top_seat:rbe2"), modal::parseInterface("bottom_seat:rbe2")}, rs),
            std::vector<std::string>{});
    }();
    return liner;
}

EngineCase linerCase() {
    EngineCase c = ringCase();
    c.linerBody.model = BodyModel::Flexible;
    c.linerBody.surface = "bore";
    return c;
}

// The iterate of a step of dt at a constant piston velocity and cylinder pressure, settled.
ContactIterate settled(RingContact& ring, double velocity, double pressure) {
    ContactStep step;
    step.dt = 1e-4;
    step.pistonVelocity = velocity;
    step.cylinderPressure = pressure;
    step.linerOffset = -0.08;
    ContactState now = ring.initialState(step.linerOffset);
    ContactIterate it;
    WorkTally work;
    for (int k = 0; k < 400; ++k) {
        ring.evaluate(step, now, now, Eigen::Vector2d::Zero(), Eigen::VectorXd(), it, work);
        const double change = std::abs(it.minGap - now.minGap);
        now = ring.accepted(step, now, it);
        if (change <= 1e-10 * std::abs(now.minGap)) break;
    }
    return it;
}

// The rows' force per unit circumference (N/m) and their centroid (piston-frame z, m).
std::pair<double, double> rowsForce(const RingContact& ring, const ContactIterate& it) {
    const lube::FilmGrid& g = *ring.loadGrid();
    double w = 0.0, moment = 0.0;
    for (int i = 0; i < g.nAxial(); ++i) {
        const double f = it.linerLoad[g.index(i, 0)] * g.axialWidth(i);
        w += f;
        moment += f * g.z(i);
    }
    return {w, moment / w};
}

}  // namespace

TEST(RingLiner, TheRingPressesTheLinerWithItsTensionAndGasAtItsHeight) {
    const EngineCase c = linerCase();
    const double T = 209.0, b = 1.15e-3;
    const RingSpec spec = barrelRing(b, 8e-6, T, 0.3e-6);
    RingContact ring(c, spec, true, 101, nullptr, reducedLiner(), kOffsetLow, kOffsetHigh);
    ASSERT_NE(ring.loadGrid(), nullptr);
    // At rest the asperities carry the tension, symmetric about the barrel's middle.
    const ContactIterate rest = settled(ring, 0.0, 0.0);
    const auto [w0, z0] = rowsForce(ring, rest);
    std::printf("at rest: %.6g N/m on the liner (tension %.6g), centroid %.4g mm (ring middle %.4g mm)\n", w0, T,
                1e3 * z0, 1e3 * (spec.groove.lowerFlank + 0.5 * b));
    EXPECT_NEAR(w0 / T, 1.0, 1e-3);
    EXPECT_NEAR(z0, spec.groove.lowerFlank + 0.5 * b, 1e-3 * b);
    // Sliding with 50 kPa in the cylinder, above and behind the top ring: tension and gas.
    const ContactIterate sliding = settled(ring, -8.0, 5e4);
    const auto [w1, z1] = rowsForce(ring, sliding);
    std::printf("sliding, 50 kPa: %.6g N/m (tension + gas %.6g)\n", w1, T + 5e4 * b);
    EXPECT_NEAR(w1 / (T + 5e4 * b), 1.0, 1e-3);
    EXPECT_GT(z1, spec.groove.lowerFlank);
    EXPECT_LT(z1, spec.top());

    // The liner's quasi-static response to the ring's modal load opens the bore at the ring.
    Eigen::VectorXd f = Eigen::VectorXd::Zero(reducedLiner()->modes());
    ContactStep step;
    step.linerOffset = -0.08;
    WorkTally work;
    ring.addModalLoad(step, sliding, f, work);
    Eigen::VectorXd q;
    reducedLiner()->quasiStatic(f, q);
    const FlexibleSurface bore(reducedLiner(), FlexibleSurface::Side::Liner, "bore", *ring.loadGrid(),
                               kOffsetLow + spec.groove.lowerFlank - 1e-3, kOffsetHigh + spec.top() + 1e-3);
    Eigen::VectorXd dh;
    bore.filmChange(q, step.linerOffset, dh);
    std::printf("bore opened by %.3g .. %.3g m under the ring\n", dh.minCoeff(), dh.maxCoeff());
    EXPECT_GT(dh.minCoeff(), 0.0);
}

TEST(RingLiner, TheOilControlRingPressesWithItsLandsAlone) {
    const EngineCase c = linerCase();
    RingSpec oil = barrelRing(2.43e-3, 0.0, 580.0, 0.3e-6);
    oil.kind = RingKind::OilControl;
    oil.lands = OilControlLandsSpec{0.4e-3, 2.03e-3, 4e-6};
    oil.groove = {0.0138, 0.07e-3, 1.2e-3};
    RingContact ring(c, oil, false, 201, nullptr, reducedLiner(), kOffsetLow, kOffsetHigh);
    const ContactIterate rest = settled(ring, 0.0, 0.0);
    const lube::FilmGrid& g = *ring.loadGrid();
    double total = 0.0, between = 0.0;
    for (int i = 0; i < g.nAxial(); ++i) {
        const double f = rest.linerLoad[g.index(i, 0)] * g.axialWidth(i);
        total += f;
        const double z = g.z(i) - oil.groove.lowerFlank;
        if (z > oil.lands->width && z < oil.height - oil.lands->width) between += std::abs(f);
    }
    std::printf("oil-control ring at rest: %.6g N/m on the liner, %.3g between its lands\n", total, between);
    EXPECT_NEAR(total / oil.tensionPerLength, 1.0, 1e-3);
    EXPECT_EQ(between, 0.0);
}
