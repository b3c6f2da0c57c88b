#pragma once
// Hdf5Writer: a new HDF5 file of groups, attributes and datasets in little-endian IEEE doubles,
// unsigned bytes and 32-bit integers, each failure an exception naming the file (as shown to the
// user) and the object; the files of `flexehd thermal` and the run's acoustics record.
#include <memory>
#include <string>
#include <vector>

namespace flexehd::modal {

class Hdf5Writer {
public:
    /// Creates (truncates) `path`; messages say "<what> <shownAs>: …" (e.g. "thermal file out/t.h5").
    Hdf5Writer(const std::string& path, std::string what, std::string shownAs);
    ~Hdf5Writer();
    Hdf5Writer(const Hdf5Writer&) = delete;
    Hdf5Writer& operator=(const Hdf5Writer&) = delete;

    [[noreturn]] void fail(const std::string& what) const;
    void group(const std::string& name);
    void stringAttribute(const std::string& object, const std::string& name, const std::string& value);
    void doubleAttribute(const std::string& object, const std::string& name, double value);
    void intAttribute(const std::string& object, const std::string& name, int value);
    /// Row-major data of the given dimensions.
    void doubles(const std::string& name, const std::vector<unsigned long long>& dims, const double* data);
    void bytes(const std::string& name, const std::vector<unsigned long long>& dims, const unsigned char* data);
    void ints(const std::string& name, const std::vector<unsigned long long>& dims, const int* data);
    /// Closes the file (flushes it, which can fail).
    void close();

private:
    struct File;
    std::unique_ptr<File> file_;
    std::string what_, shown_;
};

}  // namespace flexehd::modal
