#pragma once
// RingBeltLoads: the ring pack's loads on the flexible piston's ring belt (docs/coupling.md §2,
// "The ring pack's loads on the flexible piston"), each a uniform pressure on its part of the
// piston's surface groups `ring_lands` and `ring_grooves`, the parts cut out by the case's ring
// pack (modal::PressurePattern's bands of z):
//   - the top land at the cylinder's gas pressure, each land between two rings at its gas;
//   - each groove's root at the groove's gas (behind the ring);
//   - each groove flank at the mean of the groove's gas and that of the space beside the flank
//     (as the ring's side faces see it, docs/ring-pack.md "Ring lift in a run"), plus, on the
//     flank the ring sits on, the ring's flank force spread over the flank.
// Per part one modal vector Φᵀ F₁ (F₁ the consistent nodal forces of 1 Pa), computed once; each
// evaluation sums them with the step's pressures. The static response is exact where the basis
// holds each part's pattern; a body without them is refused, naming every `--pressure-pattern`
// option that makes them.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cosim/case/RingPackSpec.hpp"
#include "cosim/engine/RingGas.hpp"
#include "modal/PressurePattern.hpp"
#include "modal/ReducedBody.hpp"

namespace flexehd::cosim {

class RingBeltLoads {
public:
    /// The parts of the ring belt the pack's rings (top first) and bore (m) cut out; `file` names
    /// the reduced body in the messages. Throws std::invalid_argument for a body without the
    /// groups or the patterns.
    RingBeltLoads(const modal::ReducedBody& body, const std::vector<RingSpec>& rings, double bore,
                  const std::string& file);

    /// The patterns the pack needs, in the order of the parts: the top land, the lands between
    /// the rings, then per ring its groove's root, lower flank and upper flank.
    static std::vector<modal::PressurePattern> patterns(const std::vector<RingSpec>& rings);

    /// Adds the modal load (m) of the gas round each ring and its flank force (one entry per ring).
    void add(const std::vector<RingGas>& gas, Eigen::Ref<Eigen::VectorXd> f) const;

    /// m², the area of each ring's lower and upper flank on the mesh.
    double lowerFlankArea(std::size_t ring) const { return area_[2 * ring]; }
    double upperFlankArea(std::size_t ring) const { return area_[2 * ring + 1]; }

private:
    std::size_t rings_;
    double circumference_;
    Eigen::MatrixXd unit_;      // m × parts: Φᵀ F₁ per part
    std::vector<double> area_;  // the flanks' areas, per ring lower then upper
};

}  // namespace flexehd::cosim
