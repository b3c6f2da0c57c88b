// bench_lube: times PSOR, the active-set and the multigrid solver to the same relative natural residual on a
// skirt-like film and on a plain journal bearing, at grids nAxial×nTheta from 64×128 up.
// Not a test: prints a Markdown table (scripts/bench_lube.sh writes it into docs/).
//   bench_lube [maxAxial=512] [tolerance=1e-8] [repeats=1] [multigrid]
// Each time is the best of `repeats` cold solves (a fresh ReynoldsSolver each), which filters
// out the noise of a shared machine. With a fourth argument `multigrid` only the multigrid solver
// is timed (short table), for profiling and before/after comparisons.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "lube/FilmIntegrals.hpp"
#include "lube/ReynoldsSolver.hpp"

using namespace flexehd::lube;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Problem {
    FilmGrid grid;
    FilmState film;
};

// Journal: L/D = 1, ε = 0.7, R = 50 mm, c = 50 µm, ω = 100 rad/s, open ends at 0.
Problem journal(int nz, int nt) {
    const double R = 0.05, c = 50e-6;
    Problem p{FilmGrid::fullCircumference(R, FilmGrid::uniform(-R, R, nz), nt), {}};
    p.film.h.resize(p.grid.size());
    for (int k = 0; k < p.grid.size(); ++k)
        p.film.h[k] = c * (1 + 0.7 * std::cos(p.grid.theta(p.grid.thetaIndex(k))));
    p.film.inner.circumferential = 100.0 * R;
    return p;
}

// Skirt-like: R = 45 mm, skirt 40 mm long (axial spacing graded finer at the ends), clearance
// 20 µm, barrel 15 µm, piston tilted (eccentricity +15 µm at the top, −5 µm at the bottom,
// towards +x), tilting at 0.05 rad/s·… (squeeze), liner sliding at −8 m/s relative to the piston,
// pin-boss relief (Void) for |θ ∓ 90°| < 30°.
Problem skirt(int nz, int nt) {
    const double R = 0.045, L = 0.04, c = 20e-6;
    std::vector<double> z = FilmGrid::uniform(0.0, 1.0, nz);
    for (double& v : z) v = L * (v - 0.15 * std::sin(2 * kPi * v) / (2 * kPi));
    Problem p{FilmGrid::fullCircumference(R, z, nt), {}};
    p.film.h.resize(p.grid.size());
    p.film.dhdt.resize(p.grid.size());
    for (int k = 0; k < p.grid.size(); ++k) {
        const double zz = p.grid.z(p.grid.axialIndex(k)) / L, th = p.grid.theta(p.grid.thetaIndex(k));
        const double e = 15e-6 * zz - 5e-6 * (1 - zz), edot = 2e-3 * (zz - 0.5);
        p.film.h[k] = c + 15e-6 * std::pow(2 * zz - 1, 2) - e * std::cos(th);
        p.film.dhdt[k] = -edot * std::cos(th);
        const double d = std::min(std::abs(std::remainder(th - kPi / 2, 2 * kPi)),
                                  std::abs(std::remainder(th + kPi / 2, 2 * kPi)));
        if (d < kPi / 6) p.grid.voidNode(k);
    }
    p.film.outer.axial = -8.0;
    return p;
}

}  // namespace

int main(int argc, char** argv) {
    const int maxAxial = argc > 1 ? std::atoi(argv[1]) : 512;
    const double tol = argc > 2 ? std::atof(argv[2]) : 1e-8;
    const int repeats = std::max(1, argc > 3 ? std::atoi(argv[3]) : 1);
    if (argc > 4 && std::string(argv[4]) == "multigrid") {
        std::printf("| problem | grid | multigrid it. (coarse) | best multigrid s | µs/node |\n|---|---|---|---|---|\n");
        for (const std::string name : {"skirt", "journal"})
            for (int nz = 64; nz <= maxAxial; nz *= 2) {
                double best = 1e300;
                ReynoldsResult r;
                for (int rep = 0; rep < repeats; ++rep) {
                    Problem pb = name == "skirt" ? skirt(nz, 2 * nz) : journal(nz, 2 * nz);
                    ReynoldsOptions opt;
                    opt.solver = SolverKind::Multigrid;
                    opt.control.tolerance = tol;
                    ReynoldsSolver rs(pb.grid, Lubricant(0.01), opt);
                    const auto t0 = std::chrono::steady_clock::now();
                    r = rs.solve(pb.film);
                    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                }
                std::printf("| %s | %d×%d | %d (%d) | %.4f | %.3f |\n", name.c_str(), nz, 2 * nz, r.iterations,
                            r.coarseIterations, best, 1e6 * best / (2 * nz * nz));
                std::fflush(stdout);
            }
        return 0;
    }
    std::printf("| problem | grid (axial×circ.) | nodes | PSOR sweeps | PSOR s | active-set it. "
                "(coarse) | active-set s | multigrid it. (coarse) | multigrid s | multigrid µs/node "
                "| speed-up vs PSOR | max |Δp|/p_max PSOR | max |Δp|/p_max multigrid |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    const SolverKind kinds[3] = {SolverKind::Psor, SolverKind::ActiveSet, SolverKind::Multigrid};
    for (const std::string name : {"skirt", "journal"}) {
        for (int nz = 64; nz <= maxAxial; nz *= 2) {
            const int nt = 2 * nz;
            ReynoldsResult res[3];
            double sec[3];
            for (int s = 0; s < 3; ++s) {
                sec[s] = 1e300;
                for (int rep = 0; rep < repeats; ++rep) {
                    Problem pb = name == "skirt" ? skirt(nz, nt) : journal(nz, nt);
                    ReynoldsOptions opt;
                    opt.solver = kinds[s];
                    opt.control.tolerance = tol;
                    opt.control.maxIterations = 1000000;
                    ReynoldsSolver rs(pb.grid, Lubricant(0.01), opt);
                    const auto t0 = std::chrono::steady_clock::now();
                    res[s] = rs.solve(pb.film);
                    sec[s] = std::min(sec[s], std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                }
            }
            // Errors against the active-set answer (exact to round-off).
            const double pmax = res[1].pressure.maxCoeff();
            auto err = [&](int s) { return (res[s].pressure - res[1].pressure).cwiseAbs().maxCoeff() / pmax; };
            std::printf("| %s | %d×%d | %d | %d | %.3f | %d (%d) | %.3f | %d (%d) | %.3f | %.2f | %.0f | "
                        "%.1e | %.1e |\n",
                        name.c_str(), nz, nt, nz * nt, res[0].iterations, sec[0],
                        res[1].iterations, res[1].coarseIterations, sec[1], res[2].iterations,
                        res[2].coarseIterations, sec[2], 1e6 * sec[2] / (nz * nt), sec[0] / sec[2],
                        err(0), err(2));
            std::fflush(stdout);
        }
    }
    return 0;
}
