#include "cosim/coupling/MemoryBudget.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace flexehd::cosim {

namespace {

/// MemAvailable of /proc/meminfo in bytes, 0 if absent.
std::uint64_t memAvailable() {
    std::ifstream in("/proc/meminfo");
    std::string key;
    std::uint64_t kb = 0;
    std::string unit;
    while (in >> key >> kb) {
        std::getline(in, unit);
        if (key == "MemAvailable:") return kb * 1024;
    }
    return 0;
}

/// A number from a cgroup file ("max" or absent: 0).
std::uint64_t cgroupValue(const char* file) {
    std::ifstream in(file);
    std::string s;
    if (!(in >> s) || s == "max") return 0;
    std::istringstream v(s);
    std::uint64_t x = 0;
    return (v >> x) ? x : 0;
}

}  // namespace

std::uint64_t availableMemoryBytes() {
    std::uint64_t avail = memAvailable();
    const auto cap = [&](std::uint64_t limit) {
        if (limit > 0) avail = avail > 0 ? std::min(avail, limit) : limit;
    };
    const std::uint64_t max = cgroupValue("/sys/fs/cgroup/memory.max");
    if (max > 0) cap(max - std::min(max, cgroupValue("/sys/fs/cgroup/memory.current")));
    rlimit as{};
    if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) cap(as.rlim_cur);
    return avail;
}

double filmMemoryEstimateBytes(double nodes, int modes) { return nodes * (500.0 + 64.0 * std::max(0, modes)); }

std::string formatBytes(double bytes) {
    const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
    int u = 0;
    while (bytes >= 1000.0 && u < 6) {
        bytes /= 1000.0;
        ++u;
    }
    return bytes < 10.0 && u > 0 ? fmt::format("{:.1f} {}", bytes, units[u]) : fmt::format("{:.0f} {}", bytes, units[u]);
}

void requireFilmMemory(const std::string& where, int axialNodes, int circumferentialNodes, int modes) {
    const double nodes = double(axialNodes) * double(circumferentialNodes);
    // The film solvers index nodes (and 5 matrix entries per node) with 32-bit integers.
    if (5.0 * nodes > double(std::numeric_limits<int>::max()))
        throw std::runtime_error(fmt::format("{}: the film grid of {} × {} = {:.0f} nodes is larger than the film "
                                             "solvers can index (at most {} nodes): use a coarser grid",
                                             where, axialNodes, circumferentialNodes, nodes,
                                             std::numeric_limits<int>::max() / 5));
    const double need = filmMemoryEstimateBytes(nodes, modes);
    const std::uint64_t avail = availableMemoryBytes();
    if (avail == 0 || need <= double(avail)) return;
    throw std::runtime_error(fmt::format(
        "{}: the film grid of {} × {} = {:.0f} nodes{} needs at least {} of memory; {} are available: use a "
        "coarser grid (docs/case-file.md, grid)",
        where, axialNodes, circumferentialNodes, nodes, modes > 0 ? fmt::format(" with {} modes", modes) : "",
        formatBytes(need), formatBytes(double(avail))));
}

}  // namespace flexehd::cosim
