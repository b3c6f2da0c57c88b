#include "fem/AtomicFile.hpp"

#include <fstream>

#include <filesystem>
#include <vector>
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

void writeTextAtomically(const std::string& path, const std::string& text) {
    writeAtomically(path, [&](const std::string& tmp) {
        std::ofstream f(tmp);
        f << text;
        f.close();
        if (!f) throw std::runtime_error("cannot write " + tmp);
    });
}

int removeStaleTemporaries(const std::string& directory) {
    namespace fs = std::filesystem;
    static const char* const kOutputs[] = {".vtu", ".vts", ".pvd", ".json", ".csv", ".h5", ".fingerprint"};
    std::error_code ec;
    if (!fs::is_directory(directory, ec)) return 0;
    std::vector<fs::path> stale;
    for (auto it = fs::recursive_directory_iterator(directory, fs::directory_options::skip_permission_denied, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const fs::path& p = it->path();
        if (p.extension() != ".tmp" || !it->is_regular_file(ec)) continue;
        const std::string inner = p.stem().extension().string();
        for (const char* e : kOutputs)
            if (inner == e) stale.push_back(p);
    }
    int removed = 0;
    for (const fs::path& p : stale) removed += fs::remove(p, ec) ? 1 : 0;
    return removed;
}

}  // namespace flexehd::fem
