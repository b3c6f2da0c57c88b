// writeReducedBody: the reduced body as a self-describing HDF5 file (docs/reduced-body-format.md),
// written atomically.
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
    if (b.supportDamping.size() > 0 && (b.supportDamping.rows() != m || b.supportDamping.cols() != m))
        fail("support damping matrix is " + size(b.supportDamping.rows(), b.supportDamping.cols()) + " for " +
             std::to_string(m) + " modes");
    if ((b.supportDamping.size() > 0) != !b.settings.dampers.empty())
        fail("support damping matrix and damper settings must come together");
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
    w.stringsAttribute("/settings", "pressure_patterns", s.pressurePatterns);
    w.stringsAttribute("/settings", "supports", s.supports);
    w.stringsAttribute("/settings", "dampers", s.dampers);
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
    // Optional: only a body with damper supports has it (docs/reduced-body-format.md).
    if (b.supportDamping.size() > 0) w.matrix("/modes/support_damping", b.supportDamping, "N s/m");
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

}  // namespace flexehd::modal
