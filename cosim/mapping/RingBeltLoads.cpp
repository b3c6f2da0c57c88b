// RingBeltLoads: the ring pack's gas and ring forces on the flexible piston's ring belt.
#include "cosim/mapping/RingBeltLoads.hpp"

#include <algorithm>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "fem/ElasticityAssembler.hpp"

namespace flexehd::cosim {

namespace {

// Half the width of a flank's band (m): flank triangles lie at the flank's z, the root's and the
// lands' centroids a third of an element or more away.
constexpr double kFlankBand = 1e-5;
// Bounds that agree to this (m) name the same band (a pattern typed from the message's digits).
constexpr double kSameBound = 1e-9;

}  // namespace

std::vector<modal::PressurePattern> RingBeltLoads::patterns(const std::vector<RingSpec>& rings) {
    std::vector<modal::PressurePattern> p;
    if (rings.empty()) return p;
    p.push_back({"ring_lands", rings.front().grooveTop(), std::numeric_limits<double>::infinity()});
    for (std::size_t k = 0; k + 1 < rings.size(); ++k)
        p.push_back({"ring_lands", rings[k + 1].grooveTop(), rings[k].groove.lowerFlank});
    for (const RingSpec& r : rings) {
        const double low = r.groove.lowerFlank, high = r.grooveTop();
        p.push_back({"ring_grooves", low + kFlankBand, high - kFlankBand});
        p.push_back({"ring_grooves", low - kFlankBand, low + kFlankBand});
        p.push_back({"ring_grooves", high - kFlankBand, high + kFlankBand});
    }
    return p;
}

RingBeltLoads::RingBeltLoads(const modal::ReducedBody& body, const std::vector<RingSpec>& rings, double bore,
                             const std::string& file)
    : rings_(rings.size()), circumference_(std::numbers::pi * bore) {
    if (rings.empty()) throw std::invalid_argument("bodies.piston.loads: ring_pack needs a ring pack (rings)");
    for (const char* group : {"ring_lands", "ring_grooves"})
        if (!body.mesh.hasGroup(group) || body.mesh.group(group).dim != 2)
            throw std::invalid_argument(fmt::format(
                "bodies.piston.loads: ring_pack needs the piston's surface groups ring_lands and ring_grooves "
                "(meshes/piston.geo), but {} has no surface group '{}'",
                file, group));
    const std::vector<modal::PressurePattern> needed = patterns(rings);
    std::vector<modal::PressurePattern> given;
    for (const std::string& text : body.settings.pressurePatterns) given.push_back(modal::PressurePattern::parse(text));
    std::string missing;
    for (const modal::PressurePattern& p : needed)
        if (std::none_of(given.begin(), given.end(), [&](const auto& g) { return g.matches(p, kSameBound); }))
            missing += " --pressure-pattern " + p.text();
    if (!missing.empty())
        throw std::invalid_argument(fmt::format(
            "bodies.piston.loads: ring_pack needs the reduced body's static response to a uniform pressure on each "
            "land and groove part of the ring pack, but {} was reduced without some of them; reduce it again adding"
            "{} (docs/modal.md)",
            file, missing));
    const fem::ElasticityAssembler assembler(body.mesh);
    unit_.resize(body.numModes(), static_cast<Eigen::Index>(needed.size()));
    for (std::size_t k = 0; k < needed.size(); ++k) {
        const fem::BoundarySurface s = needed[k].surface(body.mesh);
        unit_.col(static_cast<Eigen::Index>(k)) = body.shapes.transpose() * assembler.pressureLoad(s, 1.0);
        if (k >= rings.size() && (k - rings.size()) % 3 != 0) area_.push_back(s.area());  // the flanks
    }
}

void RingBeltLoads::add(const std::vector<RingGas>& gas, Eigen::Ref<Eigen::VectorXd> f) const {
    if (gas.size() != rings_)
        throw std::logic_error(fmt::format("RingBeltLoads: gas round {} rings for a pack of {}", gas.size(), rings_));
    Eigen::VectorXd p(unit_.cols());
    p[0] = gas.front().above;  // the top land: the cylinder's
    for (std::size_t k = 0; k + 1 < rings_; ++k) p[static_cast<Eigen::Index>(k + 1)] = gas[k].below;
    for (std::size_t i = 0; i < rings_; ++i) {
        const RingGas& g = gas[i];
        const auto at = static_cast<Eigen::Index>(rings_ + 3 * i);
        const double flank = g.flankForce * circumference_;  // N on the ring, > 0 from its lower flank
        p[at] = g.behind;
        p[at + 1] = 0.5 * (g.behind + g.below) + std::max(flank, 0.0) / lowerFlankArea(i);
        p[at + 2] = 0.5 * (g.behind + g.above) + std::max(-flank, 0.0) / upperFlankArea(i);
    }
    f += unit_ * p;
}

}  // namespace flexehd::cosim
