// fnv1a64File: the content hash of a file (reduced bodies are cached and fingerprinted by it).
#include "modal/ReducedBodyFile.hpp"

#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace flexehd::modal {

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
