#pragma once
// Crash-safe file output: content is written to "<path>.tmp" and renamed over `path`
// only once complete, so a killed run never leaves a truncated file behind. A write that
// fails says why in words (a full disk as "no space left on device (ENOSPC)").
#include <functional>
#include <string>
#include <string_view>

namespace flexehd::fem {

/// Calls `write(temporaryPath)`, then atomically renames the result to `path`.
/// Throws std::runtime_error naming the file if writing or renaming fails.
void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write);

/// writeAtomically of a text (the whole file); the error names the reason (writeFailureReason).
void writeTextAtomically(const std::string& path, const std::string& text);

/// Writes all of `text` to the open file descriptor `fd` at `offset` (pwrite, retried on
/// EINTR and short writes). Returns 0, or the errno of the write that failed.
int writeAllAt(int fd, std::string_view text, long long offset);

/// Why writing `path` failed, in words: the reason for `errnum` (ENOSPC, EDQUOT, EROFS, EACCES,
/// EFBIG, EIO named with their symbol), or, for errnum 0 (a library that does not say), what
/// the file system holding `path` shows (full, or "an I/O error").
std::string writeFailureReason(const std::string& path, int errnum);

/// Removes what writeAtomically leaves when a run is killed mid-write: files "NAME.EXT.tmp" in
/// `directory` and below, EXT one of the output formats (vtu, vts, pvd, json, csv, h5,
/// fingerprint); other files are left alone. Returns how many it removed.
int removeStaleTemporaries(const std::string& directory);

}  // namespace flexehd::fem
