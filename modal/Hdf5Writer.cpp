#include "modal/Hdf5Writer.hpp"

#include <stdexcept>

#include "modal/Hdf5Handle.hpp"

namespace flexehd::modal {

struct Hdf5Writer::File {
    QuietHdf5Errors quiet;
    Hdf5Handle id;
    explicit File(const std::string& path)
        : id(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose) {}
};

namespace {

using Id = Hdf5Handle;

void dataset(const Hdf5Writer& w, hid_t file, const std::string& name, const std::vector<unsigned long long>& dims,
             hid_t fileType, hid_t memType, const void* data) {
    const std::vector<hsize_t> d(dims.begin(), dims.end());
    Id space(H5Screate_simple(int(d.size()), d.data(), nullptr), H5Sclose);
    Id set(H5Dcreate2(file, name.c_str(), fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
    if (set.get() < 0 || H5Dwrite(set.get(), memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
        w.fail("cannot write dataset " + name);
}

template <typename T>
void scalarAttribute(const Hdf5Writer& w, hid_t file, const std::string& object, const std::string& name,
                     hid_t fileType, hid_t memType, T value) {
    Id space(H5Screate(H5S_SCALAR), H5Sclose);
    Id a(H5Acreate_by_name(file, object.c_str(), name.c_str(), fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                           H5P_DEFAULT),
         H5Aclose);
    if (a.get() < 0 || H5Awrite(a.get(), memType, &value) < 0) w.fail("cannot write attribute " + object + "@" + name);
}

}  // namespace

Hdf5Writer::Hdf5Writer(const std::string& path, std::string what, std::string shownAs)
    : file_(std::make_unique<File>(path)), what_(std::move(what)), shown_(std::move(shownAs)) {
    if (file_->id.get() < 0) fail("cannot create the file");
}

Hdf5Writer::~Hdf5Writer() = default;

void Hdf5Writer::fail(const std::string& what) const { throw std::runtime_error(what_ + " " + shown_ + ": " + what); }

void Hdf5Writer::group(const std::string& name) {
    Id g(H5Gcreate2(file_->id.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    if (g.get() < 0) fail("cannot create group " + name);
}

void Hdf5Writer::stringAttribute(const std::string& object, const std::string& name, const std::string& value) {
    Id type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type.get(), H5T_VARIABLE);
    H5Tset_cset(type.get(), H5T_CSET_UTF8);
    Id space(H5Screate(H5S_SCALAR), H5Sclose);
    Id a(H5Acreate_by_name(file_->id.get(), object.c_str(), name.c_str(), type.get(), space.get(), H5P_DEFAULT,
                           H5P_DEFAULT, H5P_DEFAULT),
         H5Aclose);
    const char* p = value.c_str();
    if (a.get() < 0 || H5Awrite(a.get(), type.get(), &p) < 0) fail("cannot write attribute " + object + "@" + name);
}

void Hdf5Writer::doubleAttribute(const std::string& object, const std::string& name, double value) {
    scalarAttribute(*this, file_->id.get(), object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, value);
}

void Hdf5Writer::intAttribute(const std::string& object, const std::string& name, int value) {
    scalarAttribute(*this, file_->id.get(), object, name, H5T_STD_I32LE, H5T_NATIVE_INT, value);
}

void Hdf5Writer::doubles(const std::string& name, const std::vector<unsigned long long>& dims, const double* data) {
    dataset(*this, file_->id.get(), name, dims, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data);
}

void Hdf5Writer::bytes(const std::string& name, const std::vector<unsigned long long>& dims,
                       const unsigned char* data) {
    dataset(*this, file_->id.get(), name, dims, H5T_STD_U8LE, H5T_NATIVE_UCHAR, data);
}

void Hdf5Writer::ints(const std::string& name, const std::vector<unsigned long long>& dims, const int* data) {
    dataset(*this, file_->id.get(), name, dims, H5T_STD_I32LE, H5T_NATIVE_INT, data);
}

void Hdf5Writer::close() {
    if (file_->id.close() < 0) fail("cannot close (flush) the file");
}

}  // namespace flexehd::modal
