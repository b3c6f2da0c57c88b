#include "cosim/contact/CaseContacts.hpp"

#include "cosim/contact/OilControlRingBand.hpp"
#include "cosim/contact/SkirtContact.hpp"

#include <algorithm>
#include <limits>

namespace flexehd::cosim {
namespace {

// The oil-control ring's band on the skirt's oil layer: the layer's columns, and the liner's z
// range its edges sweep over a revolution.
std::unique_ptr<FilmContact> oilControlRing(const OilControlRingSpec& ring, const SkirtContact& skirt,
                                            const std::function<double(double)>& linerOffset) {
    const std::optional<LinerFootprint> columns = skirt.linerFootprint();
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int k = 0; k <= 1440; ++k) {
        lo = std::min(lo, linerOffset(0.25 * k) + ring.bottom);
        hi = std::max(hi, linerOffset(0.25 * k) + ring.top);
    }
    return std::make_unique<OilControlRingBand>(ring, *columns, lo, hi);
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
    return contacts;
}

}  // namespace flexehd::cosim
