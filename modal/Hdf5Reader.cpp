#include "modal/Hdf5Reader.hpp"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "modal/Hdf5Handle.hpp"

namespace flexehd::modal {

struct Hdf5Reader::File {
    QuietHdf5Errors quiet;
    Hdf5Handle id;
    explicit File(const std::string& path) : id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose) {}
};

Hdf5Reader::Hdf5Reader(const std::string& path, std::string what) : what_(std::move(what)), path_(path) {
    if (!std::filesystem::exists(path)) fail("no such file");
    file_ = std::make_unique<File>(path);
    if (file_->id.get() < 0) fail("cannot open it as an HDF5 file");
}

Hdf5Reader::~Hdf5Reader() = default;

void Hdf5Reader::fail(const std::string& what) const { throw std::runtime_error(what_ + " " + path_ + ": " + what); }

std::vector<double> Hdf5Reader::doubles(const std::string& name, std::vector<unsigned long long>& dims) const {
    if (H5Lexists(file_->id.get(), name.c_str(), H5P_DEFAULT) <= 0) fail("no dataset " + name);
    Hdf5Handle set(H5Dopen2(file_->id.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
    if (set.get() < 0) fail("cannot open dataset " + name);
    Hdf5Handle space(H5Dget_space(set.get()), H5Sclose);
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank < 1) fail("dataset " + name + " has no dimensions");
    std::vector<hsize_t> d(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space.get(), d.data(), nullptr);
    dims.assign(d.begin(), d.end());
    std::size_t n = 1;
    for (hsize_t k : d) n *= static_cast<std::size_t>(k);
    std::vector<double> v(n);
    if (n > 0 && H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
        fail("cannot read dataset " + name + " as numbers");
    for (std::size_t k = 0; k < n; ++k)
        if (!std::isfinite(v[k])) fail("dataset " + name + " holds a value that is not finite (at " + std::to_string(k) + ")");
    return v;
}

namespace {

Hdf5Handle openAttribute(const Hdf5Reader& r, hid_t file, const std::string& object, const std::string& name) {
    if (H5Aexists_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT) <= 0)
        r.fail("no attribute " + object + "@" + name);
    return Hdf5Handle(H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
}

}  // namespace

std::string Hdf5Reader::stringAttribute(const std::string& object, const std::string& name) const {
    Hdf5Handle a = openAttribute(*this, file_->id.get(), object, name);
    Hdf5Handle type(H5Aget_type(a.get()), H5Tclose);
    if (H5Tget_class(type.get()) != H5T_STRING) fail("attribute " + object + "@" + name + " is not text");
    if (H5Tis_variable_str(type.get()) > 0) {
        char* p = nullptr;
        Hdf5Handle mem(H5Tcopy(H5T_C_S1), H5Tclose);
        H5Tset_size(mem.get(), H5T_VARIABLE);
        H5Tset_cset(mem.get(), H5Tget_cset(type.get()));
        if (H5Aread(a.get(), mem.get(), &p) < 0 || !p) fail("cannot read attribute " + object + "@" + name);
        std::string s(p);
        H5free_memory(p);
        return s;
    }
    std::string s(H5Tget_size(type.get()), '\0');
    if (H5Aread(a.get(), type.get(), s.data()) < 0) fail("cannot read attribute " + object + "@" + name);
    return s.substr(0, s.find('\0'));
}

double Hdf5Reader::doubleAttribute(const std::string& object, const std::string& name) const {
    Hdf5Handle a = openAttribute(*this, file_->id.get(), object, name);
    double v = 0.0;
    if (H5Aread(a.get(), H5T_NATIVE_DOUBLE, &v) < 0 || !std::isfinite(v))
        fail("attribute " + object + "@" + name + " is not a finite number");
    return v;
}

int Hdf5Reader::intAttribute(const std::string& object, const std::string& name) const {
    Hdf5Handle a = openAttribute(*this, file_->id.get(), object, name);
    int v = 0;
    if (H5Aread(a.get(), H5T_NATIVE_INT, &v) < 0) fail("attribute " + object + "@" + name + " is not an integer");
    return v;
}

}  // namespace flexehd::modal
