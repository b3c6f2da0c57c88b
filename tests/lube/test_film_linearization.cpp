// FilmLinearization (the film's generalized Jacobian for the coupled Newton method) against
// central differences of full complementarity solves (the active-set solver, an independent
// route: it knows nothing of the linearisation), on a cavitated journal bearing with squeeze,
// an odd number of columns (the colouring across the periodic wrap) and masked nodes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "lube/FilmLinearization.hpp"
#include "lube/ReynoldsSolver.hpp"
#include "tests/lube/LubeTestSupport.hpp"

using namespace flexehd::lube;
using flexehd::lube::test::Journal;
using flexehd::lube::test::kPi;

namespace {

struct Case {
    FilmGrid grid;
    FilmState film;
    Eigen::VectorXd dh, dhdt;  // a direction of change
};

Case journalWithSqueeze(int nTheta, int nZ, bool masks, bool arcs = false) {
    Journal jb;
    jb.eps = 0.6;
    Case c{jb.finiteGrid(2 * jb.R, nTheta, nZ), {}, {}, {}};
    if (arcs) c.grid.restrictToArcs({{-1.0137, 1.2291}, {2.0511, 4.1033}});  // ends between nodes
    if (masks)  // a relief pocket away from the load line
        for (int k = 0; k < c.grid.size(); ++k) {
            const double th = c.grid.theta(c.grid.thetaIndex(k)), z = c.grid.z(c.grid.axialIndex(k));
            if (std::abs(std::remainder(th - 0.5 * kPi, 2 * kPi)) < 0.3 && std::abs(z) < 0.02) c.grid.voidNode(k);
        }
    c.film = jb.state(c.grid);
    const int n = c.grid.size();
    c.film.dhdt.resize(n);
    c.dh.resize(n);
    c.dhdt.resize(n);
    for (int k = 0; k < n; ++k) {
        const double th = c.grid.theta(c.grid.thetaIndex(k)), z = c.grid.z(c.grid.axialIndex(k)) / jb.R;
        c.film.dhdt[k] = -2e-3 * std::cos(th - 0.4);  // the journal closes the gap near θ = 0.4
        c.dh[k] = jb.c * (0.3 * std::cos(2 * th) + 0.2 * z + 0.1 * std::sin(th) * z * z);
        c.dhdt[k] = 1e-3 * (std::sin(th) + 0.5 * z * std::cos(3 * th));
    }
    return c;
}

Eigen::VectorXd solve(const Case& c, double s, Cavitation cav) {
    ReynoldsOptions opt;
    opt.solver = SolverKind::ActiveSet;
    opt.cavitation = cav;
    opt.control.tolerance = 1e-14;
    ReynoldsSolver rs(c.grid, Lubricant(0.01, 850.0), opt);
    FilmState f = c.film;
    f.h += s * c.dh;
    f.dhdt += s * c.dhdt;
    return rs.solve(f).pressure;
}

// max |δp_lin − δp_fd| / max |δp_fd| with δp_fd the central difference with step s.
double relativeError(const Case& c, Cavitation cav, double* cavitatedFraction) {
    const int n = c.grid.size();
    const double pLower = cav == Cavitation::Reynolds ? 0.0 : -std::numeric_limits<double>::infinity();
    const Eigen::VectorXd p = solve(c, 0.0, cav);
    FilmLinearization lin(c.grid);
    lin.linearize(c.film, Eigen::VectorXd::Constant(n, 850.0), Eigen::VectorXd::Constant(n, 0.01), p, pLower);
    if (cavitatedFraction) *cavitatedFraction = double(lin.cavitatedNodes()) / n;
    EXPECT_LE(lin.colours(), 13) << "a distance-2 colouring of a 5-point grid needs few colours";
    const double s = 1e-5;
    const Eigen::VectorXd fd = (solve(c, s, cav) - solve(c, -s, cav)) / (2 * s);
    const Eigen::MatrixXd dp = lin.pressureChange(c.dh, c.dhdt);
    // The two parts separately too: thickness only and rate only.
    const Eigen::MatrixXd both = lin.pressureChange(c.dh, Eigen::MatrixXd()) + lin.pressureChange(Eigen::MatrixXd(), c.dhdt);
    EXPECT_LT((both - dp).cwiseAbs().maxCoeff(), 1e-12 * dp.cwiseAbs().maxCoeff());
    const Eigen::MatrixXd scaled = lin.pressureChange(c.dh, Eigen::MatrixXd(0.5 * c.dhdt), 2.0);  // δḣ = 2 · dhdt/2
    EXPECT_LT((scaled - dp).cwiseAbs().maxCoeff(), 1e-12 * dp.cwiseAbs().maxCoeff());
    EXPECT_GT(fd.cwiseAbs().maxCoeff(), 0.0);
    const double err = (dp.col(0) - fd).cwiseAbs().maxCoeff() / fd.cwiseAbs().maxCoeff();
    std::printf("relative error %.3g, rate part alone %.3g\n", err, (lin.pressureChange(Eigen::MatrixXd(), c.dhdt).col(0) - fd).cwiseAbs().maxCoeff() / fd.cwiseAbs().maxCoeff());
    return err;
}

}  // namespace

TEST(FilmLinearization, MatchesDifferencesOfCavitatedSolves) {
    const Case c = journalWithSqueeze(73, 21, true);  // odd column count: colouring across the wrap
    double cavitated = 0.0;
    const double err = relativeError(c, Cavitation::Reynolds, &cavitated);
    EXPECT_GT(cavitated, 0.2) << "the check must include a cavitated region";
    EXPECT_LT(err, 1e-6);
}

// Bearing surfaces on two arcs cut between nodes (FilmGrid::restrictToArcs): the face values at
// the cuts depend on the neighbour beyond the cut column, which the linearisation must see.
TEST(FilmLinearization, MatchesDifferencesOnArcsCutBetweenNodes) {
    const Case c = journalWithSqueeze(72, 21, false, true);
    const double err = relativeError(c, Cavitation::Reynolds, nullptr);
    EXPECT_LT(err, 1e-6);
}

TEST(FilmLinearization, MatchesDifferencesOfTheLinearProblem) {
    const Case c = journalWithSqueeze(48, 17, false);
    double cavitated = 1.0;
    const double err = relativeError(c, Cavitation::None, &cavitated);
    EXPECT_EQ(cavitated, 0.0);
    EXPECT_LT(err, 1e-6);
}

TEST(FilmLinearization, BadInputIsNamed) {
    const Case c = journalWithSqueeze(24, 9, false);
    FilmLinearization lin(c.grid);
    const int n = c.grid.size();
    EXPECT_THROW(lin.linearize(c.film, Eigen::VectorXd::Constant(n, 850.0), Eigen::VectorXd::Constant(n, 0.01),
                               Eigen::VectorXd::Zero(n - 1), 0.0),
                 std::invalid_argument);
    lin.linearize(c.film, Eigen::VectorXd::Constant(n, 850.0), Eigen::VectorXd::Constant(n, 0.01),
                  Eigen::VectorXd::Zero(n), 0.0);
    EXPECT_THROW(lin.pressureChange(Eigen::MatrixXd::Zero(n + 1, 2), Eigen::MatrixXd()), std::invalid_argument);
}
