#pragma once
// LinerCovers: the bands of the liner the film contacts cover at one instant (docs/coupling.md
// §6, "The liner's oil layer and its covers"). Under a cover the oil is the contact's film; the
// liner's oil layer is what lies outside every cover. A band covers the θ columns its contact
// reaches (the skirt its panels, a ring the whole bore); on each column the bands over it, given
// in any order and overlapping, count as their union.
#include <memory>
#include <vector>

namespace flexehd::cosim {

/// A liner-frame z interval a contact covers (m, low ≤ high) on the θ columns `columns` flags
/// (null: every column).
struct LinerCover {
    double low = 0.0, high = 0.0;
    std::shared_ptr<const std::vector<char>> columns;
    bool covers(int j) const { return !columns || (*columns)[static_cast<std::size_t>(j)]; }
};

class LinerCovers {
public:
    LinerCovers() = default;
    explicit LinerCovers(std::vector<LinerCover> bands);

    /// The length (m) of [a, b] under the covers on column j (a ≤ b).
    double covered(int j, double a, double b) const;
    /// The bands, ascending in their lower edge.
    const std::vector<LinerCover>& bands() const { return bands_; }

private:
    std::vector<LinerCover> bands_;
};

}  // namespace flexehd::cosim
