// The element count `reduce` expects before Gmsh meshes a .geo, against the real meshes of the
// shipped geometries, and the refusal of a size whose mesh cannot fit in memory.
#include <chrono>
#include <cstdio>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "CliRunner.hpp"
#include "fem/MeshReader.hpp"

namespace {

using flexehd::test::runFlexehd;
using ::testing::HasSubstr;

const std::string kSource = FLEXEHD_SOURCE_DIR;

struct Counted {
    flexehd::fem::MeshEstimate estimate;
    double tetrahedra = 0.0, nodes = 0.0;
};

Counted meshAndEstimate(const std::string& file, double size) {
    Counted c;
    flexehd::fem::MeshOptions o;
    o.size = size;
    o.beforeMeshing = [&](const flexehd::fem::MeshEstimate& e) { c.estimate = e; };
    const flexehd::fem::Mesh m = flexehd::fem::readMesh(kSource + "/meshes/" + file, o);
    c.tetrahedra = double(m.volume.size());
    c.nodes = double(m.numNodes());
    std::printf("%s at %g m: volume %.4g m3, area %.4g m2; estimate %.0f tetrahedra, %.0f nodes; real %.0f, %.0f\n",
                file.c_str(), size, c.estimate.volume, c.estimate.area, c.estimate.tetrahedra, c.estimate.nodes,
                c.tetrahedra, c.nodes);
    return c;
}

void expectWithinFactor(double estimate, double real, double factor, const std::string& what) {
    EXPECT_GT(estimate, real / factor) << what;
    EXPECT_LT(estimate, real * factor) << what;
}

TEST(MeshEstimate, PistonAtTheCoarseSizeIsWithinAFactorOfThree) {
    const Counted c = meshAndEstimate("piston.geo", 0.0065);  // 6 241 TET10, 12 484 nodes
    EXPECT_DOUBLE_EQ(c.estimate.size, 0.0065);
    expectWithinFactor(c.estimate.tetrahedra, c.tetrahedra, 3.0, "piston tetrahedra");
    expectWithinFactor(c.estimate.nodes, c.nodes, 3.0, "piston nodes");
}

TEST(MeshEstimate, LinerAtTheCoarseSizeIsWithinAFactorOfThree) {
    const Counted c = meshAndEstimate("liner.geo", 0.009);  // 4 771 TET10, 9 736 nodes
    expectWithinFactor(c.estimate.tetrahedra, c.tetrahedra, 3.0, "liner tetrahedra");
    expectWithinFactor(c.estimate.nodes, c.nodes, 3.0, "liner nodes");
}

TEST(MeshEstimate, SmallestSizeForANodeCountInvertsTheEstimate) {
    const double v = 1.5e-4, a = 4e-2;
    const double h = flexehd::fem::sizeForNodes(v, a, 1e6, 2);
    EXPECT_NEAR(flexehd::fem::estimateMesh(v, a, h, 2).nodes, 1e6, 1e6 * 1e-6);
}

TEST(ReduceCommand, RefusesASizeTooFineForMemoryWithinSeconds) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = runFlexehd("reduce --mesh " + kSource +
                                  "/meshes/piston.geo --size 1e-6 --E 7.5e10 --nu 0.33 --rho 2700 "
                                  "--interface pin_bore:rbe2@0,0,0 --modes 20 --out /tmp/flexehd_never_written.h5",
                              30);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_NE(r.status, 0);
    EXPECT_LT(seconds, 10.0);
    const std::string all = r.out + r.err;
    EXPECT_THAT(all, HasSubstr("--size 1e-06 would make about"));
    EXPECT_THAT(all, HasSubstr("the smallest size within the memory budget of"));
    EXPECT_THAT(all, HasSubstr("meshing "));
}

TEST(ReduceCommand, RefusesSizeOneTenthOfAMillimetre) {
    const auto r = runFlexehd("reduce --mesh " + kSource +
                                  "/meshes/piston.geo --size 1e-4 --E 7.5e10 --nu 0.33 --rho 2700 "
                                  "--interface pin_bore:rbe2@0,0,0 --modes 20 --out /tmp/flexehd_never_written.h5",
                              30);
    EXPECT_NE(r.status, 0);
    EXPECT_THAT(r.out + r.err, HasSubstr("--size 0.0001 would make about"));
}

}  // namespace
