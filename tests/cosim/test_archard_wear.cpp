// Archard's wear maps (docs/coupling.md §7) against hand-computed rates: a uniform contact
// pressure P at a constant sliding speed u wears the skirt at k_p P u everywhere on it, and the liner
// at k_l P u times the share of the time the skirt covers a point, the skirt sliding at u.
#include "cosim/engine/SkirtFilm.hpp"
#include "cosim/wear/ArchardWear.hpp"
#include "SmallEngineCase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace flexehd;
using namespace flexehd::cosim;

TEST(ArchardWear, UniformContactAtConstantSpeedGivesTheHandRates) {
    const EngineCase c = test::smallCase();
    const SkirtFilm film(c.engine, c.piston, c.grid);
    const lube::FilmGrid& g = film.grid();
    const double kp = 2e-16, kl = 5e-17, P = 3e6, u = 4.0, L = g.length();
    const double travel = 0.5 * L, T = travel / u;  // the skirt slides up by half its length
    const double zLow = g.z(0) - 0.1, zHigh = g.z(g.nAxial() - 1) + 0.1;
    ArchardWear wear(g, kp, kl, zLow, zHigh);
    const Eigen::VectorXd pc = Eigen::VectorXd::Constant(g.size(), P);
    const int steps = 2000;
    for (int n = 1; n <= steps; ++n) wear.add(pc, -u, travel * n / steps, T / steps);  // the speed's sign does not count
    wear.finishCycle();
    ASSERT_TRUE(wear.finished());
    double worstSkirt = 0.0;
    for (int k = 0; k < g.size(); ++k)
        if (g.kind(k) != lube::NodeKind::Void) worstSkirt = std::max(worstSkirt, std::abs(wear.pistonRate()[k] / (kp * P * u) - 1.0));
    EXPECT_LT(worstSkirt, 1e-12);
    // A liner point at z is covered while z − s lies on the skirt: the share of the travel s ∈ (0, travel]
    // with g.z(0) ≤ z − s ≤ g.z(last).
    const int j = 0;  // the thrust panel's middle column
    double worstCovered = 0.0, worstPartial = 0.0;
    int partial = 0;
    for (int cell = 0; cell < wear.linerCells(); ++cell) {
        const double z = wear.linerCellZ(cell);
        const double lo = std::max(0.0, z - g.z(g.nAxial() - 1)), hi = std::min(travel, z - g.z(0));
        const double share = std::max(0.0, hi - lo) / travel;
        const double rate = wear.linerRate()[static_cast<Eigen::Index>(cell) * g.nTheta() + j];
        const double err = std::abs(rate - kl * P * u * share) / (kl * P * u);
        if (share == 1.0) worstCovered = std::max(worstCovered, err);
        else if (share > 0.0) {
            worstPartial = std::max(worstPartial, err);
            ++partial;
        }
    }
    EXPECT_LT(worstCovered, 1e-12);
    EXPECT_GT(partial, 5);
    EXPECT_LT(worstPartial, 2.0 / steps);  // the step that covers or uncovers it: one step's share
}
