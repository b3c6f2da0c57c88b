// The multigrid solver (TNNMG, lube/MultigridSolver) against the two independent methods for
// the same complementarity problem: PSOR (the seed's baseline) and the active-set solver
// (exact to round-off), on a journal bearing and on a skirt-like film with graded axial
// spacing, pin-boss masks, squeeze and sliding; plus warm start, level-independent iteration
// counts and clear failure.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>
#include <stdexcept>

#include "lube/ReynoldsSolver.hpp"
#include "tests/lube/LubeTestSupport.hpp"

using namespace flexehd::lube;
using flexehd::lube::test::Journal;
using flexehd::lube::test::kPi;

namespace {

ReynoldsResult solveWith(const FilmGrid& g, const FilmState& st, SolverKind kind, double tol,
                         Cavitation cav = Cavitation::Reynolds) {
    ReynoldsOptions opt;
    opt.solver = kind;
    opt.cavitation = cav;
    opt.control.tolerance = tol;
    ReynoldsSolver rs(g, Lubricant(0.01), opt);
    return rs.solve(st);
}

double maxDiff(const ReynoldsResult& a, const ReynoldsResult& b) {
    return (a.pressure - b.pressure).cwiseAbs().maxCoeff() / b.pressure.cwiseAbs().maxCoeff();
}

// Skirt-like film: R = 45 mm, 40 mm long, axial spacing graded 0.85:1.15, clearance 20 µm,
// barrel 15 µm, tilted and tilting piston, liner sliding at −8 m/s, pin-boss relief masked.
struct Skirt {
    FilmGrid grid;
    FilmState film;
};
Skirt skirt(int nz, int nt) {
    const double R = 0.045, L = 0.04, c = 20e-6;
    std::vector<double> z = FilmGrid::uniform(0.0, 1.0, nz);
    for (double& v : z) v = L * (v - 0.15 * std::sin(2 * kPi * v) / (2 * kPi));
    Skirt s{FilmGrid::fullCircumference(R, z, nt), {}};
    s.film.h.resize(s.grid.size());
    s.film.dhdt.resize(s.grid.size());
    for (int k = 0; k < s.grid.size(); ++k) {
        const double zz = s.grid.z(s.grid.axialIndex(k)) / L, th = s.grid.theta(s.grid.thetaIndex(k));
        const double e = 15e-6 * zz - 5e-6 * (1 - zz), edot = 2e-3 * (zz - 0.5);
        s.film.h[k] = c + 15e-6 * std::pow(2 * zz - 1, 2) - e * std::cos(th);
        s.film.dhdt[k] = -edot * std::cos(th);
        const double d = std::min(std::abs(std::remainder(th - kPi / 2, 2 * kPi)),
                                  std::abs(std::remainder(th + kPi / 2, 2 * kPi)));
        if (d < kPi / 6) s.grid.voidNode(k);
    }
    s.film.outer.axial = -8.0;
    return s;
}

}  // namespace

// Journal L/D = 1, ε = 0.7 (cavitated): multigrid = active set = PSOR to the tolerance.
TEST(Multigrid, JournalEqualsActiveSetAndPsor) {
    Journal jb;
    jb.eps = 0.7;
    const FilmGrid g = jb.finiteGrid(2 * jb.R, 72, 25);
    const FilmState st = jb.state(g);
    const ReynoldsResult mg = solveWith(g, st, SolverKind::Multigrid, 1e-11);
    const ReynoldsResult as = solveWith(g, st, SolverKind::ActiveSet, 1e-11);
    const ReynoldsResult ps = solveWith(g, st, SolverKind::Psor, 1e-11);
    EXPECT_LE(mg.residual, 1e-11);
    EXPECT_GT(as.pressure.maxCoeff(), 1e5);
    EXPECT_LT(maxDiff(mg, as), 1e-9);
    EXPECT_LT(maxDiff(mg, ps), 1e-8);
    EXPECT_EQ(mg.pressure.minCoeff(), 0.0) << "cavitated nodes sit exactly at p_cav";
    EXPECT_GT(mg.iterations, 0);
    EXPECT_LT(mg.iterations, 20);
}

// Skirt: graded spacing, masks, squeeze and axial sliding, anisotropic cells (Δz ≈ RΔθ/3).
TEST(Multigrid, SkirtEqualsActiveSet) {
    const Skirt s = skirt(48, 96);
    const ReynoldsResult mg = solveWith(s.grid, s.film, SolverKind::Multigrid, 1e-11);
    const ReynoldsResult as = solveWith(s.grid, s.film, SolverKind::ActiveSet, 1e-11);
    EXPECT_LT(maxDiff(mg, as), 1e-9);
    EXPECT_GT((mg.pressure.array() <= 0.0).count(), s.grid.size() / 10) << "must be cavitated";
    const ReynoldsResult full = solveWith(s.grid, s.film, SolverKind::Multigrid, 1e-11, Cavitation::None);
    const ReynoldsResult fullAs = solveWith(s.grid, s.film, SolverKind::ActiveSet, 1e-11, Cavitation::None);
    EXPECT_LT(maxDiff(full, fullAs), 1e-9) << "unconstrained (linear) problem";
}

// Skirt on a full circumference with an odd number of columns: θ cannot be halved (z-only
// coarsening, the general Galerkin product), the zebra colouring has two adjacent even columns
// across the wrap (the fused z-line cycle then corrects every column), and the coarser levels
// turn to θ- or alternating lines as z coarsens. Same answer as the active set.
TEST(Multigrid, SkirtOddPeriodicColumns) {
    const Skirt s = skirt(40, 95);
    const ReynoldsResult mg = solveWith(s.grid, s.film, SolverKind::Multigrid, 1e-11);
    const ReynoldsResult as = solveWith(s.grid, s.film, SolverKind::ActiveSet, 1e-11);
    EXPECT_LT(maxDiff(mg, as), 1e-9);
    EXPECT_GT((mg.pressure.array() <= 0.0).count(), s.grid.size() / 10) << "must be cavitated";
    EXPECT_LT(mg.iterations, 20);
}

// Open arc (no periodic wrap, odd node count), supply hole at a prescribed pressure, non-uniform
// axial spacing; cavitation at a negative p_cav.
TEST(Multigrid, OpenArcWithSupplyHole) {
    Journal jb;
    jb.eps = 0.5;
    std::vector<double> z = FilmGrid::uniform(0.0, 1.0, 33);
    for (double& v : z) v = 0.06 * v * v;  // graded, non-uniform
    z[0] = 0.0;
    FilmGrid g = FilmGrid::arc(jb.R, z, 0.2, 0.2 + 1.5 * kPi, 97);
    g.fixNode(g.index(16, 48), 2e5);
    const FilmState st = jb.state(g);
    for (Cavitation cav : {Cavitation::Reynolds, Cavitation::None}) {
        ReynoldsOptions opt;
        opt.cavitation = cav;
        opt.cavitationPressure = -2e4;
        opt.control.tolerance = 1e-11;
        ReynoldsResult r[2];
        for (int s = 0; s < 2; ++s) {
            opt.solver = s == 0 ? SolverKind::Multigrid : SolverKind::ActiveSet;
            ReynoldsSolver rs(g, Lubricant(0.01), opt);
            r[s] = rs.solve(st);
        }
        EXPECT_LT(maxDiff(r[0], r[1]), 1e-9);
        if (cav == Cavitation::Reynolds) {
            EXPECT_NEAR(r[0].pressure.minCoeff(), -2e4, 1e-9);
        }
    }
}

// Multigrid property: with nested iteration (the default cold start: coarse solves prolonged),
// the number of fine V-cycles does not grow with the grid (16× more nodes); a warm start from
// the answer needs none. (From p = p_cav without nesting the cavitation boundary needs more
// iterations to travel, docs/lube.md §3.)
TEST(Multigrid, IterationsIndependentOfGridAndWarmStart) {
    Journal jb;
    jb.eps = 0.7;
    int its[2];
    for (int s = 0; s < 2; ++s) {
        const int nt = s == 0 ? 64 : 256;
        ReynoldsOptions opt;
        opt.solver = SolverKind::Multigrid;
        ReynoldsSolver rs(jb.finiteGrid(2 * jb.R, nt, nt / 2 + 1), Lubricant(jb.mu), opt);
        const ReynoldsResult r = rs.solve(jb.state(rs.grid()));
        its[s] = r.iterations;
        if (s == 1) {
            const ReynoldsResult again = rs.solve(jb.state(rs.grid()), &r.pressure);
            EXPECT_EQ(again.iterations, 0);
            EXPECT_LT((again.pressure - r.pressure).cwiseAbs().maxCoeff(), 1e-6 * r.pressure.maxCoeff());
        }
    }
    EXPECT_LE(its[1], its[0] + 1) << its[0] << " -> " << its[1];
    EXPECT_LE(its[1], 8);
}

// An iteration budget too small for the tolerance: a clear error, no NaN.
TEST(Multigrid, NotConvergedThrows) {
    Journal jb;
    ReynoldsOptions opt;
    opt.solver = SolverKind::Multigrid;
    opt.gridSequencing = false;
    opt.control.tolerance = 1e-14;
    opt.control.maxIterations = 1;
    ReynoldsSolver rs(jb.finiteGrid(2 * jb.R, 64, 17), Lubricant(jb.mu), opt);
    try {
        rs.solve(jb.state(rs.grid()));
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("not converged after 1 iterations"), std::string::npos)
            << e.what();
    }
}

// ReynoldsOptions::fallback: the solve multigrid cannot finish within its iteration limit is
// redone by the active-set method, whose answer is exact to round-off: the result equals an
// active-set solve of its own and says that it fell back.
TEST(Multigrid, AStalledSolveIsRedoneByTheFallbackSolver) {
    Journal jb;
    jb.eps = 0.7;
    ReynoldsOptions opt;
    opt.solver = SolverKind::Multigrid;
    opt.gridSequencing = false;
    opt.control.tolerance = 1e-12;
    opt.control.maxIterations = 1;
    opt.fallback = SolverKind::ActiveSet;
    ReynoldsSolver rs(jb.finiteGrid(2 * jb.R, 64, 17), Lubricant(jb.mu), opt);
    const FilmState st = jb.state(rs.grid());
    const ReynoldsResult r = rs.solve(st);
    EXPECT_TRUE(r.fellBack);
    const ReynoldsResult as = solveWith(rs.grid(), st, SolverKind::ActiveSet, 1e-12);
    EXPECT_LT(maxDiff(r, as), 1e-12);
    EXPECT_GT(as.pressure.maxCoeff(), 1e5);
    // A re-solve with a new squeeze rate after the fallback solved: the fallback's system, again
    // equal to an active-set solve of the changed film.
    FilmState squeezed = st;
    squeezed.dhdt = Eigen::VectorXd::Constant(rs.grid().size(), -2e-3);
    const ReynoldsResult again = rs.resolve(squeezed.dhdt, r.pressure);
    EXPECT_TRUE(again.fellBack);
    const ReynoldsResult freshSqueezed = solveWith(rs.grid(), squeezed, SolverKind::ActiveSet, 1e-12);
    EXPECT_LT(maxDiff(again, freshSqueezed), 1e-12);
    EXPECT_GT(maxDiff(freshSqueezed, as), 1e-3) << "the squeeze must change the film";
    opt.control.maxIterations = 200;
    ReynoldsSolver converging(rs.grid(), Lubricant(jb.mu), opt);
    EXPECT_FALSE(converging.solve(st).fellBack) << "a converged multigrid solve is kept";
}

// The ReynoldsSystem stencil lives in LargeArrayAllocator storage, which does not zero new
// memory, so assembly must write every entry: on a masked skirt grid large enough for the
// huge-page path (5 doubles × 128×256 nodes ≥ 1 MiB), built right after a block of the same
// size was filled with garbage and freed (the allocator may hand it out again), every stencil
// entry must equal the compressed-column matrix (couplings to non-Film nodes 0, non-Film rows
// identities) and be finite.
TEST(Multigrid, StencilFullyWrittenWithoutZeroFill) {
    const Skirt s = skirt(128, 256);
    const int n = s.grid.size(), nt = s.grid.nTheta();
    constexpr std::size_t m = ReynoldsSystem::kStencilSize;
    {
        LargeVector<double> junk(m * static_cast<std::size_t>(n));
        for (double& v : junk) v = std::nan("");
    }
    const ReynoldsSystem sys(s.grid, s.film, 850.0, 0.01);
    const auto& st = sys.stencil();
    ASSERT_EQ(st.size(), m * static_cast<std::size_t>(n));
    const SparseMatrix& A = sys.matrix();
    int voidRows = 0;
    for (int k = 0; k < n; ++k) {
        const int i = k / nt, j = k % nt;
        const int nb[3] = {k, i * nt + (j + 1) % nt, i + 1 < s.grid.nAxial() ? k + nt : -1};
        const int e3[3] = {ReynoldsSystem::kStencilC, ReynoldsSystem::kStencilE, ReynoldsSystem::kStencilN};
        for (int e = 0; e < 3; ++e) {
            const double v = st[m * static_cast<std::size_t>(k) + static_cast<std::size_t>(e3[e])];
            ASSERT_TRUE(std::isfinite(v)) << "node " << k << " entry " << e;
            const double ref = nb[e] < 0 ? 0.0 : A.coeff(k, nb[e]);
            ASSERT_EQ(v, ref) << "node " << k << " entry " << e;
        }
        if (!sys.isFilm(k)) {
            ++voidRows;
            EXPECT_EQ(st[m * static_cast<std::size_t>(k) + ReynoldsSystem::kStencilC], 1.0);
        }
    }
    EXPECT_GT(voidRows, n / 4);  // the pin-boss masks are in the test
}

// The symmetric 3-value stencil (C, E, N per node; W and S read from the neighbours' E and N,
// ReynoldsSystem::westStencilColumn) reproduces all five entries of every row of A: on a
// periodic masked skirt grid with an odd column count (the wrap pairs column nθ − 1 with 0) and
// on an open arc with a fixed node (where the west entry of column 0 must come out 0).
TEST(Multigrid, SymmetricStencilReproducesMatrix) {
    Skirt s = skirt(24, 45);
    Journal jb;
    std::vector<double> z = FilmGrid::uniform(0.0, 0.06, 17);
    FilmGrid arc = FilmGrid::arc(jb.R, z, 0.2, 0.2 + 1.5 * kPi, 31);
    arc.fixNode(arc.index(8, 15), 2e5);
    const FilmState arcState = jb.state(arc);
    for (int c = 0; c < 2; ++c) {
        const FilmGrid& g = c == 0 ? s.grid : arc;
        const ReynoldsSystem sys(g, c == 0 ? s.film : arcState, 850.0, 0.01);
        const auto& st = sys.stencil();
        const SparseMatrix& A = sys.matrix();
        const int nz = g.nAxial(), nt = g.nTheta();
        constexpr std::size_t m = ReynoldsSystem::kStencilSize;
        auto entry = [&](int i, int j, int e) { return st[m * static_cast<std::size_t>(i * nt + j) + static_cast<std::size_t>(e)]; };
        int masked = 0;
        for (int i = 0; i < nz; ++i)
            for (int j = 0; j < nt; ++j) {
                const int k = i * nt + j;
                masked += !sys.isFilm(k);
                const bool hasW = j > 0 || g.periodic(), hasE = j + 1 < nt || g.periodic();
                const double ref[5] = {i > 0 ? A.coeff(k, k - nt) : 0.0,
                                       hasW ? A.coeff(k, i * nt + (j + nt - 1) % nt) : 0.0, A.coeff(k, k),
                                       hasE ? A.coeff(k, i * nt + (j + 1) % nt) : 0.0,
                                       i + 1 < nz ? A.coeff(k, k + nt) : 0.0};
                const double got[5] = {i > 0 ? entry(i - 1, j, ReynoldsSystem::kStencilN) : entry(nz - 1, j, ReynoldsSystem::kStencilN),
                                       entry(i, ReynoldsSystem::westStencilColumn(j, nt), ReynoldsSystem::kStencilE),
                                       entry(i, j, ReynoldsSystem::kStencilC), entry(i, j, ReynoldsSystem::kStencilE),
                                       entry(i, j, ReynoldsSystem::kStencilN)};
                for (int e = 0; e < 5; ++e) ASSERT_EQ(got[e], ref[e]) << "grid " << c << " node " << k << " entry " << e;
            }
        EXPECT_GT(masked, 0);
        EXPECT_EQ(nt % 2, 1);
    }
}

// Nested iteration on one hierarchy (MultigridSolver::prepare, used by ReynoldsSolver's cold
// start): a solve on a coarse grid of the fine hierarchy, and afterwards on the fine grid, gives
// the same iterates, bit for bit, as separate solvers with hierarchies of their own (the levels,
// their work arrays and the free-row ranges of the line sweeps are reused, not shared state).
TEST(Multigrid, SharedHierarchyEqualsSeparateSolvers) {
    const Skirt s = skirt(64, 128);
    std::vector<int> map;
    const std::optional<FilmGrid> coarse = s.grid.coarsened(map);
    ASSERT_TRUE(coarse.has_value());
    FilmState cf;
    cf.outer = s.film.outer;
    cf.h.resize(coarse->size());
    cf.dhdt.resize(coarse->size());
    for (int I = 0; I < coarse->nAxial(); ++I)
        for (int J = 0; J < coarse->nTheta(); ++J) {
            const int kf = s.grid.index(map[static_cast<std::size_t>(I)], 2 * J);
            cf.h[coarse->index(I, J)] = s.film.h[kf];
            cf.dhdt[coarse->index(I, J)] = s.film.dhdt[kf];
        }
    const ReynoldsSystem coarseSys(*coarse, cf, 850.0, 0.01), fineSys(s.grid, s.film, 850.0, 0.01);
    SolverControl control;
    control.tolerance = 1e-10;
    MultigridSolver shared, alone, aloneFine;
    shared.prepare(s.grid);
    ASSERT_TRUE(shared.hasLevel(*coarse));
    Eigen::VectorXd p1, p2;
    const SolveReport r1 = shared.solve(coarseSys, p1, 0.0, control);
    const SolveReport r2 = alone.solve(coarseSys, p2, 0.0, control);
    EXPECT_EQ(r1.iterations, r2.iterations);
    EXPECT_EQ((p1 - p2).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(shared.levels(), alone.levels());
    Eigen::VectorXd q1, q2;  // then the fine grid, cold, on the hierarchy used for the coarse solve
    const SolveReport f1 = shared.solve(fineSys, q1, 0.0, control);
    const SolveReport f2 = aloneFine.solve(fineSys, q2, 0.0, control);
    EXPECT_EQ(f1.iterations, f2.iterations);
    EXPECT_EQ((q1 - q2).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_GT((q1.array() <= 0.0).count(), s.grid.size() / 10) << "must be cavitated";
}

// SolverControl::minIterations (used for the nested coarse solves of a cold start): a converged
// warm start still gets that many iterations, and stays the answer.
TEST(Multigrid, MinIterationsOnConvergedStart) {
    Journal jb;
    jb.eps = 0.7;
    ReynoldsOptions opt;
    opt.solver = SolverKind::Multigrid;
    ReynoldsSolver rs(jb.finiteGrid(2 * jb.R, 128, 65), Lubricant(jb.mu), opt);
    const ReynoldsResult r = rs.solve(jb.state(rs.grid()));
    opt.control.minIterations = 1;
    ReynoldsSolver rs1(jb.finiteGrid(2 * jb.R, 128, 65), Lubricant(jb.mu), opt);
    const ReynoldsResult again = rs1.solve(jb.state(rs1.grid()), &r.pressure);
    EXPECT_EQ(again.iterations, 1);
    EXPECT_LE(again.residual, opt.control.tolerance);
    EXPECT_LT((again.pressure - r.pressure).cwiseAbs().maxCoeff(), 1e-6 * r.pressure.maxCoeff());
}

// A re-solve with a new squeeze rate on the kept system and hierarchy (ReynoldsSolver::resolve,
// the JFO solver's passes) gives the pressure a fresh solve of that film gives, to the
// tolerance, and the same solution from the same start whichever solver path: the skirt film
// with its squeeze rate doubled and reversed in turn, and the multigrid against the active set.
TEST(Multigrid, ResolveWithANewSqueezeRateEqualsAFreshSolve) {
    Skirt s = skirt(33, 96);
    for (SolverKind kind : {SolverKind::Multigrid, SolverKind::ActiveSet}) {
        ReynoldsOptions opt;
        opt.solver = kind;
        opt.control.tolerance = 1e-11;
        ReynoldsSolver rs(s.grid, Lubricant(0.01), opt);
        const ReynoldsResult first = rs.solve(s.film);
        for (double factor : {2.0, -1.0}) {
            FilmState changed = s.film;
            changed.dhdt *= factor;
            const ReynoldsResult again = rs.resolve(changed.dhdt, first.pressure);
            const ReynoldsResult fresh = solveWith(s.grid, changed, SolverKind::ActiveSet, 1e-11);
            EXPECT_LT(maxDiff(again, fresh), 1e-8) << "solver " << int(kind) << ", squeeze x" << factor;
            EXPECT_GT(maxDiff(first, fresh), 1e-3) << "the squeeze change must change the film";
        }
    }
    ReynoldsSolver unused(s.grid, Lubricant(0.01), ReynoldsOptions{});
    EXPECT_THROW(unused.resolve(s.film.dhdt, Eigen::VectorXd::Zero(s.grid.size())), std::logic_error);
}
