// bench_lube: times PSOR, the active-set and the multigrid solver to the same relative natural residual on a
// skirt-like film and on a plain journal bearing, at grids nAxial×nTheta from 64×128 up.
// Not a test: prints a Markdown table (scripts/bench_lube.sh writes it into docs/).
//   bench_lube [maxAxial=512] [tolerance=1e-8] [repeats=1] [multigrid|omega|jfo]
// Each time is the best of `repeats` cold solves (a fresh ReynoldsSolver each; in the full
// table after one untimed cold solve of each solver, PSOR's being its ω scan), which filters
// out the noise of a shared machine; the full table also gives the best thread CPU times (not
// inflated while other processes hold the core) and their ratio. PSOR runs at its automatic ω and at the best ω of a scan
// (see the full table below). With a fourth argument `multigrid` only the multigrid solver is
// timed (short table, with CPU time and a solver reused across cold solves), for profiling and
// before/after comparisons; `omega` scans PSOR's ω at the grid maxAxial × 2·maxAxial; `jfo` times
// the cold mass-conserving solve against the multigrid Reynolds solve on the steady skirt.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>

#include "lube/FilmIntegrals.hpp"
#include "lube/JfoSolver.hpp"
#include "lube/LargeArrayAllocator.hpp"
#include "lube/PsorSolver.hpp"
#include "lube/ReynoldsSolver.hpp"

using namespace flexehd::lube;

namespace {

constexpr double kPi = 3.14159265358979323846;

// CPU time of this thread (s): unlike wall-clock time, not inflated while other processes
// hold the core.
double cpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

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
    // The allocator setting of the flexehd command line (freed blocks stay in the heap), so the
    // solvers run as they do there.
    retainFreedHeapMemory();
    const int maxAxial = argc > 1 ? std::atoi(argv[1]) : 512;
    const double tol = argc > 2 ? std::atof(argv[2]) : 1e-8;
    const int repeats = std::max(1, argc > 3 ? std::atoi(argv[3]) : 1);
    if (argc > 4 && std::string(argv[4]) == "omega") {
        // PSOR relaxation scan at one grid (maxAxial × 2·maxAxial): is the automatic ω optimal?
        std::printf("| problem | grid | ω | PSOR sweeps | PSOR s |\n|---|---|---|---|---|\n");
        for (const std::string name : {"skirt", "journal"}) {
            const int nz = maxAxial;
            Problem pb0 = name == "skirt" ? skirt(nz, 2 * nz) : journal(nz, 2 * nz);
            // ω = 2/(1 + f·s) with s = (2 − ω_auto)/ω_auto, i.e. f = 1 is the automatic choice.
            const double w0 = PsorSolver::automaticOmega(pb0.grid), s0 = (2.0 - w0) / w0;
            for (double f : {0.7, 0.85, 1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0}) {
                const double w = 2.0 / (1.0 + f * s0), dw = f - 1.0;
                double best = 1e300;
                ReynoldsResult r;
                for (int rep = 0; rep < repeats; ++rep) {
                    Problem pb = name == "skirt" ? skirt(nz, 2 * nz) : journal(nz, 2 * nz);
                    ReynoldsOptions opt;
                    opt.solver = SolverKind::Psor;
                    opt.omega = w;
                    opt.control.tolerance = tol;
                    opt.control.maxIterations = 1000000;
                    ReynoldsSolver rs(pb.grid, Lubricant(0.01), opt);
                    const auto t0 = std::chrono::steady_clock::now();
                    r = rs.solve(pb.film);
                    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                }
                std::printf("| %s | %d×%d | %.4f%s | %d | %.3f |\n", name.c_str(), nz, 2 * nz, w,
                            dw == 0.0 ? " (auto)" : "", r.iterations, best);
                std::fflush(stdout);
            }
        }
        return 0;
    }
    if (argc > 4 && std::string(argv[4]) == "jfo") {
        // The mass-conserving film against the Reynolds condition on the steady skirt (no
        // squeeze), cold: a fresh solver each, no warm start (the JFO active set starts from the
        // multigrid Reynolds solution and factorizes with KLU, its ordering included).
        std::printf("| grid | multigrid Reynolds s | JFO active set s (factorizations) | JFO multigrid s (passes) | "
                    "ratio active set / multigrid to Reynolds | max |Δp|/p_max active set, multigrid |\n"
                    "|---|---|---|---|---|---|\n");
        for (int nz = 64; nz <= maxAxial; nz *= 2) {
            double bestR = 1e300, bestJ = 1e300, bestM = 1e300, dp = 0.0, dpm = 0.0;
            int fact = 0, passes = 0;
            for (int rep = 0; rep < repeats; ++rep) {
                Problem pb = skirt(nz, 2 * nz);
                pb.film.dhdt.resize(0);
                ReynoldsOptions opt;
                opt.solver = SolverKind::Multigrid;
                opt.control.tolerance = tol;
                ReynoldsSolver rs(pb.grid, Lubricant(0.01), opt);
                auto t0 = std::chrono::steady_clock::now();
                const Eigen::VectorXd pr = rs.solve(pb.film).pressure;
                bestR = std::min(bestR, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                JfoOptions jo;
                jo.method = JfoMethod::ActiveSet;
                jo.control.tolerance = tol;
                t0 = std::chrono::steady_clock::now();
                const JfoSolver js(pb.grid, Lubricant(0.01), jo);
                const JfoResult jr = js.solve(pb.film);
                bestJ = std::min(bestJ, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                fact = jr.factorizations;
                dp = (jr.pressure - pr).cwiseAbs().maxCoeff() / pr.cwiseAbs().maxCoeff();
                jo.method = JfoMethod::Multigrid;
                t0 = std::chrono::steady_clock::now();
                const JfoSolver jm(pb.grid, Lubricant(0.01), jo);
                const JfoResult mr = jm.solve(pb.film);

                bestM = std::min(bestM, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                passes = mr.iterations;
                dpm = (mr.pressure - jr.pressure).cwiseAbs().maxCoeff() / jr.pressure.cwiseAbs().maxCoeff();
            }
            std::printf("| %d×%d | %.4f | %.4f (%d) | %.4f (%d) | %.2f, %.2f | %.2g, %.2g |\n", nz, 2 * nz, bestR, bestJ, fact,
                        bestM, passes, bestJ / bestR, bestM / bestR, dp, dpm);
            std::fflush(stdout);
        }
        return 0;
    }
    if (argc > 4 && std::string(argv[4]) == "multigrid") {
        std::printf("| problem | grid | multigrid it. (coarse) | best multigrid s | µs/node | best CPU s | reused solver s |\n|---|---|---|---|---|---|---|\n");
        for (const std::string name : {"skirt", "journal"})
            for (int nz = 64; nz <= maxAxial; nz *= 2) {
                double best = 1e300, bestCpu = 1e300;
                ReynoldsResult r;
                for (int rep = 0; rep < repeats; ++rep) {
                    Problem pb = name == "skirt" ? skirt(nz, 2 * nz) : journal(nz, 2 * nz);
                    ReynoldsOptions opt;
                    opt.solver = SolverKind::Multigrid;
                    opt.control.tolerance = tol;
                    ReynoldsSolver rs(pb.grid, Lubricant(0.01), opt);
                    const double c0 = cpuSeconds();
                    const auto t0 = std::chrono::steady_clock::now();
                    r = rs.solve(pb.film);
                    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                    bestCpu = std::min(bestCpu, cpuSeconds() - c0);
                }
                // The same cold solve (no warm start) repeated with one ReynoldsSolver, as in a
                // co-simulation: its memory is allocated once.
                double reused = 1e300;
                {
                    Problem pb = name == "skirt" ? skirt(nz, 2 * nz) : journal(nz, 2 * nz);
                    ReynoldsOptions opt;
                    opt.solver = SolverKind::Multigrid;
                    opt.control.tolerance = tol;
                    ReynoldsSolver rs(pb.grid, Lubricant(0.01), opt);
                    for (int rep = 0; rep <= repeats; ++rep) {
                        const auto t0 = std::chrono::steady_clock::now();
                        rs.solve(pb.film);
                        if (rep > 0) reused = std::min(reused, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                    }
                }
                std::printf("| %s | %d×%d | %d (%d) | %.4f | %.3f | %.4f | %.4f |\n", name.c_str(), nz, 2 * nz, r.iterations,
                            r.coarseIterations, best, 1e6 * best / (2 * nz * nz), bestCpu, reused);
                std::fflush(stdout);
            }
        return 0;
    }
    // Full table. PSOR is run at the automatic ω and at the best ω of a scan (fewest sweeps of
    // ω = 2/(1 + f·s), s = (2 − ω_auto)/ω_auto, f = 0.85 … 2.2, f = 1 being the automatic
    // value): the speed-up is quoted against the tuned PSOR, which a user would not know in
    // advance, and against the automatic one.
    std::printf("| problem | grid (axial×circ.) | nodes | PSOR ω auto → tuned | PSOR sweeps auto / tuned | "
                "PSOR s auto / tuned | active-set it. (coarse) | active-set s | multigrid it. (coarse) | "
                "multigrid s | multigrid µs/node | speed-up vs tuned PSOR (vs auto) | "
                "CPU s tuned PSOR / multigrid, speed-up | "
                "max |Δp|/p_max PSOR | max |Δp|/p_max multigrid |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const std::string name : {"skirt", "journal"}) {
        for (int nz = 64; nz <= maxAxial; nz *= 2) {
            const int nt = 2 * nz;
            // One timed cold solve (a fresh ReynoldsSolver); its thread CPU time goes to lastCpu.
            double lastCpu = 0.0;
            auto run = [&](SolverKind kind, double omega, ReynoldsResult& out) {
                Problem pb = name == "skirt" ? skirt(nz, nt) : journal(nz, nt);
                ReynoldsOptions opt;
                opt.solver = kind;
                opt.omega = omega;
                opt.control.tolerance = tol;
                opt.control.maxIterations = 1000000;
                ReynoldsSolver rs(pb.grid, Lubricant(0.01), opt);
                const double c0 = cpuSeconds();
                const auto t0 = std::chrono::steady_clock::now();
                out = rs.solve(pb.film);
                const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                lastCpu = cpuSeconds() - c0;
                return t;
            };
            // Best wall time of `repeats` solves (the first may be given); best CPU time in cpu.
            auto best = [&](SolverKind kind, double omega, ReynoldsResult& out, double first, double& cpu) {
                double t = first;
                for (int rep = first < 1e300 ? 1 : 0; rep < repeats; ++rep) {
                    t = std::min(t, run(kind, omega, out));
                    cpu = std::min(cpu, lastCpu);
                }
                return t;
            };
            // PSOR: ω scan (one solve each), then best of `repeats` at the automatic and best ω.
            const Problem pb0 = name == "skirt" ? skirt(nz, nt) : journal(nz, nt);
            const double wAuto = PsorSolver::automaticOmega(pb0.grid), s0 = (2.0 - wAuto) / wAuto;
            double wBest = wAuto, tAuto = 1e300, tBest = 1e300, cAuto = 1e300, cBest = 1e300;
            int sweepsAuto = 0, sweepsBest = 1 << 30;
            ReynoldsResult psor, psorAuto;
            for (double f : {0.85, 1.0, 1.25, 1.5, 1.8, 2.2}) {
                const double w = f == 1.0 ? wAuto : 2.0 / (1.0 + f * s0);
                ReynoldsResult r;
                const double t = run(SolverKind::Psor, w, r);
                if (f == 1.0) {
                    sweepsAuto = r.iterations;
                    tAuto = t;
                    cAuto = lastCpu;
                    psorAuto = r;
                }
                if (r.iterations < sweepsBest) {
                    sweepsBest = r.iterations;
                    wBest = w;
                    tBest = t;
                    cBest = lastCpu;
                    psor = r;
                }
            }
            tAuto = best(SolverKind::Psor, wAuto, psorAuto, tAuto, cAuto);
            if (wBest == wAuto) {
                tBest = tAuto;
                cBest = cAuto;
            } else {
                tBest = best(SolverKind::Psor, wBest, psor, tBest, cBest);
            }
            ReynoldsResult as, mg;
            double cAs = 1e300, cMg = 1e300;
            // One untimed cold solve of each before its timed ones, as PSOR's ω scan is for PSOR:
            // the first solves of a solver kind in a process pay the allocator's warm-up (fresh
            // mappings, page faults; docs/lube.md §7), which a co-simulation pays once.
            run(SolverKind::ActiveSet, 0.0, as);
            const double tAs = best(SolverKind::ActiveSet, 0.0, as, 1e300, cAs);
            run(SolverKind::Multigrid, 0.0, mg);
            const double tMg = best(SolverKind::Multigrid, 0.0, mg, 1e300, cMg);
            // Errors against the active-set answer (exact to round-off).
            const double pmax = as.pressure.maxCoeff();
            auto err = [&](const ReynoldsResult& r) { return (r.pressure - as.pressure).cwiseAbs().maxCoeff() / pmax; };
            std::printf("| %s | %d×%d | %d | %.4f → %.4f | %d / %d | %.3f / %.3f | %d (%d) | %.3f | %d (%d) | "
                        "%.4f | %.2f | %.0f (%.0f) | %.3f / %.4f, %.0f | %.1e | %.1e |\n",
                        name.c_str(), nz, nt, nz * nt, wAuto, wBest, sweepsAuto, sweepsBest, tAuto, tBest,
                        as.iterations, as.coarseIterations, tAs, mg.iterations, mg.coarseIterations, tMg,
                        1e6 * tMg / (nz * nt), tBest / tMg, tAuto / tMg, cBest, cMg, cBest / cMg, err(psor), err(mg));
            std::fflush(stdout);
        }
    }
    return 0;
}
