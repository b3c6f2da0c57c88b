// The reduced-body HDF5 file: exact round trip, the documented layout as another tool
// sees it (raw HDF5 C API), and clear errors for missing, foreign, newer and damaged files.
#include <hdf5.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../fem/TestData.hpp"
#include "SyntheticBody.hpp"
#include "modal/ReducedBodyFile.hpp"

using flexehd::test::errorOf;
using flexehd::test::scratchDir;
using flexehd::test::syntheticBody;
using namespace flexehd;
using testing::HasSubstr;

namespace {

/// Same size and same bytes (so -0.0, subnormals and NaN payloads count too).
template <class A>
void expectBitwiseEqual(const A& expected, const A& actual, const std::string& what) {
    ASSERT_EQ(expected.rows(), actual.rows()) << what;
    ASSERT_EQ(expected.cols(), actual.cols()) << what;
    if (expected.size() == 0) return;  // no bytes (and data() may be null)
    EXPECT_EQ(0, std::memcmp(expected.data(), actual.data(), sizeof(typename A::Scalar) * expected.size())) << what;
}

void expectSameBody(const modal::ReducedBody& a, const modal::ReducedBody& b) {
    EXPECT_EQ(a.meshPath, b.meshPath);
    EXPECT_EQ(a.meshHash, b.meshHash);
    EXPECT_EQ(a.elementOrder, b.elementOrder);
    EXPECT_EQ(a.meshSize, b.meshSize);
    EXPECT_EQ(a.material.E, b.material.E);
    EXPECT_EQ(a.material.nu, b.material.nu);
    EXPECT_EQ(a.material.rho, b.material.rho);
    EXPECT_EQ(a.settings.normalModes, b.settings.normalModes);
    EXPECT_EQ(a.settings.cutoffHz, b.settings.cutoffHz);
    EXPECT_EQ(a.settings.staticCorrection, b.settings.staticCorrection);
    EXPECT_EQ(a.settings.pressurePatterns, b.settings.pressurePatterns);
    EXPECT_EQ(a.settings.supports, b.settings.supports);
    EXPECT_EQ(a.settings.axialOrder, b.settings.axialOrder);
    EXPECT_EQ(a.settings.axialHats, b.settings.axialHats);
    EXPECT_EQ(a.settings.circumferentialOrder, b.settings.circumferentialOrder);
    EXPECT_EQ(a.settings.dampingRatio, b.settings.dampingRatio);

    expectBitwiseEqual(a.mesh.nodes, b.mesh.nodes, "nodes");
    EXPECT_EQ(a.mesh.nodeTags, b.mesh.nodeTags);
    EXPECT_EQ(a.mesh.source, b.mesh.source);
    for (auto [x, y] : {std::pair{&a.mesh.volume, &b.mesh.volume}, std::pair{&a.mesh.surface, &b.mesh.surface}}) {
        EXPECT_EQ(x->type, y->type);
        expectBitwiseEqual(x->nodes, y->nodes, "element nodes");
        EXPECT_EQ(x->tags, y->tags);
    }
    ASSERT_EQ(a.mesh.groups.size(), b.mesh.groups.size());
    for (const auto& [name, g] : a.mesh.groups) {
        ASSERT_TRUE(b.mesh.hasGroup(name)) << name;
        EXPECT_EQ(g.name, b.mesh.group(name).name);
        EXPECT_EQ(g.dim, b.mesh.group(name).dim) << name;
        EXPECT_EQ(g.elements, b.mesh.group(name).elements) << name;
    }

    ASSERT_EQ(a.interfaces.size(), b.interfaces.size());
    for (std::size_t i = 0; i < a.interfaces.size(); ++i) {
        EXPECT_EQ(a.interfaces[i].group, b.interfaces[i].group);
        EXPECT_EQ(a.interfaces[i].kind, b.interfaces[i].kind);
        expectBitwiseEqual(a.interfaces[i].referencePoint, b.interfaces[i].referencePoint, "reference point");
        EXPECT_EQ(a.interfaces[i].nodes, b.interfaces[i].nodes);
    }

    expectBitwiseEqual(a.shapes, b.shapes, "shapes");
    expectBitwiseEqual(a.massMatrix, b.massMatrix, "mass");
    expectBitwiseEqual(a.stiffnessMatrix, b.stiffnessMatrix, "stiffness");
    expectBitwiseEqual(a.frequenciesHz, b.frequenciesHz, "frequencies");
    EXPECT_EQ(a.rigidBody, b.rigidBody);
    expectBitwiseEqual(a.dampingRatios, b.dampingRatios, "damping");
    expectBitwiseEqual(a.interfaceMotion, b.interfaceMotion, "interface motion");
}

/// Edits a written file with the raw C API, as a damaged or foreign file would look.
struct RawFile {
    explicit RawFile(const std::string& path) : id(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT)) {
        EXPECT_GE(id, 0);
    }
    ~RawFile() { H5Fclose(id); }
    void setIntAttribute(const char* object, const char* name, int value) const {
        const hid_t a = H5Aopen_by_name(id, object, name, H5P_DEFAULT, H5P_DEFAULT);
        ASSERT_GE(a, 0);
        EXPECT_GE(H5Awrite(a, H5T_NATIVE_INT, &value), 0);
        H5Aclose(a);
    }
    void remove(const char* object) const { EXPECT_GE(H5Ldelete(id, object, H5P_DEFAULT), 0); }
    void removeAttribute(const char* object, const char* name) const {
        EXPECT_GE(H5Adelete_by_name(id, object, name, H5P_DEFAULT), 0);
    }
    void vector(const char* object, const std::vector<double>& values) const {
        const hsize_t n = values.size();
        const hid_t space = H5Screate_simple(1, &n, nullptr);
        const hid_t d = H5Dcreate2(id, object, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        EXPECT_GE(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
        H5Dclose(d);
        H5Sclose(space);
    }
    /// Overwrites entry `index` (in the file's row-major order) of an existing float64 dataset.
    void setEntry(const char* object, hsize_t index, double value) const {
        const hid_t d = H5Dopen2(id, object, H5P_DEFAULT);
        ASSERT_GE(d, 0) << object;
        const hid_t space = H5Dget_space(d);
        std::vector<double> v(H5Sget_simple_extent_npoints(space));
        EXPECT_GE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), 0);
        v.at(index) = value;
        EXPECT_GE(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), 0);
        H5Sclose(space);
        H5Dclose(d);
    }
    /// Reads a whole float64 dataset, checking its shape.
    std::vector<double> read(const char* object, const std::vector<hsize_t>& shape) const {
        const hid_t d = H5Dopen2(id, object, H5P_DEFAULT);
        const hid_t space = H5Dget_space(d);
        std::vector<hsize_t> dims(H5Sget_simple_extent_ndims(space));
        H5Sget_simple_extent_dims(space, dims.data(), nullptr);
        EXPECT_EQ(dims, shape) << object;
        std::vector<double> v(H5Sget_simple_extent_npoints(space));
        H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
        H5Sclose(space);
        H5Dclose(d);
        return v;
    }
    hid_t id;
};

class ReducedBodyFileTest : public testing::Test {
protected:
    static void SetUpTestSuite() { body_ = new modal::ReducedBody(syntheticBody()); }
    static void TearDownTestSuite() { delete body_; }
    void SetUp() override {
        dir_ = scratchDir();
        good_ = (dir_ / "body.h5").string();
        modal::writeReducedBody(*body_, good_);
    }
    static modal::ReducedBody* body_;  // meshing once keeps the suite fast
    std::filesystem::path dir_;
    std::string good_;
};
modal::ReducedBody* ReducedBodyFileTest::body_ = nullptr;

}  // namespace

TEST_F(ReducedBodyFileTest, RoundTripIsExact) {
    modal::ReducedBody b = *body_;
    // Values a lossy path would change: signed zero, subnormal, extremes (non-finite values
    // are rejected on read: NonFiniteValueNamesTheFileDatasetAndEntry).
    b.shapes(0, 0) = -0.0;
    b.shapes(1, 0) = std::numeric_limits<double>::denorm_min();
    b.shapes(2, 1) = std::numeric_limits<double>::max();
    b.interfaceMotion(3, 2) = -std::numeric_limits<double>::min();
    const std::string path = (dir_ / "exact.h5").string();
    modal::writeReducedBody(b, path);
    const modal::ReducedBody r = modal::readReducedBody(path);
    expectSameBody(b, r);
    EXPECT_EQ(r.mesh.volume.type, fem::ElementType::Tet10);
    EXPECT_EQ(r.mesh.surface.type, fem::ElementType::Tri6);
    EXPECT_EQ(r.numModes(), 9);
    // The named surfaces come back with their triangles.
    EXPECT_EQ(r.mesh.groupNodes("xmax"), body_->mesh.groupNodes("xmax"));
    for (const auto& e : std::filesystem::directory_iterator(dir_)) EXPECT_NE(e.path().extension(), ".tmp");
}

TEST_F(ReducedBodyFileTest, OverwritesAnExistingFile) {
    modal::ReducedBody b = *body_;
    b.shapes.conservativeResize(Eigen::NoChange, 2);
    b.massMatrix = b.massMatrix.topLeftCorner(2, 2).eval();
    b.stiffnessMatrix = b.stiffnessMatrix.topLeftCorner(2, 2).eval();
    b.frequenciesHz.conservativeResize(2);
    b.dampingRatios.conservativeResize(2);
    b.rigidBody.resize(2);
    b.interfaceMotion.conservativeResize(Eigen::NoChange, 2);
    modal::writeReducedBody(b, good_);
    expectSameBody(b, modal::readReducedBody(good_));
}

TEST_F(ReducedBodyFileTest, EmptyListsRoundTrip) {
    modal::ReducedBody b = *body_;
    b.settings.staticCorrection.clear();
    b.interfaces.clear();
    b.interfaceMotion.resize(0, b.numModes());
    b.mesh.groups.at("xmin").elements.clear();
    const std::string path = (dir_ / "empty.h5").string();
    modal::writeReducedBody(b, path);
    expectSameBody(b, modal::readReducedBody(path));
}

TEST_F(ReducedBodyFileTest, PressurePatternsRoundTrip) {
    modal::ReducedBody b = *body_;
    b.settings.pressurePatterns = {"xmax", "boundary"};
    const std::string path = (dir_ / "patterns.h5").string();
    modal::writeReducedBody(b, path);
    const modal::ReducedBody r = modal::readReducedBody(path);
    EXPECT_EQ(r.settings.pressurePatterns, (std::vector<std::string>{"xmax", "boundary"}));
    expectSameBody(b, r);
}

// A file written before /settings had `pressure_patterns` reads as a body without them.
TEST_F(ReducedBodyFileTest, FileWithoutPressurePatternsReadsAsEmpty) {
    modal::ReducedBody b = *body_;
    b.settings.pressurePatterns = {"xmax"};
    modal::writeReducedBody(b, good_);
    RawFile(good_).removeAttribute("/settings", "pressure_patterns");
    const modal::ReducedBody r = modal::readReducedBody(good_);
    EXPECT_TRUE(r.settings.pressurePatterns.empty());
    EXPECT_EQ(r.settings.staticCorrection, b.settings.staticCorrection);
}

TEST_F(ReducedBodyFileTest, SpringSupportsRoundTrip) {
    modal::ReducedBody b = *body_;
    b.settings.supports = {"xmax:1e12", "boundary:2.5e9"};
    const std::string path = (dir_ / "supports.h5").string();
    modal::writeReducedBody(b, path);
    const modal::ReducedBody r = modal::readReducedBody(path);
    EXPECT_EQ(r.settings.supports, (std::vector<std::string>{"xmax:1e12", "boundary:2.5e9"}));
    expectSameBody(b, r);
}

// A file written before /settings had `supports` reads as a body without spring supports.
TEST_F(ReducedBodyFileTest, FileWithoutSupportsReadsAsEmpty) {
    modal::ReducedBody b = *body_;
    b.settings.supports = {"xmax:1e12"};
    modal::writeReducedBody(b, good_);
    RawFile(good_).removeAttribute("/settings", "supports");
    const modal::ReducedBody r = modal::readReducedBody(good_);
    EXPECT_TRUE(r.settings.supports.empty());
    EXPECT_EQ(r.settings.pressurePatterns, b.settings.pressurePatterns);
}

TEST_F(ReducedBodyFileTest, LayoutAsDocumented) {
    const RawFile f(good_);
    const auto m = hsize_t(body_->numModes());
    const auto n = hsize_t(body_->mesh.numNodes());
    // Row k of /modes/shapes is mode k, entries 3*node + component.
    const auto shapes = f.read("/modes/shapes", {m, 3 * n});
    EXPECT_EQ(shapes[1 * 3 * n + 3 * 5 + 2], body_->shapes(3 * 5 + 2, 1));
    const auto mass = f.read("/modes/mass", {m, m});
    EXPECT_EQ(mass[0 * m + 1], body_->massMatrix(0, 1));  // C order: [row][column]
    const auto motion = f.read("/modes/interface_motion", {12, m});
    EXPECT_EQ(motion[7 * m + 3], body_->interfaceMotion(7, 3));
    const auto nodes = f.read("/mesh/nodes", {n, 3});
    EXPECT_EQ(nodes[3 * 4 + 1], body_->mesh.nodes(1, 4));
    f.read("/interfaces/1/reference_point", {3});
    f.read("/modes/frequencies_hz", {m});
}

TEST_F(ReducedBodyFileTest, MissingFile) {
    const std::string path = (dir_ / "nothing.h5").string();
    const std::string e = errorOf([&] { modal::readReducedBody(path); });
    EXPECT_THAT(e, HasSubstr(path));
    EXPECT_THAT(e, HasSubstr("does not exist"));
}

TEST_F(ReducedBodyFileTest, NotAnHdf5File) {
    const std::string path = (dir_ / "text.h5").string();
    std::ofstream(path) << "this is a text file, not HDF5\n";
    const std::string e = errorOf([&] { modal::readReducedBody(path); });
    EXPECT_THAT(e, HasSubstr(path));
    EXPECT_THAT(e, HasSubstr("not an HDF5 file or damaged"));
}

TEST_F(ReducedBodyFileTest, Hdf5FileOfAnotherKind) {
    const std::string path = (dir_ / "other.h5").string();
    H5Fclose(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
    EXPECT_THAT(errorOf([&] { modal::readReducedBody(path); }), HasSubstr("is not a flexehd reduced-body file"));
}

TEST_F(ReducedBodyFileTest, OtherFormatVersion) {
    RawFile(good_).setIntAttribute("/", "format_version", 2);
    const std::string e = errorOf([&] { modal::readReducedBody(good_); });
    EXPECT_THAT(e, HasSubstr(good_));
    EXPECT_THAT(e, HasSubstr("has format version 2, this flexehd reads version 1"));
}

TEST_F(ReducedBodyFileTest, MissingDataset) {
    RawFile(good_).remove("/modes/shapes");
    const std::string e = errorOf([&] { modal::readReducedBody(good_); });
    EXPECT_THAT(e, HasSubstr(good_));
    EXPECT_THAT(e, HasSubstr("missing dataset /modes/shapes"));
}

TEST_F(ReducedBodyFileTest, InconsistentDatasetSize) {
    {
        const RawFile f(good_);
        f.remove("/modes/frequencies_hz");
        f.vector("/modes/frequencies_hz", {1.0, 2.0});
    }
    const std::string e = errorOf([&] { modal::readReducedBody(good_); });
    EXPECT_THAT(e, HasSubstr("dataset /modes/frequencies_hz has shape [2], expected [9]"));
}

TEST_F(ReducedBodyFileTest, NonFiniteValueNamesTheFileDatasetAndEntry) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const hsize_t dofs = 3 * hsize_t(body_->mesh.numNodes());
    RawFile(good_).setEntry("/modes/shapes", 2 * dofs + 7, nan);  // mode 2, dof 7
    const std::string e = errorOf([&] { modal::readReducedBody(good_); });
    EXPECT_THAT(e, HasSubstr(good_));
    EXPECT_THAT(e, HasSubstr("dataset /modes/shapes has a non-finite value (nan) at [2, 7]"));
    RawFile(good_).setEntry("/modes/shapes", 2 * dofs + 7, 0.0);
    RawFile(good_).setEntry("/mesh/nodes", 3 * 5 + 1, std::numeric_limits<double>::infinity());
    EXPECT_THAT(errorOf([&] { modal::readReducedBody(good_); }),
                HasSubstr("dataset /mesh/nodes has a non-finite value (inf) at [5, 1]"));
}

TEST_F(ReducedBodyFileTest, ModalMatricesMustBeSymmetricAndDefinite) {
    const hsize_t m = hsize_t(body_->massMatrix.rows());
    // Stiffness: one off-diagonal entry changed breaks the symmetry.
    RawFile(good_).setEntry("/modes/stiffness", 7 * m + 8, 1e6);
    EXPECT_THAT(errorOf([&] { modal::readReducedBody(good_); }), HasSubstr("dataset /modes/stiffness is not symmetric"));
    modal::writeReducedBody(*body_, good_);
    // Stiffness: a negative diagonal entry (energy released by a deformation).
    RawFile(good_).setEntry("/modes/stiffness", 8 * m + 8, -1e9);
    EXPECT_THAT(errorOf([&] { modal::readReducedBody(good_); }), HasSubstr("/modes/stiffness has a negative eigenvalue"));
    modal::writeReducedBody(*body_, good_);
    // Mass: a mode without mass.
    RawFile(good_).setEntry("/modes/mass", 3 * m + 3, 0.0);
    EXPECT_THAT(errorOf([&] { modal::readReducedBody(good_); }), HasSubstr("dataset /modes/mass is not positive definite"));
    modal::writeReducedBody(*body_, good_);
    // Material outside its physical range (a producer that wrote one).
    modal::ReducedBody b = *body_;
    b.material.nu = 0.7;
    modal::writeReducedBody(b, good_);
    EXPECT_THAT(errorOf([&] { modal::readReducedBody(good_); }),
                HasSubstr("attribute 'nu' of /material is 0.7, expected a Poisson's ratio in (-1, 0.5)"));
}

TEST_F(ReducedBodyFileTest, TruncatedFile) {
    const std::string path = (dir_ / "half.h5").string();
    const auto size = std::filesystem::file_size(good_);
    std::string bytes(size / 2, '\0');
    std::ifstream(good_, std::ios::binary).read(bytes.data(), std::streamsize(bytes.size()));
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    const std::string e = errorOf([&] { modal::readReducedBody(path); });
    EXPECT_THAT(e, HasSubstr(path));
    EXPECT_THAT(e, HasSubstr("damaged"));
}

TEST_F(ReducedBodyFileTest, InconsistentBodyIsNotWritten) {
    modal::ReducedBody b = *body_;
    b.massMatrix.resize(3, 3);
    const std::string path = (dir_ / "bad.h5").string();
    EXPECT_THAT(errorOf([&] { modal::writeReducedBody(b, path); }), HasSubstr("mass matrix is 3 x 3 for 9 modes"));
    EXPECT_FALSE(std::filesystem::exists(path));
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

TEST_F(ReducedBodyFileTest, MissingDirectoriesAreMade) {
    const std::string path = (dir_ / "no" / "such" / "dir.h5").string();
    modal::writeReducedBody(*body_, path);
    EXPECT_EQ(modal::readReducedBody(path).numModes(), body_->numModes());
}

TEST_F(ReducedBodyFileTest, UnwritableLocation) {
    // A directory that cannot be made: its parent is a regular file.
    const std::filesystem::path file = dir_ / "plain_file";
    std::ofstream(file) << "not a directory\n";
    const std::string path = (file / "dir.h5").string();
    const std::string e = errorOf([&] { modal::writeReducedBody(*body_, path); });
    EXPECT_THAT(e, HasSubstr(path));
    EXPECT_THAT(e, testing::Not(HasSubstr("HDF5")));
}

TEST(Fnv1a64, KnownValues) {
    const auto dir = scratchDir();
    const auto hashOf = [&](const std::string& content) {
        const auto path = (dir / "f.bin").string();
        std::ofstream(path, std::ios::binary) << content;
        return modal::fnv1a64File(path);
    };
    // Reference values of the FNV-1a 64-bit test suite (Fowler, Noll, Vo).
    EXPECT_EQ(hashOf(""), "cbf29ce484222325");
    EXPECT_EQ(hashOf("a"), "af63dc4c8601ec8c");
    EXPECT_EQ(hashOf("foobar"), "85944171f73967e8");
    EXPECT_THAT(errorOf([&] { modal::fnv1a64File((dir / "missing").string()); }), HasSubstr("missing"));
}
