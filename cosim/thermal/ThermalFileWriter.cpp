#include "cosim/thermal/ThermalFileWriter.hpp"

#include "modal/Hdf5Handle.hpp"

#include <cmath>
#include <stdexcept>

#include "fem/AtomicFile.hpp"

namespace flexehd::cosim {
namespace {

using Id = modal::Hdf5Handle;

class Writer {
public:
    Writer(const std::string& path, const std::string& shownAs)
        : shown_(shownAs), file_(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose) {
        if (file_.get() < 0) fail("cannot create the file");
    }
    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error("thermal file " + shown_ + ": " + what);
    }
    void check(herr_t r, const std::string& what) const {
        if (r < 0) fail(what);
    }

    void group(const std::string& name) {
        Id g(H5Gcreate2(file_.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
        if (g.get() < 0) fail("cannot create group " + name);
    }
    void stringAttribute(const std::string& object, const std::string& name, const std::string& value) {
        Id type(H5Tcopy(H5T_C_S1), H5Tclose);
        H5Tset_size(type.get(), H5T_VARIABLE);
        H5Tset_cset(type.get(), H5T_CSET_UTF8);
        Id space(H5Screate(H5S_SCALAR), H5Sclose);
        Id a(H5Acreate_by_name(file_.get(), object.c_str(), name.c_str(), type.get(), space.get(), H5P_DEFAULT,
                               H5P_DEFAULT, H5P_DEFAULT),
             H5Aclose);
        const char* p = value.c_str();
        check(a.get() < 0 ? -1 : H5Awrite(a.get(), type.get(), &p), "cannot write attribute " + object + "@" + name);
    }
    template <typename T>
    void scalarAttribute(const std::string& object, const std::string& name, hid_t fileType, hid_t memType, T value) {
        Id space(H5Screate(H5S_SCALAR), H5Sclose);
        Id a(H5Acreate_by_name(file_.get(), object.c_str(), name.c_str(), fileType, space.get(), H5P_DEFAULT,
                               H5P_DEFAULT, H5P_DEFAULT),
             H5Aclose);
        check(a.get() < 0 ? -1 : H5Awrite(a.get(), memType, &value), "cannot write attribute " + object + "@" + name);
    }
    void dataset(const std::string& name, const std::vector<hsize_t>& dims, hid_t fileType, hid_t memType,
                 const void* data) {
        Id space(H5Screate_simple(int(dims.size()), dims.data(), nullptr), H5Sclose);
        Id d(H5Dcreate2(file_.get(), name.c_str(), fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose);
        check(d.get() < 0 ? -1 : H5Dwrite(d.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
              "cannot write dataset " + name);
    }
    void close() { check(file_.close(), "cannot close (flush) the file"); }

private:
    std::string shown_;
    Id file_;
};

// GROUP/ring_belt: the surface temperature's profile over z.
void writeRingBelt(Writer& w, const std::string& g, const AxialProfile& p, const std::string& surface) {
    const auto n = hsize_t(p.axial.size());
    if (n < 2 || p.values.size() != p.axial.size()) w.fail(g + ": inconsistent profile sizes");
    for (std::size_t k = 0; k < p.axial.size(); ++k) {
        if (!std::isfinite(p.axial[k]) || (k > 0 && !(p.axial[k] > p.axial[k - 1])))
            w.fail(g + ": z values are not finite and strictly increasing");
        if (!std::isfinite(p.values[k]) || !(p.values[k] > 0.0))
            w.fail(g + ": a temperature is not finite and positive");
    }
    w.group(g);
    if (!surface.empty()) w.stringAttribute(g, "surface", surface);
    w.stringAttribute(g, "quantity", "circumferential mean temperature of the outer surface");
    w.dataset(g + "/z_m", {n}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, p.axial.data());
    w.dataset(g + "/temperature_k", {n}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, p.values.data());
    w.stringAttribute(g + "/z_m", "units", "m");
    w.stringAttribute(g + "/temperature_k", "units", "K");
}

void writeBody(Writer& w, const std::string& g, const ThermalBodyTable& body) {
    const SurfaceTable& t = body.table;
    const auto nz = hsize_t(t.axial.size()), nt = hsize_t(t.theta.size());
    if (nz < 2 || nt < 3 || hsize_t(t.radial.rows()) != nz || hsize_t(t.radial.cols()) != nt ||
        t.onSurface.rows() != t.radial.rows() || t.onSurface.cols() != t.radial.cols())
        w.fail(g + ": inconsistent table sizes");
    if (!t.radial.allFinite()) w.fail(g + ": radial displacement has a non-finite value");
    for (std::size_t k = 1; k < t.axial.size(); ++k)
        if (!(t.axial[k] > t.axial[k - 1])) w.fail(g + ": axial values are not strictly increasing");
    w.group(g);
    w.stringAttribute(g, "units", "m");
    for (const auto& [name, value] : body.attributes) {
        if (!std::isfinite(value)) w.fail(g + "@" + name + " is not finite");
        w.scalarAttribute(g, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, value);
    }
    for (const auto& [name, value] : body.textAttributes) w.stringAttribute(g, name, value);
    w.dataset(g + "/axial", {nz}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, t.axial.data());
    w.dataset(g + "/theta", {nt}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, t.theta.data());
    w.dataset(g + "/radial_displacement", {nz, nt}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, t.radial.data());
    w.dataset(g + "/on_surface", {nz, nt}, H5T_STD_U8LE, H5T_NATIVE_UCHAR, t.onSurface.data());
    for (const auto& [name, unit] : {std::pair{"axial", "m"}, {"theta", "rad"}, {"radial_displacement", "m"}, {"on_surface", "1"}})
        w.stringAttribute(g + "/" + name, "units", unit);
    if (body.ringBelt) writeRingBelt(w, g + "/ring_belt", *body.ringBelt, body.ringBeltSurface);
}

}  // namespace

void writeThermalFile(const std::string& path, const std::optional<ThermalBodyTable>& piston,
                      const std::optional<ThermalBodyTable>& liner) {
    if (!piston && !liner) throw std::runtime_error("thermal file " + path + ": neither piston nor liner to write");
    fem::writeAtomically(path, [&](const std::string& tmp) {
        Writer w(tmp, path);
        w.stringAttribute("/", "format", "flexehd-thermal");
        w.scalarAttribute("/", "format_version", H5T_STD_I32LE, H5T_NATIVE_INT, 1);
        if (piston) writeBody(w, "/piston", *piston);
        if (liner) writeBody(w, "/liner", *liner);
        w.close();
    });
}

}  // namespace flexehd::cosim
