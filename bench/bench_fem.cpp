// Benchmark of the finite-element core on one mesh: mesh import, sparsity pattern,
// stiffness and mass assembly, Cholesky factorization (CHOLMOD) and the eigen-solve,
// each timed separately, with peak memory. Run through scripts/bench_fem.sh.
//   bench_fem MESH [SIZE] [--assembly-only] [--modes N]
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "fem/ElasticityAssembler.hpp"
#include "fem/EigenmodeSolver.hpp"
#include "fem/MeshReader.hpp"
#include "fem/StaticSolver.hpp"

using namespace flexehd::fem;
using Clock = std::chrono::steady_clock;

static double seconds(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
static double peakMiB() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss / 1024.0;
}

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_fem MESH [SIZE_M] [--assembly-only] [--modes N]\n");
        return 2;
    }
    const std::string path = argv[1];
    double size = 0.0;
    bool assemblyOnly = false;
    int modes = 20;
    for (int i = 2; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--assembly-only")) assemblyOnly = true;
        else if (!std::strcmp(argv[i], "--modes") && i + 1 < argc) modes = std::stoi(argv[++i]);
        else size = std::stod(argv[i]);
    }
    try {
        auto t = Clock::now();
        const Mesh mesh = readMesh(path, {2, size});
        const double tRead = seconds(t);
        std::printf("mesh          %s (size %g m): %d nodes, %d %s, %d DOFs\n", path.c_str(), size,
                    int(mesh.numNodes()), int(mesh.volume.size()), std::string(name(mesh.volume.type)).c_str(),
                    3 * int(mesh.numNodes()));
        std::printf("read+mesh     %8.3f s\n", tRead);
        t = Clock::now();
        ElasticityAssembler assembler(mesh);
        std::printf("pattern       %8.3f s\n", seconds(t));
        const ElasticMaterial alu{7.0e10, 0.33, 2700.0};
        t = Clock::now();
        const SparseMatrix K = assembler.stiffness(alu);
        std::printf("stiffness     %8.3f s  (%lld non-zeros, upper triangle)\n", seconds(t), (long long)K.nonZeros());
        t = Clock::now();
        const SparseMatrix M = assembler.mass(alu.rho);
        std::printf("mass          %8.3f s\n", seconds(t));
        if (!assemblyOnly) {
            EigenmodeOptions opt;
            opt.count = modes;
            const Eigenmodes r = solveEigenmodes(K, M, opt);
            std::printf("factorize     %8.3f s  (K - sigma M, CHOLMOD supernodal)\n", r.factorSeconds);
            std::printf("eigensolve    %8.3f s  (%d modes, %d Lanczos restarts, %d solves)\n", r.solveSeconds, modes,
                        r.iterations, r.operations);
            std::printf("first elastic %8.1f Hz\n", r.frequenciesHz()(std::min(6, modes - 1)));
        }
        std::printf("peak memory   %8.0f MiB\n", peakMiB());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_fem: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
