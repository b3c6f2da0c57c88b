#pragma once
// AppendFile: a file that grows by whole pieces (a CSV row, say) or not at all. Each append is
// written straight to the file (no buffer that a later flush could write twice); a failed
// append (a full disk) is cut back so that the file ends where it ended before, and the error
// says why in words (writeFailureReason).
#include <string>
#include <string_view>

namespace flexehd::fem {

class AppendFile {
public:
    /// Creates (or truncates) `path`. Throws std::runtime_error naming the file and the reason.
    explicit AppendFile(std::string path);
    ~AppendFile();
    AppendFile(const AppendFile&) = delete;
    AppendFile& operator=(const AppendFile&) = delete;

    /// Appends `text` whole. On failure the file is truncated back to its size before the call
    /// and std::runtime_error names the file, the reason and how many bytes the file keeps.
    void append(std::string_view text);

    const std::string& path() const { return path_; }
    /// Bytes in the file (everything appended so far).
    long long size() const { return size_; }

private:
    std::string path_;
    int fd_ = -1;
    long long size_ = 0;
};

}  // namespace flexehd::fem
