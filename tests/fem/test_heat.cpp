// Steady conduction through a slab with convection on both faces, against the 1-D
// solution: q = (T1 - T2) / (1/h1 + L/k + 1/h2), T linear in x (exact on TET4 / TET10).
#include <gtest/gtest.h>

#include "TestData.hpp"
#include "fem/DofMap.hpp"
#include "fem/HeatAssembler.hpp"
#include "fem/MeshReader.hpp"
#include "fem/StaticSolver.hpp"

using namespace flexehd::fem;
using flexehd::test::dataPath;

class SlabConduction : public testing::TestWithParam<int> {};

TEST_P(SlabConduction, ConvectionBothSides) {
    const Mesh m = readMesh(dataPath("slab.geo"), {GetParam(), 0.01});
    const double L = 0.1, k = 50.0, h1 = 100.0, T1 = 500.0, h2 = 50.0, T2 = 300.0;
    const double q = (T1 - T2) / (1 / h1 + L / k + 1 / h2);  // 6250 W/m²
    HeatAssembler heat(m);
    SparseMatrix K = heat.conductivity(k);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(heat.numDofs());
    heat.addConvection(BoundarySurface(m, "hot"), h1, T1, K, f);
    heat.addConvection(BoundarySurface(m, "cold"), h2, T2, K, f);
    const Eigen::VectorXd T = StaticSolver(K).solve(f);
    double err = 0.0;
    for (Index n = 0; n < m.numNodes(); ++n)
        err = std::max(err, std::abs(T(n) - (T1 - q / h1 - q * m.nodes(0, n) / k)));
    EXPECT_LT(err, 1e-9 * T1);
}

TEST_P(SlabConduction, PrescribedFluxAndTemperature) {
    const Mesh m = readMesh(dataPath("slab.geo"), {GetParam(), 0.01});
    const double k = 50.0, q = 2.0e4, Tcold = 350.0;
    HeatAssembler heat(m);
    const SparseMatrix K = heat.conductivity(k);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(heat.numDofs());
    heat.addHeatFlux(BoundarySurface(m, "hot"), q, f);
    DofMap dofs(m.numNodes(), 1);
    dofs.constrain(m.groupNodes("cold"), kX, Tcold);
    dofs.finalize();
    const Eigen::VectorXd T = dofs.expand(StaticSolver(dofs.reduce(K)).solve(dofs.reduceLoad(f, K)));
    double err = 0.0;
    for (Index n = 0; n < m.numNodes(); ++n)
        err = std::max(err, std::abs(T(n) - (Tcold + q * (0.1 - m.nodes(0, n)) / k)));
    EXPECT_LT(err, 1e-9 * Tcold);
}

INSTANTIATE_TEST_SUITE_P(Tet4AndTet10, SlabConduction, testing::Values(1, 2));
