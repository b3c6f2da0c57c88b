// coupling.elastic_squeeze: the squeeze term carries the elastic deformation rate and each step is
// solved by semismooth Newton on (e, β, y) with the film's linearisation (docs/coupling.md §3).
//
// The check is made from outside the simulation, with the run's written states only: at every
// written step whose two predecessors are written too (uniform steps of 0.25°), the film
// thickness h = h_rigid(e, β) + Δh(y) of the three states gives ∂h/∂t by BDF2; the film is solved
// from scratch by the active-set solver (not the run's multigrid solver) and the skirt's
// quasi-static response q = C Φᵀ A (p + p_c) must reproduce the run's modal coordinates y to the
// coupling tolerance. The same check with the rigid rate only must fail — the elastic rate is
// not negligible in this run — so the check can tell the two equations apart.
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "lube/ReynoldsSolver.hpp"
#include "CliRunner.hpp"
#include "RecordedRun.hpp"
#include "SmallEngineCase.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace flexehd::cosim;
namespace lube = flexehd::lube;
namespace fs = std::filesystem;

TEST(ElasticSqueeze, StepsSolveTheEquationsWithTheElasticRate) {
    const fs::path dir = fs::temp_directory_path() / ("flexehd_squeeze_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string file = (dir / "piston.h5").string();
    const auto red = flexehd::test::reduceSmallPiston(file);
    ASSERT_EQ(red.status, 0) << red.err;

    EngineCase c = flexehd::test::smallFlexibleCase(file);
    c.coupling.elasticSqueeze = true;
    flexehd::test::checkableSteps(c);
    PistonSimulation sim(c);
    ASSERT_EQ(sim.contact<SkirtContact>().clearance(), nullptr);  // h_rigid is the skirt film's alone
    // Through BDC (pure squeeze) and the firing slap.
    const flexehd::test::RecordedRun run = flexehd::test::recordRun(sim, 400.0);
    const std::vector<StepRecord>& steps = run.steps;
    const std::vector<Snapshot>& snaps = run.snapshots;

    const lube::FilmGrid& g = sim.contact<SkirtContact>().film().grid();
    const FlexibleSurface& body = *sim.contact<SkirtContact>().piston();
    lube::ReynoldsOptions opt;
    opt.solver = lube::SolverKind::ActiveSet;
    opt.cavitation = lube::Cavitation::Reynolds;
    opt.control.tolerance = 1e-12;
    lube::ReynoldsSolver solver(g, lube::Lubricant(c.lubricant.viscosity, c.lubricant.density), opt);
    const lube::GreenwoodTripp contact(c.contact.sigma, c.contact.beta, c.contact.asperityDensity,
                                       c.contact.compositeModulus);
    auto total = [&](const Snapshot& s) {
        Eigen::VectorXd h, dh;
        sim.contact<SkirtContact>().film().rigidThickness(s.lateral, s.tilt, h);
        body.filmChange(s.pistonModal, 0.0, dh);
        return std::pair<Eigen::VectorXd, Eigen::VectorXd>(h + dh, h);
    };
    // The three states are three consecutive accepted steps (no shortened step in between).
    auto consecutive = [&](double deg0, double deg1, double deg2) {
        for (std::size_t k = 2; k < steps.size(); ++k)
            if (std::abs(steps[k].crankDeg - deg2) < 1e-9)
                return std::abs(steps[k - 1].crankDeg - deg1) < 1e-9 && std::abs(steps[k - 2].crankDeg - deg0) < 1e-9;
        return false;
    };
    const double tolH = c.coupling.tolerance * c.piston.clearance;
    double worstFull = 0.0, worstRigidOnly = 0.0, largestElasticRate = 0.0;
    int checked = 0;
    for (std::size_t i = 2; i < snaps.size(); i += 2) {  // every other step: the test's time
        const Snapshot &s0 = snaps[i - 2], &s1 = snaps[i - 1], &s2 = snaps[i];
        // Three consecutive accepted steps of 0.25° (written states, no step in between).
        if (std::abs(s2.crankDeg - s1.crankDeg - 0.25) > 1e-9 || std::abs(s1.crankDeg - s0.crankDeg - 0.25) > 1e-9 ||
            !consecutive(s0.crankDeg, s1.crankDeg, s2.crankDeg))
            continue;
        const double dt = 0.25 * sim.kinematics().secondsPerDegree();
        const auto [h2, r2] = total(s2);
        const auto [h1, r1] = total(s1);
        const auto [h0, r0] = total(s0);
        for (int pass = 0; pass < 2; ++pass) {  // 0: full rate, 1: rigid rate only
            lube::FilmState f;
            f.outer.axial = -sim.kinematics().at(s2.crankDeg).velocity;
            f.dhdt = pass == 0 ? Eigen::VectorXd((1.5 * h2 - 2.0 * h1 + 0.5 * h0) / dt)
                               : Eigen::VectorXd((1.5 * r2 - 2.0 * r1 + 0.5 * r0) / dt);
            f.h = h2;
            Eigen::VectorXd pc = Eigen::VectorXd::Zero(g.size());
            for (int k = 0; k < g.size(); ++k) {
                if (g.kind(k) == lube::NodeKind::Void) continue;
                pc[k] = contact.pressure(std::max(h2[k], -2.0 * c.contact.sigma));
                f.h[k] = std::max(f.h[k], 0.05 * c.contact.sigma);  // the run's floor
            }
            const Eigen::VectorXd p = solver.solve(f).pressure;
            Eigen::VectorXd q, dh;
            body.respond(p + pc, 0.0, q);
            body.filmChange(q - s2.pistonModal, 0.0, dh);
            double r = 0.0;
            for (int k = 0; k < g.size(); ++k)
                if (g.kind(k) != lube::NodeKind::Void) r = std::max(r, std::abs(dh[k]));
            (pass == 0 ? worstFull : worstRigidOnly) = std::max(pass == 0 ? worstFull : worstRigidOnly, r);
            if (pass == 0) {
                const Eigen::VectorXd elasticRate = (1.5 * (h2 - r2) - 2.0 * (h1 - r1) + 0.5 * (h0 - r0)) / dt;
                largestElasticRate = std::max(largestElasticRate, elasticRate.cwiseAbs().maxCoeff());
            }
        }
        ++checked;
    }
    std::printf("%d steps checked: max |Δh(H(y) − y)| %.3g m with the elastic rate, %.3g m with the rigid rate "
                "only (tolerance %.3g m); largest elastic rate %.3g m/s\n",
                checked, worstFull, worstRigidOnly, tolH, largestElasticRate);
    EXPECT_GE(checked, 500);
    // The run's stopping criterion is max|Δh(H(y) − y)| ≤ tol·c with its own film solver (relative
    // residual 1e-8); the independent solve may differ by that much more.
    EXPECT_LT(worstFull, 2.0 * tolH);
    EXPECT_GT(worstRigidOnly, 100.0 * tolH) << "the check must distinguish the two squeeze terms";
    fs::remove_all(dir);
}
