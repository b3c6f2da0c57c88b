#pragma once
// A ParaView collection (.pvd): a list of (time, file) datasets that ParaView opens as
// one time series. Used for mode shapes (time = mode number, for Animate Modes) and for
// results over the engine cycle.
#include <string>
#include <vector>

namespace flexehd::cosim {

class PvdCollection {
public:
    void add(double time, const std::string& relativeFile) { entries_.push_back({time, relativeFile}); }
    /// Writes the collection atomically (a killed run leaves the previous valid file).
    void write(const std::string& path) const;

private:
    struct Entry {
        double time;
        std::string file;
    };
    std::vector<Entry> entries_;
};

}  // namespace flexehd::cosim
