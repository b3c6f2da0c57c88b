#pragma once
// The reduced-body file: a self-describing HDF5 file holding a ReducedBody, for the
// co-simulation and for other tools (h5py, ParaView through `flexehd export-modes`).
// Layout and versioning rule: docs/reduced-body-format.md.
#include <string>

#include "modal/ReducedBody.hpp"

namespace flexehd::modal {

/// Value of the root attribute `format`.
inline constexpr const char* kReducedBodyFormat = "flexehd-reduced-body";
/// The only `format_version` this build writes and reads.
inline constexpr int kReducedBodyFormatVersion = 1;
/// Value of the root attribute `units`: every quantity in the file is in these.
inline constexpr const char* kReducedBodyUnits = "SI: m, kg, s, N, Pa, rad";

/// Writes `body` to `path` (HDF5), through "<path>.tmp" renamed when complete, so a
/// killed run never leaves a truncated file. Throws std::runtime_error naming the file
/// and object on failure, std::invalid_argument if the body is inconsistent (array
/// sizes, group names HDF5 cannot hold).
void writeReducedBody(const ReducedBody& body, const std::string& path);

/// Reads a file written by writeReducedBody; every float64 array comes back bitwise
/// identical. Throws std::runtime_error naming the file (and the object) if it is
/// missing, not HDF5 or damaged, of another format or format version, or if a required
/// group, attribute or dataset is missing or of inconsistent size, or if a value is not what
/// a body can have (reducedBodyDefect: non-finite, unphysical material, modal mass not
/// positive definite, stiffness not symmetric positive semi-definite).
ReducedBody readReducedBody(const std::string& path);

/// 64-bit FNV-1a hash of the bytes of a file as 16 lower-case hex digits (the mesh
/// hash of ReducedBody). Throws std::runtime_error if the file cannot be read.
std::string fnv1a64File(const std::string& path);

}  // namespace flexehd::modal
