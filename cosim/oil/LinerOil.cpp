// LinerOil: the master's liner oil layer, its start and its step (docs/coupling.md §6).
#include "cosim/oil/LinerOil.hpp"

#include "cosim/oil/OilSupply.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace flexehd::cosim {

namespace {

constexpr int kMarginCells = 8;  // liner cells beyond the contacts' reach on either side

}  // namespace

LinerOil::LinerOil(const OilSupplySpec& supply, const std::vector<LinerFootprint>& footprints, double zReplenish)
    : supply_(supply), zLow_(0.0), zHigh_(0.0), cell_(0.0), zReplenish_(zReplenish) {
    if (footprints.empty()) throw std::invalid_argument("LinerOil: no contact runs on the liner's oil layer");
    const LinerFootprint& first = footprints.front();
    zLow_ = first.zLow;
    zHigh_ = first.zHigh;
    cell_ = first.cell;
    width_ = first.width;
    for (const LinerFootprint& f : footprints) {
        if (f.width.size() != width_.size())
            throw std::invalid_argument("LinerOil: the contacts on the liner's oil layer have " +
                                        std::to_string(width_.size()) + " and " + std::to_string(f.width.size()) +
                                        " columns; they must share the layer's columns");
        for (std::size_t j = 0; j < width_.size(); ++j) width_[j] = std::max(width_[j], f.width[j]);
        zLow_ = std::min(zLow_, f.zLow);
        zHigh_ = std::max(zHigh_, f.zHigh);
        cell_ = std::min(cell_, f.cell);
    }
}

LinerOilState LinerOil::initial(const LinerCovers& covers) const {
    auto layer = std::make_shared<LinerOilLayer>(zLow_ - kMarginCells * cell_, zHigh_ + kMarginCells * cell_, cell_, width_);
    layer->fill([this](double z) { return supplyLayerThickness(supply_, z); });
    LinerOilState s;
    s.layer = std::move(layer);
    s.covers = covers;
    return s;
}

LinerOilState LinerOil::advance(const LinerOilState& now, const LinerCovers& after, double dt,
                                const std::function<void(LinerOilExchange&)>& exchange) const {
    auto next = std::make_shared<LinerOilLayer>(*now.layer);
    LinerOilExchange ex{*now.layer, *next, now.covers, after, dt};
    exchange(ex);
    LinerOilState s;
    s.covers = after;
    s.shortfall = now.shortfall + ex.shortfall;
    s.replenished = now.replenished;
    if (std::isfinite(zReplenish_))
        s.replenished += next->restore(zReplenish_, [this](double z) { return supplyLayerThickness(supply_, z); }, after);
    s.layer = std::move(next);
    return s;
}

}  // namespace flexehd::cosim
