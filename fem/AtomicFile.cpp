#include "fem/AtomicFile.hpp"

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace flexehd::fem {

void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write) {
    namespace fs = std::filesystem;
    const std::string tmp = path + ".tmp";
    try {
        write(tmp);
    } catch (...) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        throw;
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(tmp, ignored);  // nothing half-done stays behind
        throw std::runtime_error("cannot write '" + path + "': " + ec.message());
    }
}

}  // namespace flexehd::fem
