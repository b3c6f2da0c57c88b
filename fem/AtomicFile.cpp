#include "fem/AtomicFile.hpp"

#include <cerrno>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

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
        throw std::runtime_error("cannot write '" + path + "': " + writeFailureReason(path, ec.value()));
    }
}

int writeAllAt(int fd, std::string_view text, long long offset) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::pwrite(fd, text.data() + done, text.size() - done, static_cast<off_t>(offset + done));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return errno;
        if (n == 0) return EIO;
        done += static_cast<std::size_t>(n);
    }
    return 0;
}

void writeTextAtomically(const std::string& path, const std::string& text) {
    writeAtomically(path, [&](const std::string& tmp) {
        const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (fd < 0) throw std::runtime_error("cannot write '" + path + "': " + writeFailureReason(tmp, errno));
        int err = writeAllAt(fd, text, 0);
        if (::close(fd) != 0 && err == 0) err = errno;
        if (err) throw std::runtime_error("cannot write '" + path + "': " + writeFailureReason(tmp, err));
    });
}

std::string writeFailureReason(const std::string& path, int errnum) {
    switch (errnum) {
        case ENOSPC: return "the disk is full (no space left on device, ENOSPC)";
        case EDQUOT: return "the disk quota is used up (EDQUOT)";
        case EROFS: return "the file system is read-only (EROFS)";
        case EACCES:
        case EPERM: return "permission denied (EACCES)";
        case EFBIG: return "the file would exceed the largest size allowed (EFBIG)";
        case EIO: return "an input/output error of the device (EIO)";
        case 0: break;
        default: return std::generic_category().message(errnum);
    }
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) dir = ".";
    const fs::space_info s = fs::space(dir, ec);
    if (!ec && s.available < 64 * 1024) return "the disk is full (no space left on device, ENOSPC)";
    return "an I/O error (the writer gave no reason)";
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
