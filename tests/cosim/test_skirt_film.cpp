// The skirt film's panels at their true edges (docs/lube.md §1, cut control volumes): the film
// forces and the dissipation follow the panel half-angle continuously — no staircase when the
// edge crosses a grid column — and their slope with the half-angle is the grid-converged one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "SmallEngineCase.hpp"
#include "cosim/engine/SkirtFilm.hpp"
#include "lube/FilmIntegrals.hpp"
#include "lube/ReynoldsSolver.hpp"

using namespace flexehd;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct PanelLoads {
    double lateral;      ///< N, film pressure force along x (thrust side)
    double dissipation;  ///< W
};

/// The example skirt at a fixed eccentric, tilted position, sliding at 10 m/s, on a grid of
/// nz × nt nodes with the panels ±halfAngleDeg about θ = 0 and π.
PanelLoads panelLoads(double halfAngleDeg, int nz, int nt) {
    cosim::EngineCase c = test::smallCase();
    c.piston.skirtHalfAngle = halfAngleDeg * kDeg;
    c.grid = {nz, nt};
    const cosim::SkirtFilm skirt(c.engine, c.piston, c.grid);
    lube::FilmState film;
    skirt.rigidThickness(0.6 * c.piston.clearance, 0.4e-3, film.h);
    film.outer.axial = -10.0;
    const lube::Lubricant oil(c.lubricant.viscosity, c.lubricant.density);
    lube::ReynoldsSolver solver(skirt.grid(), oil);
    const Eigen::VectorXd p = solver.solve(film).pressure;
    const lube::FilmLoads loads = lube::integrateFilm(skirt.grid(), film, oil, p);
    return {loads.pressureForce.x(), loads.viscousDissipation};
}

}  // namespace

TEST(SkirtPanel, FilmForcesFollowTheHalfAngleSmoothlyAndAtTheConvergedRate) {
    // 72 columns: Δθ = 5°, a column at 40°. The half-angle runs from 36.25° to 43.75° across it;
    // a panel of whole columns would give four equal values and a jump.
    std::vector<double> angles, lateral, power;
    for (double a = 36.25; a <= 43.76; a += 1.25) angles.push_back(a);
    for (double a : angles) {
        const PanelLoads l = panelLoads(a, 24, 72);
        lateral.push_back(l.lateral);
        power.push_back(l.dissipation);
        std::printf("  half-angle %.2f deg: lateral force %.3f N, dissipation %.4f W\n", a, l.lateral, l.dissipation);
    }
    // Each step of the half-angle changes both by about the same amount (a smooth, not a
    // staircase, dependence): consecutive differences within a factor 1.5 of each other.
    for (std::size_t i = 1; i + 1 < angles.size(); ++i) {
        for (const std::vector<double>* v : {&lateral, &power}) {
            const double d0 = (*v)[i] - (*v)[i - 1], d1 = (*v)[i + 1] - (*v)[i];
            EXPECT_GT(d0 * d1, 0.0) << "at " << angles[i] << " deg";
            EXPECT_LT(std::max(d0 / d1, d1 / d0), 1.5) << "at " << angles[i] << " deg";
        }
    }
    // The slope between 37.5° and 42.5° against the same slope on a grid 4× finer each way.
    const PanelLoads lo = panelLoads(37.5, 24, 72), hi = panelLoads(42.5, 24, 72);
    const PanelLoads loFine = panelLoads(37.5, 96, 288), hiFine = panelLoads(42.5, 96, 288);
    const double slopeF = (hi.lateral - lo.lateral) / 5.0, slopeFFine = (hiFine.lateral - loFine.lateral) / 5.0;
    const double slopeP = (hi.dissipation - lo.dissipation) / 5.0;
    const double slopePFine = (hiFine.dissipation - loFine.dissipation) / 5.0;
    std::printf("  slope of the lateral force %.4f N/deg (fine grid %.4f), of the dissipation %.5f W/deg (%.5f)\n",
                slopeF, slopeFFine, slopeP, slopePFine);
    EXPECT_NEAR(slopeF, slopeFFine, 0.05 * std::abs(slopeFFine));
    EXPECT_NEAR(slopeP, slopePFine, 0.05 * std::abs(slopePFine));
}
