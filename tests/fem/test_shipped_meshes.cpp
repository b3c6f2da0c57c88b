// The example engine's meshes (meshes/*.geo) load with all their named groups and valid
// second-order elements; their FE volume matches OpenCASCADE's exact CAD volume
// (docs/meshes.md), and the free piston has six rigid-body modes.
#include <gtest/gtest.h>

#include "TestData.hpp"
#include "fem/BoundarySurface.hpp"
#include "fem/MeshReader.hpp"
#include "fem/ModalAnalysis.hpp"

using namespace flexehd::fem;
using flexehd::test::meshPath;

TEST(ShippedMeshes, PistonCoarse) {
    const Mesh m = readMesh(meshPath("piston.geo"), {2, 0.0065});  // checks every element
    EXPECT_EQ(m.volume.type, ElementType::Tet10);
    for (const char* g : {"piston", "skirt", "pin_bore", "crown", "ring_grooves", "underside"}) {
        ASSERT_TRUE(m.hasGroup(g)) << g;
        EXPECT_FALSE(m.group(g).elements.empty()) << g;
    }
    EXPECT_NEAR(m.volumeMeasure() / 1.169826e-4, 1.0, 1e-3);  // OCC getMass volume, m^3
    // Every surface group is a boundary with outward orientation (throws otherwise).
    for (const char* g : {"skirt", "pin_bore", "crown", "ring_grooves", "underside"}) BoundarySurface(m, g);

    EigenmodeOptions opt;
    opt.count = 8;
    const ModalAnalysis r = analyseModes(m, {7.0e10, 0.33, 2700.0}, {}, opt);
    EXPECT_EQ(r.rigidBodyModes(), 6);
    for (int k = 0; k < 6; ++k) EXPECT_LT(std::abs(r.modes.eigenvalues(k)), 1e-4 * r.modes.eigenvalues(6));
}

TEST(ShippedMeshes, LinerCoarse) {
    const Mesh m = readMesh(meshPath("liner.geo"), {2, 0.009});
    for (const char* g : {"liner", "bore", "outer", "top_seat", "bottom_seat"}) {
        ASSERT_TRUE(m.hasGroup(g)) << g;
        EXPECT_FALSE(m.group(g).elements.empty()) << g;
    }
    EXPECT_NEAR(m.volumeMeasure() / 3.2003e-4, 1.0, 1e-3);
    // Bore: the 86 mm cylinder, 160 mm long: area π D L.
    EXPECT_NEAR(BoundarySurface(m, "bore").area() / (3.14159265358979 * 0.086 * 0.160), 1.0, 1e-3);
}
