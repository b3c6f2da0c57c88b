// The coupling residual formed where a test needs it (docs/coupling.md §1): the skirt's bound
// Σ_j |dy_j| max|Ψ_j| is an upper bound of the film change max_i |Σ_j Ψ_ij dy_j| (the triangle
// inequality) and equals it for the change of one mode alone; CouplingResidual's tests decide as
// the exact value does and form it only where the bound does not settle them.
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/coupling/CouplingResidual.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "CliRunner.hpp"
#include "SmallEngineCase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <random>
#include <unistd.h>

using namespace flexehd;
using namespace flexehd::cosim;
namespace fs = std::filesystem;

TEST(CouplingResidual, TheSkirtsBoundHoldsAndIsExactForOneMode) {
    const fs::path dir = fs::temp_directory_path() / ("flexehd_coupling_residual_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string file = (dir / "piston.h5").string();
    const auto red = test::reduceSmallPiston(file);
    ASSERT_EQ(red.status, 0) << red.err;
    PistonSimulation sim(test::smallFlexibleCase(file));
    const SkirtContact& skirt = sim.contact<SkirtContact>();
    const int m = skirt.piston()->modes();
    ASSERT_GT(m, 4);
    WorkTally work;
    const ContactStep step;
    // One mode alone: the bound is its shape's largest film change, the exact value itself.
    for (int j = 0; j < m; ++j) {
        const Eigen::VectorXd e = Eigen::VectorXd::Unit(m, j) * (j % 2 ? -1.0 : 1.0);
        const double exact = skirt.filmChange(step, e, work), bound = skirt.filmChangeBound(e);
        ASSERT_GT(exact, 0.0) << "mode " << j;
        EXPECT_NEAR(bound, exact, 1e-11 * exact) << "mode " << j;
    }
    // Random changes, dense and of a few modes: bound ≥ exact.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> pick(0, m - 1);
    double loosest = 1.0;
    for (int trial = 0; trial < 200; ++trial) {
        Eigen::VectorXd dy = Eigen::VectorXd::Zero(m);
        if (trial % 2)
            for (int j = 0; j < m; ++j) dy[j] = u(rng);
        else
            for (int k = 0; k < 3; ++k) dy[pick(rng)] = u(rng);
        const double exact = skirt.filmChange(step, dy, work), bound = skirt.filmChangeBound(dy);
        ASSERT_GE(bound, exact) << "trial " << trial;
        loosest = std::max(loosest, bound / exact);
    }
    std::printf("bound / exact at most %.2f over 200 modal changes of %d modes\n", loosest, m);
    fs::remove_all(dir);
}

TEST(CouplingResidual, ItsTestsDecideAsTheExactValueAndFormItOnlyWhereTheBoundDoesNot) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int formed = 0, settledByTheBound = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        const double exact = 4.0 * u(rng), bound = exact * (1.0 + 3.0 * u(rng));
        const double limit = 4.0 * u(rng), unit = 0.1 + u(rng), floor = 8.0 * u(rng);
        int calls = 0;
        auto make = [&] { return CouplingResidual(bound, [&] { return ++calls, exact; }); };
        CouplingResidual a = make();
        EXPECT_EQ(a.atMost(limit), exact <= limit);
        EXPECT_EQ(calls, bound <= limit ? 0 : 1);
        calls = 0;
        CouplingResidual b = make();
        EXPECT_EQ(b.measure(unit, floor), std::max(exact / unit, floor));
        EXPECT_EQ(calls, bound / unit <= floor ? 0 : 1);
        b.measure(unit, floor);  // formed once at most
        EXPECT_LE(calls, 1);
        formed += calls;
        settledByTheBound += calls == 0;
    }
    EXPECT_GT(formed, 0);
    EXPECT_GT(settledByTheBound, 0);
    CouplingResidual rigid;
    EXPECT_TRUE(rigid.atMost(0.0));
    EXPECT_EQ(rigid.measure(1.0, 0.5), 0.5);
}
