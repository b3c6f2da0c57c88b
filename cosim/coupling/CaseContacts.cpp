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

}  // namespace

std::vector<std::unique_ptr<FilmContact>> caseContacts(const EngineCase& c, const CaseBodies& bodies,
                                                       const std::function<double(double)>& linerOffset) {
    std::vector<std::unique_ptr<FilmContact>> contacts;
    auto skirt = std::make_unique<SkirtContact>(c, bodies, linerOffset);
    const std::optional<OilControlRingSpec>& ring = c.lubricant.supply.oilControlRing;
    std::unique_ptr<FilmContact> band =
        ring && skirt->linerFootprint() ? oilControlRing(*ring, *skirt, linerOffset) : nullptr;
    contacts.push_back(std::move(skirt));
    if (band) contacts.push_back(std::move(band));
    // The ring pack, top ring first (the cylinder's pressure above and behind it).
    for (std::size_t i = 0; i < c.rings.size(); ++i) {
        try {
            contacts.push_back(std::make_unique<RingContact>(c, c.rings[i], i == 0));
        } catch (const std::invalid_argument& e) {
            throw std::runtime_error(fmt::format("{}: rings[{}]: {}", c.path, i, e.what()));
        }
    }
    return contacts;
}

}  // namespace flexehd::cosim
