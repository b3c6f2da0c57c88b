#pragma once
// LinerCovers: the bands of the liner the film contacts cover at one instant (docs/coupling.md
// §6, "The liner's oil layer and its covers"). Under a cover the oil is the contact's film; the
// liner's oil layer is what lies outside every cover. Bands given in any order and overlapping
// are merged into disjoint ones.
#include <vector>

namespace flexehd::cosim {

/// A liner-frame z interval a contact covers (m, low ≤ high).
struct LinerCover {
    double low = 0.0, high = 0.0;
};

class LinerCovers {
public:
    LinerCovers() = default;
    explicit LinerCovers(std::vector<LinerCover> bands);

    /// The length (m) of [a, b] under the covers (a ≤ b).
    double covered(double a, double b) const;
    /// The disjoint bands, ascending in z.
    const std::vector<LinerCover>& bands() const { return bands_; }

private:
    std::vector<LinerCover> bands_;
};

}  // namespace flexehd::cosim
