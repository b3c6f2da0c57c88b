#pragma once
// Hdf5Reader: datasets of doubles and scalar attributes of an HDF5 file, each failure an
// exception naming the file (as shown to the user) and the object; the reading side of
// Hdf5Writer (the run's acoustics record).
#include <memory>
#include <string>
#include <vector>

namespace flexehd::modal {

class Hdf5Reader {
public:
    /// Opens `path` read-only; messages say "<what> <path>: …". Throws std::runtime_error when the
    /// file is missing or not HDF5.
    Hdf5Reader(const std::string& path, std::string what);
    ~Hdf5Reader();
    Hdf5Reader(const Hdf5Reader&) = delete;
    Hdf5Reader& operator=(const Hdf5Reader&) = delete;

    [[noreturn]] void fail(const std::string& what) const;
    /// A dataset of doubles, row-major, with its dimensions; every value finite, else an error.
    std::vector<double> doubles(const std::string& name, std::vector<unsigned long long>& dims) const;
    std::string stringAttribute(const std::string& object, const std::string& name) const;
    double doubleAttribute(const std::string& object, const std::string& name) const;
    int intAttribute(const std::string& object, const std::string& name) const;

private:
    struct File;
    std::unique_ptr<File> file_;
    std::string what_, path_;
};

}  // namespace flexehd::modal
