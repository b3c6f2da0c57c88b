#include "modal/ReducedBodyFile.hpp"

#include "fem/AtomicFile.hpp"
#include "modal/Hdf5Handle.hpp"
#include "modal/ReducedBodyCheck.hpp"

#include <hdf5.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <utility>

namespace flexehd::modal {
namespace {

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using Dims = std::vector<hsize_t>;

// --- HDF5 plumbing ----------------------------------------------------------------------

using Handle = Hdf5Handle;

/// " (HDF5: <the most specific message on HDF5's error stack>)", e.g. "truncated file:
/// eof = ...", or "" if the stack is empty; clears the stack.
std::string hdf5Detail() {
    std::string message;
    H5Ewalk2(
        H5E_DEFAULT, H5E_WALK_UPWARD,
        [](unsigned n, const H5E_error2_t* e, void* out) -> herr_t {
            if (n == 0 && e->desc) *static_cast<std::string*>(out) = e->desc;
            return 0;
        },
        &message);
    H5Eclear2(H5E_DEFAULT);
    return message.empty() ? message : " (HDF5: " + message + ")";
}

// Element types and their HDF5 spelling: file types are little-endian whatever the
// machine, memory types native (no conversion on x86-64, hence bitwise round trips).
template <class T>
struct H5Type;
template <>
struct H5Type<double> {
    static hid_t file() { return H5T_IEEE_F64LE; }
    static hid_t memory() { return H5T_NATIVE_DOUBLE; }
};
template <>
struct H5Type<std::int32_t> {
    static hid_t file() { return H5T_STD_I32LE; }
    static hid_t memory() { return H5T_NATIVE_INT32; }
};
template <>
struct H5Type<std::uint64_t> {
    static hid_t file() { return H5T_STD_U64LE; }
    static hid_t memory() { return H5T_NATIVE_UINT64; }
};
template <>
struct H5Type<std::int8_t> {
    static hid_t file() { return H5T_STD_I8LE; }
    static hid_t memory() { return H5T_NATIVE_INT8; }
};
static_assert(std::is_same_v<fem::Index, std::int32_t>, "indices are stored as int32");
static_assert(sizeof(std::size_t) == sizeof(std::uint64_t), "Gmsh tags are stored as uint64");

/// Variable-length UTF-8 strings: what h5py writes for `str` and returns as `str`.
Handle stringType() {
    Handle t(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(t.get(), H5T_VARIABLE);
    H5Tset_cset(t.get(), H5T_CSET_UTF8);
    return t;
}

std::string shapeText(const Dims& dims) {
    std::string s = "[";
    for (std::size_t k = 0; k < dims.size(); ++k) s += (k ? ", " : "") + std::to_string(dims[k]);
    return s + "]";
}

std::string_view kindName(InterfaceKind kind) { return kind == InterfaceKind::Rbe2 ? "rbe2" : "rbe3"; }

fem::ElementType elementTypeFromName(const std::string& name) {
    for (auto t : {fem::ElementType::Tri3, fem::ElementType::Tri6, fem::ElementType::Tet4, fem::ElementType::Tet10})
        if (fem::name(t) == name) return t;
    throw std::invalid_argument("unknown element type '" + name + "'");
}

// --- writing -----------------------------------------------------------------------------

/// Creates groups, attributes and datasets by absolute path in one open file; every
/// failure becomes a std::runtime_error naming the file and the object.
class Writer {
public:
    Writer(std::string path, hid_t file) : path_(std::move(path)), file_(file) {}

    void group(const std::string& object) const {
        Handle g(H5Gcreate2(file_, object.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
        check(g.get(), "cannot create group " + object);
    }

    void stringAttribute(const std::string& object, const std::string& name, const std::string& value) const {
        stringsAttribute(object, name, {value}, true);
    }

    /// `scalar`: one string (h5py returns str), else a 1-D array (numpy array of str).
    void stringsAttribute(const std::string& object, const std::string& name, const std::vector<std::string>& values,
                          bool scalar = false) const {
        std::vector<const char*> pointers;
        for (const auto& v : values) pointers.push_back(v.c_str());
        const hsize_t n = values.size();
        Handle space(scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr), H5Sclose);
        const Handle type = stringType();
        write(object, name, type.get(), type.get(), space.get(), pointers.data(), n);
    }

    void intAttribute(const std::string& object, const std::string& name, int value) const {
        Handle space(H5Screate(H5S_SCALAR), H5Sclose);
        write(object, name, H5T_STD_I32LE, H5T_NATIVE_INT, space.get(), &value, 1);
    }

    void realAttribute(const std::string& object, const std::string& name, double value) const {
        Handle space(H5Screate(H5S_SCALAR), H5Sclose);
        write(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space.get(), &value, 1);
    }

    /// A contiguous dataset of shape `dims` (C order) from `data`; `unit` becomes the
    /// dataset's `unit` attribute.
    template <class T>
    void dataset(const std::string& object, const T* data, const Dims& dims, const std::string& unit = "") const {
        Handle space(H5Screate_simple(int(dims.size()), dims.data(), nullptr), H5Sclose);
        check(space.get(), "cannot create dataspace for " + object);
        Handle d(H5Dcreate2(file_, object.c_str(), H5Type<T>::file(), space.get(), H5P_DEFAULT, H5P_DEFAULT,
                            H5P_DEFAULT),
                 H5Dclose);
        check(d.get(), "cannot create dataset " + object);
        hsize_t count = 1;
        for (hsize_t n : dims) count *= n;
        if (count > 0)  // HDF5 rejects a null buffer even for zero elements
            check(H5Dwrite(d.get(), H5Type<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
                  "cannot write dataset " + object);
        if (!unit.empty()) stringAttribute(object, "unit", unit);
    }

    void matrix(const std::string& object, const Eigen::MatrixXd& m, const std::string& unit) const {
        const RowMajorMatrix rows = m;  // C order: row i of the dataset = row i of m
        dataset(object, rows.data(), {hsize_t(m.rows()), hsize_t(m.cols())}, unit);
    }

private:
    void write(const std::string& object, const std::string& name, hid_t fileType, hid_t memType, hid_t space,
               const void* data, hsize_t count) const {
        const std::string what = "attribute '" + name + "' of " + object;
        Handle a(H5Acreate_by_name(file_, object.c_str(), name.c_str(), fileType, space, H5P_DEFAULT, H5P_DEFAULT,
                                   H5P_DEFAULT),
                 H5Aclose);
        check(a.get(), "cannot create " + what);
        if (count > 0) check(H5Awrite(a.get(), memType, data), "cannot write " + what);
    }

    void check(std::int64_t status, const std::string& what) const {
        if (status < 0) throw std::runtime_error("reduced-body file '" + path_ + "': " + what + hdf5Detail());
    }

    std::string path_;
    hid_t file_;
};

/// Sizes the writer relies on; a mismatch is a bug in the producer, reported before any
/// file is touched.
void checkConsistent(const ReducedBody& b) {
    const auto fail = [](const std::string& what) {
        throw std::invalid_argument("cannot write reduced body: " + what);
    };
    const auto n = Eigen::Index(b.mesh.numNodes());
    const Eigen::Index m = b.shapes.cols();
    const auto size = [](Eigen::Index r, Eigen::Index c) { return std::to_string(r) + " x " + std::to_string(c); };
    if (b.shapes.rows() != 3 * n)
        fail("shapes are " + size(b.shapes.rows(), m) + ", expected " + std::to_string(3 * n) + " rows (3 x nodes)");
    if (b.massMatrix.rows() != m || b.massMatrix.cols() != m)
        fail("mass matrix is " + size(b.massMatrix.rows(), b.massMatrix.cols()) + " for " + std::to_string(m) + " modes");
    if (b.stiffnessMatrix.rows() != m || b.stiffnessMatrix.cols() != m)
        fail("stiffness matrix is " + size(b.stiffnessMatrix.rows(), b.stiffnessMatrix.cols()) + " for " +
             std::to_string(m) + " modes");
    if (b.frequenciesHz.size() != m || b.dampingRatios.size() != m || Eigen::Index(b.rigidBody.size()) != m)
        fail("frequencies, damping ratios and rigid-body flags need one entry per mode (" + std::to_string(m) + ")");
    for (int flag : b.rigidBody)
        if (flag != 0 && flag != 1) fail("rigid-body flags must be 0 or 1");
    const auto ni = Eigen::Index(b.interfaces.size());
    if (b.interfaceMotion.rows() != 6 * ni || b.interfaceMotion.cols() != m)
        fail("interface motion is " + size(b.interfaceMotion.rows(), b.interfaceMotion.cols()) + ", expected " +
             size(6 * ni, m) + " (6 x interfaces, modes)");
    if (!b.mesh.nodeTags.empty() && Eigen::Index(b.mesh.nodeTags.size()) != n)
        fail("mesh has " + std::to_string(b.mesh.nodeTags.size()) + " node tags for " + std::to_string(n) + " nodes");
    for (const fem::ElementBlock* block : {&b.mesh.volume, &b.mesh.surface})
        if (!block->tags.empty() && Eigen::Index(block->tags.size()) != block->nodes.cols())
            fail("element block has " + std::to_string(block->tags.size()) + " tags for " +
                 std::to_string(block->nodes.cols()) + " elements");
    for (const auto& [name, g] : b.mesh.groups)
        if (name.empty() || name == "." || name.find('/') != std::string::npos)
            fail("physical group name '" + name + "' cannot be an HDF5 group name (empty, '.' or containing '/')");
}

void writeBlock(const Writer& w, const std::string& prefix, const fem::ElementBlock& block) {
    // nodes is nodesPerElement x count, column-major: in memory exactly [count, npe] in C order.
    w.dataset(prefix, block.nodes.data(), {hsize_t(block.nodes.cols()), hsize_t(block.nodes.rows())});
    w.dataset(prefix + "_tags", reinterpret_cast<const std::uint64_t*>(block.tags.data()), {block.tags.size()});
}

void writeContent(const ReducedBody& b, const Writer& w) {
    w.stringAttribute("/", "format", kReducedBodyFormat);
    w.intAttribute("/", "format_version", kReducedBodyFormatVersion);
    w.stringAttribute("/", "units", kReducedBodyUnits);
    w.intAttribute("/", "index_base", 0);

    w.group("/provenance");
    w.stringAttribute("/provenance", "mesh_path", b.meshPath);
    w.stringAttribute("/provenance", "mesh_hash", b.meshHash);
    w.stringAttribute("/provenance", "mesh_hash_algorithm", "FNV-1a 64-bit of the file bytes, hex");
    w.intAttribute("/provenance", "element_order", b.elementOrder);
    w.realAttribute("/provenance", "mesh_size_m", b.meshSize);

    w.group("/material");
    w.realAttribute("/material", "E_pa", b.material.E);
    w.realAttribute("/material", "nu", b.material.nu);
    w.realAttribute("/material", "rho_kg_m3", b.material.rho);

    const ReductionSettings& s = b.settings;
    w.group("/settings");
    w.intAttribute("/settings", "normal_modes", s.normalModes);
    w.realAttribute("/settings", "cutoff_hz", s.cutoffHz);
    w.stringsAttribute("/settings", "static_correction", s.staticCorrection);
    w.intAttribute("/settings", "axial_order", s.axialOrder);
    w.intAttribute("/settings", "axial_hats", s.axialHats);
    w.intAttribute("/settings", "circumferential_order", s.circumferentialOrder);
    w.realAttribute("/settings", "damping_ratio", s.dampingRatio);

    const fem::Mesh& mesh = b.mesh;
    w.group("/mesh");
    w.stringAttribute("/mesh", "source", mesh.source);
    w.stringAttribute("/mesh", "element_type", std::string(fem::name(mesh.volume.type)));
    w.stringAttribute("/mesh", "surface_element_type", std::string(fem::name(mesh.surface.type)));
    // Matrix3Xd is column-major 3 x n: in memory exactly [n, 3] in C order.
    w.dataset("/mesh/nodes", mesh.nodes.data(), {hsize_t(mesh.nodes.cols()), 3}, "m");
    w.dataset("/mesh/node_tags", reinterpret_cast<const std::uint64_t*>(mesh.nodeTags.data()), {mesh.nodeTags.size()});
    writeBlock(w, "/mesh/tetrahedra", mesh.volume);
    writeBlock(w, "/mesh/triangles", mesh.surface);
    w.group("/mesh/groups");
    for (const auto& [name, g] : mesh.groups) {
        const std::string object = "/mesh/groups/" + name;
        w.group(object);
        w.intAttribute(object, "dimension", g.dim);
        w.dataset(object + "/elements", g.elements.data(), {g.elements.size()});
    }

    w.group("/interfaces");
    w.intAttribute("/interfaces", "count", int(b.interfaces.size()));
    for (std::size_t i = 0; i < b.interfaces.size(); ++i) {
        const Interface& itf = b.interfaces[i];
        const std::string object = "/interfaces/" + std::to_string(i);
        w.group(object);
        w.stringAttribute(object, "group", itf.group);
        w.stringAttribute(object, "kind", std::string(kindName(itf.kind)));
        w.dataset(object + "/reference_point", itf.referencePoint.data(), {3}, "m");
        w.dataset(object + "/nodes", itf.nodes.data(), {itf.nodes.size()});
    }

    const auto m = hsize_t(b.numModes());
    w.group("/modes");
    w.intAttribute("/modes", "count", int(m));
    // shapes is column-major 3n x m: column k (mode k) is contiguous, i.e. row k of [m, 3n].
    w.dataset("/modes/shapes", b.shapes.data(), {m, hsize_t(b.shapes.rows())}, "m per unit modal coordinate");
    w.matrix("/modes/mass", b.massMatrix, "kg");
    w.matrix("/modes/stiffness", b.stiffnessMatrix, "N/m");
    w.dataset("/modes/frequencies_hz", b.frequenciesHz.data(), {m}, "Hz");
    const std::vector<std::int8_t> rigid(b.rigidBody.begin(), b.rigidBody.end());
    w.dataset("/modes/rigid_body", rigid.data(), {m});
    w.dataset("/modes/damping_ratio", b.dampingRatios.data(), {m}, "1");
    w.matrix("/modes/interface_motion", b.interfaceMotion, "m and rad per unit modal coordinate");
}

// --- reading -----------------------------------------------------------------------------

/// Reads groups, attributes and datasets by absolute path, checking presence, rank and
/// type class; every failure names the file and the object.
class Reader {
public:
    Reader(std::string path, hid_t file) : path_(std::move(path)), file_(file) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error("reduced-body file '" + path_ + "': " + what);
    }

    /// Whether every link along an absolute path exists.
    bool has(const std::string& object) const {
        if (object == "/") return true;
        for (std::size_t slash = object.find('/', 1);; slash = object.find('/', slash + 1)) {
            const std::string prefix = object.substr(0, slash);
            if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
            if (slash == std::string::npos) return true;
        }
    }

    void requireGroup(const std::string& object) const {
        if (!has(object)) fail("missing group " + object);
    }

    /// Names of the links in a group, in name order.
    std::vector<std::string> children(const std::string& object) const {
        requireGroup(object);
        H5G_info_t info;
        check(H5Gget_info_by_name(file_, object.c_str(), &info, H5P_DEFAULT), "cannot read group " + object);
        std::vector<std::string> names;
        for (hsize_t k = 0; k < info.nlinks; ++k) {
            const auto size = H5Lget_name_by_idx(file_, object.c_str(), H5_INDEX_NAME, H5_ITER_INC, k, nullptr, 0,
                                                 H5P_DEFAULT);
            check(size, "cannot read group " + object);
            std::string name(std::size_t(size) + 1, '\0');
            H5Lget_name_by_idx(file_, object.c_str(), H5_INDEX_NAME, H5_ITER_INC, k, name.data(), name.size(),
                               H5P_DEFAULT);
            name.resize(std::size_t(size));
            names.push_back(name);
        }
        return names;
    }

    bool hasAttribute(const std::string& object, const std::string& name) const {
        return has(object) && H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
    }

    /// String attribute values (one for a scalar), variable or fixed length.
    std::vector<std::string> stringsAttr(const std::string& object, const std::string& name) const {
        const Attribute a = open(object, name, H5T_STRING, "a string");
        const auto n = hsize_t(H5Sget_simple_extent_npoints(a.space.get()));
        std::vector<std::string> values;
        if (n == 0) return values;
        if (H5Tis_variable_str(a.type.get()) > 0) {
            const Handle mem = stringType();
            std::vector<char*> pointers(n, nullptr);
            check(H5Aread(a.attribute.get(), mem.get(), pointers.data()), "cannot read " + a.what);
            for (char* p : pointers) values.emplace_back(p ? p : "");
            H5Dvlen_reclaim(mem.get(), a.space.get(), H5P_DEFAULT, pointers.data());
        } else {  // fixed length (e.g. numpy bytes written by h5py): null- or space-padded
            const std::size_t size = H5Tget_size(a.type.get());
            std::string buffer(n * size, '\0');
            check(H5Aread(a.attribute.get(), a.type.get(), buffer.data()), "cannot read " + a.what);
            for (hsize_t k = 0; k < n; ++k) {
                std::string v = buffer.substr(k * size, size);
                v.erase(std::min(v.find('\0'), v.find_last_not_of(' ') + 1));
                values.push_back(v);
            }
        }
        return values;
    }

    std::string stringAttr(const std::string& object, const std::string& name) const {
        const auto values = stringsAttr(object, name);
        if (values.size() != 1) fail("attribute '" + name + "' of " + object + " is not a single string");
        return values.front();
    }

    long long intAttr(const std::string& object, const std::string& name) const {
        return scalar<long long>(object, name, H5T_INTEGER, H5T_NATIVE_LLONG, "an integer");
    }

    double realAttr(const std::string& object, const std::string& name) const {
        return scalar<double>(object, name, H5T_FLOAT, H5T_NATIVE_DOUBLE, "a floating-point number");
    }

    /// Shape of a required dataset of the given rank.
    Dims shape(const std::string& object, int rank) const {
        if (!has(object)) fail("missing dataset " + object);
        Handle d(H5Dopen2(file_, object.c_str(), H5P_DEFAULT), H5Dclose);
        check(d.get(), "cannot open dataset " + object);
        Handle space(H5Dget_space(d.get()), H5Sclose);
        check(space.get(), "cannot read dataset " + object);
        if (H5Sget_simple_extent_ndims(space.get()) != rank)
            fail("dataset " + object + " has rank " + std::to_string(H5Sget_simple_extent_ndims(space.get())) +
                 ", expected " + std::to_string(rank));
        Dims dims(rank);
        H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
        return dims;
    }

    void expectShape(const std::string& object, const Dims& got, const Dims& expected,
                     const std::string& meaning) const {
        if (got != expected)
            fail("dataset " + object + " has shape " + shapeText(got) + ", expected " + shapeText(expected) + " (" +
                 meaning + ")");
    }

    /// Reads a whole dataset (already checked with shape()) into `out`, converting to T.
    template <class T>
    void read(const std::string& object, T* out, hsize_t count) const {
        if (count == 0) return;
        Handle d(H5Dopen2(file_, object.c_str(), H5P_DEFAULT), H5Dclose);
        check(d.get(), "cannot open dataset " + object);
        check(H5Dread(d.get(), H5Type<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out),
              "cannot read dataset " + object);
    }

    template <class T>
    std::vector<T> readVector(const std::string& object, hsize_t length, const std::string& meaning) const {
        expectShape(object, shape(object, 1), {length}, meaning);
        std::vector<T> v(length);
        read(object, v.data(), length);
        return v;
    }

    Eigen::MatrixXd readMatrix(const std::string& object, hsize_t rows, hsize_t cols, const std::string& meaning) const {
        expectShape(object, shape(object, 2), {rows, cols}, meaning);
        RowMajorMatrix m(rows, cols);
        read(object, m.data(), rows * cols);
        return m;
    }

    void check(std::int64_t status, const std::string& what) const {
        if (status < 0) fail(what + hdf5Detail());
    }

private:
    struct Attribute {
        Handle attribute, type, space;
        std::string what;
    };

    Attribute open(const std::string& object, const std::string& name, H5T_class_t typeClass,
                   const std::string& expected) const {
        const std::string what = "attribute '" + name + "' of " + object;
        if (!hasAttribute(object, name)) fail("missing " + what);
        Attribute a{Handle(H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose),
                    Handle(H5I_INVALID_HID, H5Tclose), Handle(H5I_INVALID_HID, H5Sclose), what};
        check(a.attribute.get(), "cannot open " + what);
        a.type = Handle(H5Aget_type(a.attribute.get()), H5Tclose);
        a.space = Handle(H5Aget_space(a.attribute.get()), H5Sclose);
        check(a.type.get(), "cannot read " + what);
        check(a.space.get(), "cannot read " + what);
        if (H5Tget_class(a.type.get()) != typeClass) fail(what + " is not " + expected);
        return a;
    }

    template <class T>
    T scalar(const std::string& object, const std::string& name, H5T_class_t typeClass, hid_t memType,
             const std::string& expected) const {
        const Attribute a = open(object, name, typeClass, expected);
        if (H5Sget_simple_extent_npoints(a.space.get()) != 1) fail(a.what + " is not a single value");
        T value{};
        check(H5Aread(a.attribute.get(), memType, &value), "cannot read " + a.what);
        return value;
    }

    std::string path_;
    hid_t file_;
};

void readBlock(const Reader& r, const std::string& object, const std::string& typeAttribute, int dimension,
               Eigen::Index numNodes, fem::ElementBlock& block) {
    const std::string typeName = r.stringAttr("/mesh", typeAttribute);
    try {
        block.type = elementTypeFromName(typeName);
    } catch (const std::invalid_argument& e) {
        r.fail("attribute '" + typeAttribute + "' of /mesh: " + e.what());
    }
    const Dims dims = r.shape(object, 2);
    const int npe = fem::nodesPerElement(block.type);
    // An empty block keeps whatever width it had (0 x 0 for a mesh without surfaces).
    if (dims[0] > 0 && (int(dims[1]) != npe || fem::dimension(block.type) != dimension))
        r.fail("dataset " + object + " has shape " + shapeText(dims) + ", which does not fit element type " + typeName);
    block.nodes.resize(Eigen::Index(dims[1]), Eigen::Index(dims[0]));
    r.read(object, block.nodes.data(), dims[0] * dims[1]);
    if (block.nodes.size() > 0 && (block.nodes.minCoeff() < 0 || block.nodes.maxCoeff() >= numNodes))
        r.fail("dataset " + object + " has node indices outside 0.." + std::to_string(numNodes - 1));
    const Dims tagDims = r.shape(object + "_tags", 1);
    if (tagDims[0] != 0) r.expectShape(object + "_tags", tagDims, {dims[0]}, "one Gmsh tag per element, or none");
    block.tags.resize(tagDims[0]);
    r.read(object + "_tags", reinterpret_cast<std::uint64_t*>(block.tags.data()), tagDims[0]);
}

void readMeshContent(const Reader& r, fem::Mesh& mesh) {
    r.requireGroup("/mesh");
    mesh.source = r.stringAttr("/mesh", "source");
    const Dims nodeDims = r.shape("/mesh/nodes", 2);
    r.expectShape("/mesh/nodes", nodeDims, {nodeDims[0], 3}, "nodes x 3 coordinates");
    mesh.nodes.resize(3, Eigen::Index(nodeDims[0]));
    r.read("/mesh/nodes", mesh.nodes.data(), 3 * nodeDims[0]);
    const Dims tagDims = r.shape("/mesh/node_tags", 1);
    if (tagDims[0] != 0) r.expectShape("/mesh/node_tags", tagDims, {nodeDims[0]}, "one Gmsh tag per node, or none");
    mesh.nodeTags.resize(tagDims[0]);
    r.read("/mesh/node_tags", reinterpret_cast<std::uint64_t*>(mesh.nodeTags.data()), tagDims[0]);

    const auto n = Eigen::Index(nodeDims[0]);
    readBlock(r, "/mesh/tetrahedra", "element_type", 3, n, mesh.volume);
    readBlock(r, "/mesh/triangles", "surface_element_type", 2, n, mesh.surface);

    for (const std::string& name : r.children("/mesh/groups")) {
        const std::string object = "/mesh/groups/" + name;
        fem::PhysicalGroup g;
        g.name = name;
        g.dim = int(r.intAttr(object, "dimension"));
        if (g.dim != 2 && g.dim != 3) r.fail("attribute 'dimension' of " + object + " must be 2 or 3");
        const Dims dims = r.shape(object + "/elements", 1);
        g.elements.resize(dims[0]);
        r.read(object + "/elements", g.elements.data(), dims[0]);
        const fem::Index count = g.dim == 3 ? mesh.volume.size() : mesh.surface.size();
        for (fem::Index e : g.elements)
            if (e < 0 || e >= count)
                r.fail("dataset " + object + "/elements has index " + std::to_string(e) + " outside the " +
                       std::to_string(count) + (g.dim == 3 ? " tetrahedra" : " triangles"));
        mesh.groups.emplace(name, std::move(g));
    }
}

ReducedBody readContent(const Reader& r) {
    ReducedBody b;
    b.meshPath = r.stringAttr("/provenance", "mesh_path");
    b.meshHash = r.stringAttr("/provenance", "mesh_hash");
    b.elementOrder = int(r.intAttr("/provenance", "element_order"));
    b.meshSize = r.realAttr("/provenance", "mesh_size_m");

    b.material.E = r.realAttr("/material", "E_pa");
    b.material.nu = r.realAttr("/material", "nu");
    b.material.rho = r.realAttr("/material", "rho_kg_m3");

    ReductionSettings& s = b.settings;
    s.normalModes = int(r.intAttr("/settings", "normal_modes"));
    s.cutoffHz = r.realAttr("/settings", "cutoff_hz");
    s.staticCorrection = r.stringsAttr("/settings", "static_correction");
    s.axialOrder = int(r.intAttr("/settings", "axial_order"));
    s.axialHats = int(r.intAttr("/settings", "axial_hats"));
    s.circumferentialOrder = int(r.intAttr("/settings", "circumferential_order"));
    s.dampingRatio = r.realAttr("/settings", "damping_ratio");

    readMeshContent(r, b.mesh);
    const Eigen::Index n = b.mesh.numNodes();

    const long long interfaces = r.intAttr("/interfaces", "count");
    for (long long i = 0; i < interfaces; ++i) {
        const std::string object = "/interfaces/" + std::to_string(i);
        r.requireGroup(object);
        Interface itf;
        itf.group = r.stringAttr(object, "group");
        const std::string kind = r.stringAttr(object, "kind");
        if (kind != "rbe2" && kind != "rbe3")
            r.fail("attribute 'kind' of " + object + " is '" + kind + "', expected 'rbe2' or 'rbe3'");
        itf.kind = kind == "rbe2" ? InterfaceKind::Rbe2 : InterfaceKind::Rbe3;
        r.expectShape(object + "/reference_point", r.shape(object + "/reference_point", 1), {3}, "x, y, z");
        r.read(object + "/reference_point", itf.referencePoint.data(), 3);
        const Dims dims = r.shape(object + "/nodes", 1);
        itf.nodes.resize(dims[0]);
        r.read(object + "/nodes", itf.nodes.data(), dims[0]);
        for (fem::Index k : itf.nodes)
            if (k < 0 || k >= n)
                r.fail("dataset " + object + "/nodes has node index " + std::to_string(k) + " outside 0.." +
                       std::to_string(n - 1));
        b.interfaces.push_back(std::move(itf));
    }

    r.requireGroup("/modes");
    const Dims shapeDims = r.shape("/modes/shapes", 2);
    const hsize_t m = shapeDims[0];
    r.expectShape("/modes/shapes", shapeDims, {m, hsize_t(3 * n)}, "modes x 3 nodes");
    b.shapes.resize(3 * n, Eigen::Index(m));
    r.read("/modes/shapes", b.shapes.data(), m * 3 * n);
    b.massMatrix = r.readMatrix("/modes/mass", m, m, "modes x modes");
    b.stiffnessMatrix = r.readMatrix("/modes/stiffness", m, m, "modes x modes");
    const auto f = r.readVector<double>("/modes/frequencies_hz", m, "one per mode");
    b.frequenciesHz = Eigen::Map<const Eigen::VectorXd>(f.data(), Eigen::Index(m));
    const auto rigid = r.readVector<std::int8_t>("/modes/rigid_body", m, "one per mode");
    b.rigidBody.assign(rigid.begin(), rigid.end());
    const auto zeta = r.readVector<double>("/modes/damping_ratio", m, "one per mode");
    b.dampingRatios = Eigen::Map<const Eigen::VectorXd>(zeta.data(), Eigen::Index(m));
    b.interfaceMotion =
        r.readMatrix("/modes/interface_motion", 6 * b.interfaces.size(), m, "6 x interfaces, modes");
    if (const auto defect = reducedBodyDefect(b)) r.fail(*defect);
    return b;
}

}  // namespace

void writeReducedBody(const ReducedBody& body, const std::string& path) {
    checkConsistent(body);
    // The file's directory is made as the run's output directories are.
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty() && !std::filesystem::create_directories(parent, ec) && ec)
        throw std::runtime_error("cannot create the directory '" + parent.string() + "' for reduced-body file '" +
                                 path + "': " + ec.message());
    const QuietHdf5Errors quiet;
    fem::writeAtomically(path, [&](const std::string& tmp) {
        Handle file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
        if (!file.valid())
            throw std::runtime_error("cannot create reduced-body file '" + tmp + "'" + hdf5Detail());
        writeContent(body, Writer(path, file.get()));
        if (file.close() < 0)
            throw std::runtime_error("cannot write reduced-body file '" + tmp + "'" + hdf5Detail());
    });
}

ReducedBody readReducedBody(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(path, ec)) throw std::runtime_error("reduced-body file '" + path + "' does not exist");
    if (fs::is_directory(path, ec)) throw std::runtime_error("reduced-body file '" + path + "' is a directory");
    const QuietHdf5Errors quiet;
    if (H5Fis_hdf5(path.c_str()) <= 0) {
        H5Eclear2(H5E_DEFAULT);
        throw std::runtime_error("'" + path + "' is not an HDF5 file or damaged");
    }
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!file.valid())
        throw std::runtime_error("cannot open '" + path + "': not an HDF5 file or damaged" + hdf5Detail());
    const Reader r(path, file.get());
    if (!r.hasAttribute("/", "format"))
        throw std::runtime_error("'" + path + "' is not a flexehd reduced-body file (no root attribute 'format')");
    const std::string format = r.stringAttr("/", "format");
    if (format != kReducedBodyFormat)
        throw std::runtime_error("'" + path + "' is not a flexehd reduced-body file (format '" + format + "')");
    const long long version = r.intAttr("/", "format_version");
    if (version != kReducedBodyFormatVersion)
        throw std::runtime_error("reduced-body file '" + path + "' has format version " + std::to_string(version) +
                                 ", this flexehd reads version " + std::to_string(kReducedBodyFormatVersion));
    return readContent(r);
}

std::string fnv1a64File(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read '" + path + "' to hash it");
    std::uint64_t hash = 0xcbf29ce484222325ULL;  // FNV-1a 64-bit offset basis and prime
    std::array<char, 1 << 16> buffer;
    do {
        in.read(buffer.data(), buffer.size());
        for (std::streamsize k = 0; k < in.gcount(); ++k) {
            hash ^= static_cast<unsigned char>(buffer[std::size_t(k)]);
            hash *= 0x100000001b3ULL;
        }
    } while (in);
    if (in.bad()) throw std::runtime_error("error reading '" + path + "' to hash it");
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    return hex;
}

}  // namespace flexehd::modal
