// lube::minimumFilmSpan against node counts taken from the closed form of the film: a journal
// bearing's h = c (1 + ε cos θ), whose region h ≤ 2 h_min holds the nodes with
// 1 + ε cos θ_j ≤ 2 (1 − ε), and a tilted skirt's h = h0 + β (z − z_low), cut by the film's edge.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "lube/FilmGrid.hpp"
#include "lube/MinimumFilmRegion.hpp"

using namespace flexehd::lube;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Nodes j of an nθ-node full circumference with c (1 + ε cos θ_j) ≤ 2 c (1 − ε).
int bearingNodes(int nTheta, double eps) {
    int n = 0;
    for (int j = 0; j < nTheta; ++j)
        if (1.0 + eps * std::cos(2 * kPi * j / nTheta) <= 2.0 * (1.0 - eps) + 1e-15) ++n;
    return n;
}

}  // namespace

TEST(MinimumFilmRegion, JournalBearingSpanMatchesTheClosedForm) {
    const double c = 50e-6;
    for (int nTheta : {64, 128, 144, 512})
        for (double eps : {0.9, 0.99, 0.999}) {
            const FilmGrid g = FilmGrid::fullCircumference(0.04, FilmGrid::uniform(0.0, 0.04, 9), nTheta);
            Eigen::VectorXd h(g.size());
            for (int k = 0; k < g.size(); ++k) h[k] = c * (1.0 + eps * std::cos(g.theta(g.thetaIndex(k))));
            const double hMin = c * (1.0 - eps);
            const MinimumFilmSpan s = minimumFilmSpan(g, h, hMin);
            EXPECT_NEAR(s.minFilm, h.minCoeff(), 0.0);
            EXPECT_EQ(s.circumferential, bearingNodes(nTheta, eps)) << nTheta << " nodes, eps " << eps;
            EXPECT_EQ(s.axial, 9) << "h does not vary along z: the whole column";
        }
}

TEST(MinimumFilmRegion, ATiltedSkirtsEdgeCutsTheRegion) {
    // h = 1 um + 2e-3 (z − z_low): thinnest on the lower edge, within 1 um of it up to 0.5 mm in.
    const std::vector<double> z = FilmGrid::uniform(-0.025, 0.011, 49);  // 0.75 mm spacing
    const FilmGrid g = FilmGrid::arc(0.043, z, -0.7, 0.7, 41);
    Eigen::VectorXd h(g.size());
    for (int k = 0; k < g.size(); ++k) h[k] = 1e-6 + 2e-3 * (g.z(g.axialIndex(k)) - z.front());
    const MinimumFilmSpan s = minimumFilmSpan(g, h, 1e-6);
    EXPECT_TRUE(s.atAxialEdge);
    EXPECT_EQ(g.axialIndex(s.node), 0);
    EXPECT_EQ(s.axial, 1) << "0.5 mm of region, 0.75 mm spacing";
    EXPECT_EQ(s.circumferential, 41) << "h does not vary around the arc";
    const MinimumFilmSpan wide = minimumFilmSpan(g, h, 2e-3 * 0.0031);  // 3.1 mm: nodes 0..4
    EXPECT_EQ(wide.axial, 5);
}
