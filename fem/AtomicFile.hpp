#pragma once
// Crash-safe file output: content is written to "<path>.tmp" and renamed over `path`
// only once complete, so a killed run never leaves a truncated file behind.
#include <functional>
#include <string>

namespace flexehd::fem {

/// Calls `write(temporaryPath)`, then atomically renames the result to `path`.
/// Throws std::runtime_error naming the file if writing or renaming fails.
void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write);

/// writeAtomically of a text (the whole file).
void writeTextAtomically(const std::string& path, const std::string& text);

/// Removes what writeAtomically leaves when a run is killed mid-write: files "NAME.EXT.tmp" in
/// `directory` and below, EXT one of the output formats (vtu, vts, pvd, json, csv, h5,
/// fingerprint); other files are left alone. Returns how many it removed.
int removeStaleTemporaries(const std::string& directory);

}  // namespace flexehd::fem
