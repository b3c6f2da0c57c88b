// EngineOrderSpectrum: per-bin power over engine orders, order lines and the strongest (header).
#include "acoustics/EngineOrderSpectrum.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "acoustics/InputChecks.hpp"

namespace flexehd::acoustics {

EngineOrderSpectrum::EngineOrderSpectrum(const Eigen::VectorXd& frequency_hz, const Eigen::VectorXd& power,
                                         double crankSpeed_rpm, double orderStep) {
    requirePositiveFinite("crankSpeed_rpm", crankSpeed_rpm, "crank speed in rpm");
    requirePositiveFinite("orderStep", orderStep, "order step");
    requireAtLeast("frequency_hz size", frequency_hz.size(), 2, "bins");
    if (power.size() != frequency_hz.size())
        throw std::invalid_argument("power: expected one value per frequency (" + std::to_string(frequency_hz.size()) +
                                    "), got " + std::to_string(power.size()));
    for (Eigen::Index k = 0; k < power.size(); ++k)
        if (!(std::isfinite(power(k)) && power(k) >= 0.0) || !std::isfinite(frequency_hz(k)))
            throw std::invalid_argument("power: expected finite values ≥ 0 at finite frequencies, got " +
                                        std::to_string(power(k)) + " at bin " + std::to_string(k));
    crankFrequency_hz_ = crankSpeed_rpm / 60.0;
    binOrder_ = frequency_hz / crankFrequency_hz_;
    const double binWidth = binOrder_(1) - binOrder_(0);
    if (binWidth > orderStep * (1.0 + 1e-12)) {
        std::ostringstream s;
        s << "orderStep: expected at least the spectrum's bin width in orders (" << binWidth
          << ", a longer record resolves finer orders), got " << orderStep;
        throw std::invalid_argument(s.str());
    }
    const int highest = static_cast<int>(std::floor(binOrder_(binOrder_.size() - 1) / orderStep + 0.5));
    for (int m = 1; m <= highest; ++m)
        lines_.push_back({m * orderStep, m * orderStep * crankFrequency_hz_, 0.0});
    for (Eigen::Index k = 0; k < binOrder_.size(); ++k) {
        const int m = static_cast<int>(std::floor(binOrder_(k) / orderStep + 0.5));
        if (m >= 1 && m <= highest) lines_[m - 1].power += power(k);
    }
}

std::vector<OrderLine> EngineOrderSpectrum::top(int count) const {
    std::vector<OrderLine> sorted = lines_;
    std::stable_sort(sorted.begin(), sorted.end(), [](const OrderLine& a, const OrderLine& b) { return a.power > b.power; });
    if (count < static_cast<int>(sorted.size())) sorted.resize(std::max(count, 0));
    return sorted;
}

}  // namespace flexehd::acoustics
