// Mesh import through the Gmsh SDK: formats, orders, groups, and the error cases.
#include <gmsh.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "TestData.hpp"
#include "fem/BoundarySurface.hpp"
#include "fem/MeshReader.hpp"
#include "fem/ShapeFunctions.hpp"

using namespace flexehd::fem;
using flexehd::test::dataPath;
using flexehd::test::errorOf;
using testing::HasSubstr;

TEST(MeshReader, GeoMeshedAtBothOrders) {
    const Mesh m1 = readMesh(dataPath("cube.geo"), {1, 0.5});
    const Mesh m2 = readMesh(dataPath("cube.geo"), {2, 0.5});
    EXPECT_EQ(m1.volume.type, ElementType::Tet4);
    EXPECT_EQ(m1.surface.type, ElementType::Tri3);
    EXPECT_EQ(m2.volume.type, ElementType::Tet10);
    EXPECT_EQ(m2.surface.type, ElementType::Tri6);
    EXPECT_EQ(m1.volume.size(), m2.volume.size());
    EXPECT_GT(m2.numNodes(), m1.numNodes());
    EXPECT_NEAR(m1.volumeMeasure(), 1.0, 1e-12);  // unit cube
    EXPECT_NEAR(m2.volumeMeasure(), 1.0, 1e-12);
    // Boundary: six unit faces.
    EXPECT_NEAR(BoundarySurface(m2, "boundary").area(), 6.0, 1e-12);
    EXPECT_EQ(m2.group("cube").dim, 3);
    EXPECT_EQ(m2.group("cube").elements.size(), std::size_t(m2.volume.size()));
}

TEST(MeshReader, SizeParameterRefines) {
    const Mesh coarse = readMesh(dataPath("cube.geo"), {1, 0.25});
    const Mesh fine = readMesh(dataPath("cube.geo"), {1, 0.1});
    EXPECT_GT(fine.volume.size(), 4 * coarse.volume.size());
}

TEST(MeshReader, NoSettingsLeakFromOneLoadToTheNext) {
    // Gmsh keeps onelab parameters and options across files; each load must start clean.
    const Mesh first = readMesh(dataPath("cube.geo"), {1, 0.0});
    const Mesh fine = readMesh(dataPath("cube.geo"), {1, 0.1});
    const Mesh again = readMesh(dataPath("cube.geo"), {1, 0.0});
    EXPECT_GT(fine.volume.size(), first.volume.size());
    EXPECT_EQ(again.volume.size(), first.volume.size());
    EXPECT_EQ(again.numNodes(), first.numNodes());
}

TEST(MeshReader, Msh22And41GiveTheSameMesh) {
    const auto dir = flexehd::test::scratchDir();
    convertMesh(dataPath("thick_cylinder.geo"), (dir / "c22.msh").string(), 2.2, {2, 0.02});
    convertMesh(dataPath("thick_cylinder.geo"), (dir / "c41.msh").string(), 4.1, {2, 0.02});
    const Mesh a = readMesh((dir / "c22.msh").string());
    const Mesh b = readMesh((dir / "c41.msh").string());
    ASSERT_EQ(a.volume.type, ElementType::Tet10);
    EXPECT_EQ(a.numNodes(), b.numNodes());
    EXPECT_EQ(a.volume.size(), b.volume.size());
    EXPECT_EQ(a.groupNames(), b.groupNames());
    EXPECT_NEAR(a.volumeMeasure(), b.volumeMeasure(), 1e-15);
    // Curved second-order boundary: volume of the quarter annulus π(b²-a²)H/4 to ~1e-5.
    const double exact = 3.14159265358979 * (0.1 * 0.1 - 0.05 * 0.05) * 0.02 / 4.0;
    EXPECT_NEAR(a.volumeMeasure() / exact, 1.0, 1e-4);
    // Inner surface area πaH/2.
    EXPECT_NEAR(BoundarySurface(a, "inner").area() / (3.14159265358979 * 0.05 * 0.02 / 2.0), 1.0, 1e-4);
    // A .msh read at another order is converted.
    EXPECT_EQ(readMesh((dir / "c22.msh").string(), {1, 0}).volume.type, ElementType::Tet4);
}

TEST(MeshReader, Tet10NodeOrderMatchesGmsh) {
    // Our reference node coordinates (shape-function node order) against Gmsh's own.
    readMesh(dataPath("cube.geo"), {1, 0.5});  // makes sure Gmsh is initialised
    for (auto [type, gmshType] : {std::pair{ElementType::Tet10, 11}, std::pair{ElementType::Tri6, 9}}) {
        std::string name;
        int dim, order, n, np;
        std::vector<double> local;
        gmsh::model::mesh::getElementProperties(gmshType, name, dim, order, n, local, np);
        const Eigen::Matrix3Xd ours = referenceNodes(type);
        ASSERT_EQ(n, ours.cols());
        for (int a = 0; a < n; ++a)
            for (int d = 0; d < dim; ++d) EXPECT_DOUBLE_EQ(local[a * dim + d], ours(d, a)) << name << " node " << a;
    }
}

TEST(MeshReader, ShapeFunctionsAreKroneckerAndPartitionOfUnity) {
    auto check = [](auto shape, ElementType t) {
        const Eigen::Matrix3Xd xi = referenceNodes(t);
        for (int a = 0; a < xi.cols(); ++a) {
            const auto N = shape.N(xi.col(a));
            for (int b = 0; b < xi.cols(); ++b) EXPECT_NEAR(N(b), a == b ? 1.0 : 0.0, 1e-15);
        }
        const Eigen::Vector3d p(0.21, 0.17, t == ElementType::Tet10 ? 0.33 : 0.0);
        EXPECT_NEAR(shape.N(p).sum(), 1.0, 1e-15);
        EXPECT_NEAR(shape.dN(p).colwise().sum().norm(), 0.0, 1e-14);
    };
    check(Shape<ElementType::Tet10>{}, ElementType::Tet10);
    check(Shape<ElementType::Tri6>{}, ElementType::Tri6);
}

TEST(MeshReaderErrors, MissingFile) {
    const std::string msg = errorOf([] { readMesh("/nonexistent/piston.msh"); });
    EXPECT_THAT(msg, HasSubstr("/nonexistent/piston.msh"));
    EXPECT_THAT(msg, HasSubstr("not found"));
}

TEST(MeshReaderErrors, UnsupportedExtension) {
    EXPECT_THAT(errorOf([] { readMesh(dataPath("../test_quadrature.cpp")); }), HasSubstr("unsupported extension"));
}

TEST(MeshReaderErrors, NoVolumeElements) {
    const std::string msg = errorOf([] { readMesh(dataPath("surface_only.geo")); });
    EXPECT_THAT(msg, HasSubstr("surface_only.geo"));
    EXPECT_THAT(msg, HasSubstr("no volume elements"));
}

TEST(MeshReaderErrors, UnsupportedElementTypeIsNamed) {
    const std::string msg = errorOf([] { readMesh(dataPath("hexahedra.msh")); });
    EXPECT_THAT(msg, HasSubstr("Hexahedron"));
    EXPECT_THAT(msg, HasSubstr("tetrahedra"));
}

TEST(MeshReaderErrors, InvertedElementNamedWithJacobian) {
    const std::string msg = errorOf([] { readMesh(dataPath("inverted.msh")); });
    EXPECT_THAT(msg, HasSubstr("inverted TET4 element 8"));
    EXPECT_THAT(msg, HasSubstr("Jacobian determinant -2"));
}

TEST(MeshReaderErrors, DegenerateElement) {
    const std::string msg = errorOf([] { readMesh(dataPath("degenerate.msh")); });
    EXPECT_THAT(msg, HasSubstr("degenerate TET4 element 3"));
}

TEST(MeshReaderErrors, UnknownGroupListsAvailableNames) {
    const Mesh m = readMesh(dataPath("cube.geo"), {1, 0.5});
    const std::string msg = errorOf([&] { m.group("skirt"); });
    EXPECT_THAT(msg, HasSubstr("'skirt'"));
    EXPECT_THAT(msg, HasSubstr("boundary (surface)"));
    EXPECT_THAT(msg, HasSubstr("cube (volume)"));
}

TEST(MeshReaderErrors, VolumeGroupWhereSurfaceNeeded) {
    const Mesh m = readMesh(dataPath("cube.geo"), {1, 0.5});
    EXPECT_THAT(errorOf([&] { BoundarySurface(m, "cube"); }), HasSubstr("is a volume"));
}
