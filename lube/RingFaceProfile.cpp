#include "lube/RingFaceProfile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace flexehd::lube {

RingFaceProfile RingFaceProfile::barrel(double height, double crownHeight, double offset) {
    if (!(height > 0.0) || !std::isfinite(height))
        throw std::invalid_argument("RingFaceProfile: the ring height must be positive, got " + std::to_string(height));
    if (!(crownHeight >= 0.0) || !std::isfinite(crownHeight))
        throw std::invalid_argument("RingFaceProfile: the crown height must be >= 0, got " + std::to_string(crownHeight));
    if (!(std::abs(offset) < 0.5 * height))
        throw std::invalid_argument("RingFaceProfile: the vertex offset must lie inside the face (|offset| < height/2), got " +
                                    std::to_string(offset));
    RingFaceProfile p;
    p.lower_ = -0.5 * height;
    p.upper_ = 0.5 * height;
    p.crown_ = crownHeight;
    p.offset_ = offset;
    return p;
}

RingFaceProfile RingFaceProfile::table(std::vector<std::pair<double, double>> xDrop) {
    if (xDrop.size() < 2) throw std::invalid_argument("RingFaceProfile: a face table needs at least two rows");
    for (std::size_t i = 0; i < xDrop.size(); ++i) {
        if (!std::isfinite(xDrop[i].first) || !std::isfinite(xDrop[i].second))
            throw std::invalid_argument("RingFaceProfile: face table row " + std::to_string(i + 1) + " is not finite");
        if (i > 0 && !(xDrop[i].first > xDrop[i - 1].first))
            throw std::invalid_argument("RingFaceProfile: face table x must increase strictly (row " +
                                        std::to_string(i + 1) + ")");
    }
    RingFaceProfile p;
    p.lower_ = xDrop.front().first;
    p.upper_ = xDrop.back().first;
    p.tableMin_ = std::numeric_limits<double>::infinity();
    for (const auto& r : xDrop) p.tableMin_ = std::min(p.tableMin_, r.second);
    p.table_ = std::move(xDrop);
    return p;
}

double RingFaceProfile::drop(double x) const {
    if (table_.empty()) {
        const double s = (x - offset_) / (0.5 * (upper_ - lower_));
        return crown_ * s * s;
    }
    if (x <= table_.front().first) return table_.front().second - tableMin_;
    if (x >= table_.back().first) return table_.back().second - tableMin_;
    const auto it = std::upper_bound(table_.begin(), table_.end(), x,
                                     [](double v, const std::pair<double, double>& r) { return v < r.first; });
    const auto& [x1, d1] = *it;
    const auto& [x0, d0] = *(it - 1);
    return d0 + (d1 - d0) * (x - x0) / (x1 - x0) - tableMin_;
}

double RingFaceProfile::barrelRadius() const {
    if (!table_.empty()) throw std::logic_error("RingFaceProfile::barrelRadius: a table face has no barrel radius");
    const double half = 0.5 * (upper_ - lower_);
    return crown_ > 0.0 ? half * half / (2.0 * crown_) : std::numeric_limits<double>::infinity();
}

}  // namespace flexehd::lube
