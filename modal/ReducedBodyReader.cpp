// readReducedBody: the HDF5 file back as a ReducedBody, every dataset checked for presence, rank,
// type and values (docs/reduced-body-format.md).
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
#include "modal/ReducedBodyHdf5.hpp"

namespace flexehd::modal {
namespace {

using namespace hdf5;

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

    /// An attribute added after version 1 of the format: absent in older files, which read
    /// as an empty list (docs/reduced-body-format.md, "Versioning").
    std::vector<std::string> optionalStringsAttr(const std::string& object, const std::string& name) const {
        return hasAttribute(object, name) ? stringsAttr(object, name) : std::vector<std::string>{};
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
    s.pressurePatterns = r.optionalStringsAttr("/settings", "pressure_patterns");
    s.supports = r.optionalStringsAttr("/settings", "supports");
    s.dampers = r.optionalStringsAttr("/settings", "dampers");
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
    // Added after version 1 (docs/reduced-body-format.md, "Versioning"): older files have no dampers.
    if (r.has("/modes/support_damping")) b.supportDamping = r.readMatrix("/modes/support_damping", m, m, "modes x modes");
    if (const auto defect = reducedBodyDefect(b)) r.fail(*defect);
    return b;
}


}  // namespace

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

}  // namespace flexehd::modal
