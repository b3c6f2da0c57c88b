#pragma once
// MemoryBudget: the memory a run's film grid needs, estimated before it is allocated, against
// what the machine can still give (docs/case-file.md, "grid").
#include <cstdint>
#include <string>

namespace flexehd::cosim {

/// Bytes this process can still allocate: the kernel's MemAvailable, capped by the control
/// group's memory.max less its memory.current and by the address-space limit; 0 when unknown.
std::uint64_t availableMemoryBytes();

/// A lower bound of the memory a run holds for `nodes` film nodes and `modes` modal coordinates
/// of the flexible bodies (bytes): 500 per node and 64 per node and mode, below the peak
/// resident sizes measured on the example cases (docs/case-file.md, "grid").
double filmMemoryEstimateBytes(double nodes, int modes);

/// "3.2 GB", "310 MB": a byte count as people write it.
std::string formatBytes(double bytes);

/// Throws std::runtime_error, starting with `where`, when the grid has more nodes than the film
/// solvers can index or the estimate exceeds what is available.
void requireFilmMemory(const std::string& where, int axialNodes, int circumferentialNodes, int modes);

}  // namespace flexehd::cosim
