// The skirt's hard contact with impact damping (docs/lube.md §4, "Impact damping"): at every node
// where the surfaces overlap the contact pressure is K δ max(0, 1 + χ δ̇/δ̇₀), with the approach
// speed δ̇ = −ḣ the step's rate of the node's own unfloored thickness (recomputed here from the
// iterates' thickness fields) and δ̇₀ the node's impact speed — its approach speed on the step it
// touched (at least the quasi-static 1 mm/s), kept while it stays in contact unless a faster
// approach replaces it, forgotten when it leaves. Checked over a landing (backward Euler), a deeper
// press and a rebound (BDF2 steps), a lift-off and a second landing of the small engine's rigid
// skirt; the restitution χ(e)
// itself is tested against the definition of e in tests/lube/test_elastic_foundation.cpp.
#include "cosim/contact/SkirtContact.hpp"
#include "lube/ElasticFoundation.hpp"
#include "SmallEngineCase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace flexehd;
using namespace flexehd::cosim;

TEST(SkirtImpactDamping, EachOverlappingNodeIsASpringWithHysteresisDampingAtItsImpactSpeed) {
    EngineCase c = test::smallCase();
    c.contact.restitution = 0.5;
    const double offset = 0.05;
    SkirtContact skirt(c, CaseBodies{}, [offset](double) { return offset; });
    const double K = lube::ElasticFoundation::layerStiffness(c.contact.coatingModulus, c.contact.coatingPoisson,
                                                             c.contact.coatingThickness);
    const double chi = lube::ElasticFoundation::hysteresisFactor(0.5);

    ContactStep step;
    step.dt = 1e-5;
    step.a0 = 1.0;
    step.a1 = -1.0;
    step.linerOffset = offset;
    WorkTally work;
    const ContactState start = skirt.initialState(offset);
    const Eigen::VectorXd y;

    // Towards the side that closes first.
    ContactIterate probe;
    skirt.evaluate(step, start, start, Eigen::Vector2d(50.4e-6, 0.0), y, probe, work);
    const double side = probe.minGap < 0.0 ? 1.0 : -1.0;

    const auto check = [&](const ContactState& now, const ContactState& before, const Eigen::Vector2d& x,
                           ContactIterate& it, int& touched, int& heldImpact, int& belowElastic) {
        skirt.evaluate(step, now, before, x, y, it, work);
        ASSERT_EQ(it.impactSpeed.size(), it.hTotal.size());
        for (int k = 0; k < it.hTotal.size(); ++k) {
            if (!(it.hTotal[k] < 0.0)) {
                EXPECT_EQ(it.pcHard[k], 0.0);
                continue;
            }
            const double approach =
                -(step.a0 * it.hTotal[k] + step.a1 * now.hTotal[k] + step.a2 * before.hTotal[k]) / step.dt;
            const bool wasTouching = now.impactSpeed.size() && now.hTotal[k] < 0.0;
            const double impact = std::max({wasTouching ? now.impactSpeed[k] : 0.0, approach, 1e-3});
            const double expected = -K * it.hTotal[k] * std::max(0.0, 1.0 + chi * approach / impact);
            EXPECT_NEAR(it.impactSpeed[k], impact, 1e-12 * impact);
            EXPECT_NEAR(it.pcHard[k], expected, 1e-9 * std::max(expected, 1.0)) << "node " << k;
            ++touched;
            if (wasTouching && approach > 0.0 && approach < now.impactSpeed[k]) ++heldImpact;
            if (expected < -K * it.hTotal[k]) ++belowElastic;
        }
    };

    // Landing from the centre: every touching node's first step, damped by 1 + χ.
    ContactIterate land;
    int touched = 0, held = 0, below = 0;
    check(start, start, Eigen::Vector2d(side * 50.4e-6, 0.0), land, touched, held, below);
    EXPECT_GT(touched, 0);
    EXPECT_EQ(held, 0);
    const ContactState landed = skirt.accepted(step, start, land);

    // Pressed deeper: the touching nodes keep their landing's impact speed (much larger).
    ContactIterate press;
    int touched2 = 0, held2 = 0, below2 = 0;
    check(landed, start, Eigen::Vector2d(side * 50.45e-6, 0.0), press, touched2, held2, below2);

    // BDF2 from here on (constant step).
    step.a0 = 1.5;
    step.a1 = -2.0;
    step.a2 = 0.5;
    EXPECT_GE(touched2, touched);
    EXPECT_GT(held2, 0);

    // Rebounding: below the elastic pressure (dissipation), and not below zero.
    const ContactState pressed = skirt.accepted(step, landed, press);
    ContactIterate rebound;
    int touched3 = 0, held3 = 0, below3 = 0;
    check(pressed, landed, Eigen::Vector2d(side * 50.43e-6, 0.0), rebound, touched3, held3, below3);
    EXPECT_GT(touched3, 0);
    EXPECT_EQ(below3, touched3);
    EXPECT_GE(rebound.pcHard.minCoeff(), 0.0);

    // Lifted off, then landing again slowly: the impact speed is the new approach, not the first
    // landing's (the check's `wasTouching` is false for every node).
    const ContactState bounced = skirt.accepted(step, pressed, rebound);
    ContactIterate off;
    skirt.evaluate(step, bounced, pressed, Eigen::Vector2d(side * 49.0e-6, 0.0), y, off, work);
    ASSERT_GT(off.minGap, 0.0);
    EXPECT_EQ(off.pcHard.maxCoeff(), 0.0);
    const ContactState lifted = skirt.accepted(step, bounced, off);
    const ContactState lifted2 = skirt.accepted(step, lifted, off);  // at rest for a step
    ContactIterate again;
    int touched4 = 0, held4 = 0, below4 = 0;
    check(lifted2, lifted, Eigen::Vector2d(side * 50.3e-6, 0.0), again, touched4, held4, below4);
    EXPECT_GT(touched4, 0);
    EXPECT_EQ(held4, 0);
    for (int k = 0; k < again.hTotal.size(); ++k)
        if (again.hTotal[k] < 0.0) EXPECT_LT(again.impactSpeed[k], 0.5 * land.impactSpeed.maxCoeff());
}

TEST(SkirtImpactDamping, AnElasticLayerKeepsNoImpactState) {
    EngineCase c = test::smallCase();  // restitution 1 by default
    SkirtContact skirt(c, CaseBodies{}, [](double) { return 0.05; });
    ContactStep step;
    step.dt = 1e-5;
    step.linerOffset = 0.05;
    WorkTally work;
    const ContactState start = skirt.initialState(0.05);
    ContactIterate it;
    skirt.evaluate(step, start, start, Eigen::Vector2d(50.6e-6, 0.0), Eigen::VectorXd(), it, work);
    if (!(it.minGap < 0.0)) skirt.evaluate(step, start, start, Eigen::Vector2d(-50.6e-6, 0.0), Eigen::VectorXd(), it, work);
    ASSERT_LT(it.minGap, 0.0);
    EXPECT_EQ(it.impactSpeed.size(), 0);
    const double K = lube::ElasticFoundation::layerStiffness(c.contact.coatingModulus, c.contact.coatingPoisson,
                                                             c.contact.coatingThickness);
    for (int k = 0; k < it.hTotal.size(); ++k)
        if (it.hTotal[k] < 0.0) EXPECT_DOUBLE_EQ(it.pcHard[k], -K * it.hTotal[k]);
}
