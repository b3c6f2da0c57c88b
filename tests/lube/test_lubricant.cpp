// Pressure-dependent lubricant: model formulas and the Barus reduced-pressure solution.
#include <gtest/gtest.h>

#include <cmath>

#include "lube/FilmIntegrals.hpp"
#include "lube/ReynoldsSolver.hpp"

using namespace flexehd::lube;

TEST(Lubricant, ModelsAtReferencePoints) {
    Lubricant iso(0.01, 850.0);
    EXPECT_EQ(iso.viscosity(1e9), 0.01);
    EXPECT_FALSE(iso.pressureDependent());
    Lubricant dh = Lubricant(0.01, 850.0).withDowsonHigginson();
    EXPECT_NEAR(dh.density(1e9) / 850.0, 1.0 + 0.6 / 2.7, 1e-12);  // Dowson–Higginson at 1 GPa
    EXPECT_EQ(dh.density(-1e5), 850.0);
    Lubricant barus = Lubricant(0.01).withBarus(2e-8);
    EXPECT_NEAR(barus.viscosity(1e8), 0.01 * std::exp(2.0), 1e-15);
    // Roelands shares the Barus slope α at p = 0 and is below Barus at high pressure.
    Lubricant roelands = Lubricant(0.01).withRoelands(2e-8);
    const double d = 1e3;
    EXPECT_NEAR(std::log(roelands.viscosity(d) / roelands.viscosity(0.0)) / d, 2e-8, 1e-11);
    EXPECT_LT(roelands.viscosity(5e8), barus.viscosity(5e8));
    EXPECT_THROW(Lubricant(0.01).withBarus(-1.0), std::invalid_argument);
}

// Barus viscosity only scales the Poiseuille term, so the reduced pressure
// q = (1 − e^{−αp})/α satisfies the iso-viscous Reynolds equation (classical transformation):
// p_Barus = −ln(1 − α q_iso)/α. Check on an inclined slider with α q_max ≈ 0.5 (a 2× viscosity
// rise): the Picard solution matches the transform to discretisation error (face-averaged η:
// 8e-4 at 41 nodes, 2e-4 at 81 nodes of p_max), shrinking 4× per halving.
TEST(Lubricant, BarusMatchesReducedPressureTransform) {
    const double mu = 0.05, U = 5.0, B = 0.02, h0 = 10e-6;
    double prev = 1.0;
    for (int n : {41, 81}) {
        FilmGrid g = FilmGrid::arc(1000.0, FilmGrid::uniform(0.0, B, n), -1e-3, 1e-3, 3);
        g.setEdge(Edge::ArcStart, EdgeCondition::Symmetry);
        g.setEdge(Edge::ArcEnd, EdgeCondition::Symmetry);
        FilmState st;
        st.h.resize(g.size());
        for (int k = 0; k < g.size(); ++k) st.h[k] = h0 * (2 - g.z(g.axialIndex(k)) / B);
        st.inner.axial = U;
        const ReynoldsResult iso = ReynoldsSolver(g, Lubricant(mu)).solve(st);
        const double alpha = 0.5 / iso.pressure.maxCoeff();
        ReynoldsSolver barus(g, Lubricant(mu).withBarus(alpha));
        const ReynoldsResult r = barus.solve(st);
        EXPECT_GT(r.picardIterations, 3);
        double err = 0.0;
        for (int k = 0; k < g.size(); ++k) {
            const double ref = -std::log(1 - alpha * iso.pressure[k]) / alpha;
            err = std::max(err, std::abs(r.pressure[k] - ref));
        }
        err /= r.pressure.maxCoeff();
        EXPECT_LT(err, n == 81 ? 3e-4 : 1.2e-3) << "n " << n;
        EXPECT_LT(err, prev / 3.5);
        prev = err;
    }
}
