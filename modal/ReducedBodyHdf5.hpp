#pragma once
// The HDF5 plumbing of the reduced-body file (ReducedBodyWriter.cpp, ReducedBodyReader.cpp):
// element types and their little-endian file types, UTF-8 string type, HDF5 error detail,
// shape text, interface and element-type names. Internal to modal/.
#include <hdf5.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "fem/ElementType.hpp"
#include "modal/Hdf5Handle.hpp"
#include "modal/ReducedBody.hpp"

namespace flexehd::modal::hdf5 {

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using Dims = std::vector<hsize_t>;

// --- HDF5 plumbing ----------------------------------------------------------------------

using Handle = Hdf5Handle;

/// " (HDF5: <the most specific message on HDF5's error stack>)", e.g. "truncated file:
/// eof = ...", or "" if the stack is empty; clears the stack.
inline std::string hdf5Detail() {
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
inline Handle stringType() {
    Handle t(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(t.get(), H5T_VARIABLE);
    H5Tset_cset(t.get(), H5T_CSET_UTF8);
    return t;
}

inline std::string shapeText(const Dims& dims) {
    std::string s = "[";
    for (std::size_t k = 0; k < dims.size(); ++k) s += (k ? ", " : "") + std::to_string(dims[k]);
    return s + "]";
}

inline std::string_view kindName(InterfaceKind kind) { return kind == InterfaceKind::Rbe2 ? "rbe2" : "rbe3"; }

inline fem::ElementType elementTypeFromName(const std::string& name) {
    for (auto t : {fem::ElementType::Tri3, fem::ElementType::Tri6, fem::ElementType::Tet4, fem::ElementType::Tet10})
        if (fem::name(t) == name) return t;
    throw std::invalid_argument("unknown element type '" + name + "'");
}



}  // namespace flexehd::modal::hdf5
