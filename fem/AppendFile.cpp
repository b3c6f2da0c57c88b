#include "fem/AppendFile.hpp"

#include <cerrno>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

#include "fem/AtomicFile.hpp"

namespace flexehd::fem {

AppendFile::AppendFile(std::string path) : path_(std::move(path)) {
    fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd_ < 0) throw std::runtime_error("cannot write '" + path_ + "': " + writeFailureReason(path_, errno));
}

AppendFile::~AppendFile() {
    if (fd_ >= 0) ::close(fd_);
}

void AppendFile::append(std::string_view text) {
    const int err = writeAllAt(fd_, text, size_);
    if (err == 0) {
        size_ += static_cast<long long>(text.size());
        return;
    }
    const bool cut = ::ftruncate(fd_, static_cast<off_t>(size_)) == 0;
    throw std::runtime_error("cannot write '" + path_ + "': " + writeFailureReason(path_, err) +
                             (cut ? "; the file keeps what was written before this row"
                                  : "; the file may end in a partial line, which readers drop"));
}

}  // namespace flexehd::fem
