#include "cosim/coupling/CaseContacts.hpp"

#include "cosim/contact/LinerOffsetRange.hpp"
#include "cosim/contact/OilControlRingBand.hpp"
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/ringpack/RingContact.hpp"

#include <stdexcept>

#include <fmt/format.h>


namespace flexehd::cosim {
namespace {

// The oil-control ring's band on the skirt's oil layer: the layer's columns, and the liner's z
// range its edges sweep over a revolution.
std::unique_ptr<FilmContact> oilControlRing(const OilControlRingSpec& ring, const SkirtContact& skirt,
                                            const std::function<double(double)>& linerOffset) {
    const LinerOffsetRange r = linerOffsetRange(linerOffset);
    return std::make_unique<OilControlRingBand>(ring, *skirt.linerFootprint(), r.low + ring.bottom, r.high + ring.top);
}

// The rings' columns on the skirt's oil layer: the skirt grid's θ columns, each its whole arc
// (a ring runs round the bore), over the liner offsets of a revolution.
LinerFootprint ringColumns(const SkirtContact& skirt, const std::function<double(double)>& linerOffset) {
    const lube::FilmGrid& g = skirt.grid();
    const LinerOffsetRange r = linerOffsetRange(linerOffset);
    LinerFootprint f;
    f.zLow = r.low;
    f.zHigh = r.high;
    for (int j = 0; j < g.nTheta(); ++j) f.width.push_back(g.radius() * g.angularWidth(j));
    return f;
}

}  // namespace

std::vector<std::unique_ptr<FilmContact>> caseContacts(const EngineCase& c, const CaseBodies& bodies,
                                                       const std::function<double(double)>& linerOffset) {
    std::vector<std::unique_ptr<FilmContact>> contacts;
    auto skirt = std::make_unique<SkirtContact>(c, bodies, linerOffset);
    const std::optional<OilControlRingSpec>& ring = c.lubricant.supply.oilControlRing;
    const bool layer = skirt->linerFootprint().has_value();
    for (const RingSpec& r : c.rings)
        if (layer && ring && r.kind == RingKind::OilControl)
            throw std::runtime_error(fmt::format(
                "{}: lubricant.supply.oil_control_ring and the ring pack's oil-control ring '{}' both scrape the "
                "liner's oil layer: remove lubricant.supply.oil_control_ring (the ring pack's ring leaves what its "
                "lands' films carry)",
                c.path, r.name));
    std::unique_ptr<FilmContact> band = ring && layer ? oilControlRing(*ring, *skirt, linerOffset) : nullptr;
    const std::optional<LinerFootprint> columns =
        layer ? std::optional<LinerFootprint>(ringColumns(*skirt, linerOffset)) : std::nullopt;
    contacts.push_back(std::move(skirt));
    if (band) contacts.push_back(std::move(band));
    const LinerOffsetRange offsets = linerOffsetRange(linerOffset);
    // The ring pack, top ring first (the cylinder's pressure above and behind it).
    for (std::size_t i = 0; i < c.rings.size(); ++i) {
        try {
            contacts.push_back(std::make_unique<RingContact>(c, c.rings[i], i == 0, 0, columns ? &*columns : nullptr,
                                                             bodies.liner, offsets.low, offsets.high));
        } catch (const std::invalid_argument& e) {
            throw std::runtime_error(fmt::format("{}: rings[{}]: {}", c.path, i, e.what()));
        }
    }
    return contacts;
}

}  // namespace flexehd::cosim
