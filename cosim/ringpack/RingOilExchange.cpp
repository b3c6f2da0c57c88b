// RingOilExchange: a ring's film and the liner's oil layer (docs/ring-pack.md, "The rings on the
// liner's oil layer").
#include "cosim/ringpack/RingOilExchange.hpp"

#include "cosim/oil/EdgeTrade.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>

namespace flexehd::cosim {

RingOilExchange::RingOilExchange(std::array<double, 2> edges, LinerFootprint footprint)
    : edges_(edges), footprint_(std::move(footprint)) {
    circumference_ = std::accumulate(footprint_.width.begin(), footprint_.width.end(), 0.0);
    if (!(edges_[1] > edges_[0]) || !(circumference_ > 0.0))
        throw std::invalid_argument("RingOilExchange: a cover of positive height on columns of positive width expected");
}

Eigen::VectorXd RingOilExchange::strip(const LinerOilState& oil, int edge, double before, double after) const {
    const double a = before + edges_[static_cast<std::size_t>(edge)], b = after + edges_[static_cast<std::size_t>(edge)];
    const int n = static_cast<int>(footprint_.width.size());
    Eigen::VectorXd v = Eigen::VectorXd::Zero(n);
    for (int j = 0; j < n; ++j) v[j] = oil.layer->volume(j, std::min(a, b), std::max(a, b), oil.covers);
    return v;
}

double RingOilExchange::supplyFilm(const LinerOilState& oil, double before, double after, double dt, double U) const {
    // The edge the liner comes from (U > 0: the liner moves up past the ring, the lower edge leads).
    const int lead = U >= 0.0 ? 0 : 1, out = lead == 0 ? -1 : 1;
    const bool advancing = (after - before) * out > 0.0;
    if (advancing && std::abs(U) > 0.0) return strip(oil, lead, before, after).sum() / (dt * std::abs(U) * circumference_);
    double film = 0.0;
    const double z = after + edges_[static_cast<std::size_t>(lead)] + out * 1e-9 * oil.layer->cellLength();
    for (std::size_t j = 0; j < footprint_.width.size(); ++j)
        film += footprint_.width[j] * oil.layer->thicknessAt(static_cast<int>(j), z);
    return film / circumference_;
}

void RingOilExchange::columnFlows(const LinerOilState& oil, double before, double after, double qLow, double qHigh,
                                  Eigen::VectorXd& low, Eigen::VectorXd& high) const {
    const Eigen::Map<const Eigen::VectorXd> width(footprint_.width.data(), static_cast<Eigen::Index>(footprint_.width.size()));
    for (int e = 0; e < 2; ++e) {
        const double q = (e == 0 ? qLow : qHigh) * circumference_;  // m³/s
        Eigen::VectorXd& f = e == 0 ? low : high;
        const int out = e == 0 ? -1 : 1;
        const bool advancing = (after - before) * out > 0.0;
        // In through the advancing edge: from each column as its strip held oil; else round the
        // bore alike.
        if (advancing && q > 0.0) {
            const Eigen::VectorXd v = strip(oil, e, before, after);
            if (v.sum() > 0.0) {
                f = q * v / v.sum();
                continue;
            }
        }
        f = q * width / circumference_;
    }
}

void RingOilExchange::exchange(LinerOilExchange& ex, double before, double after, const Eigen::VectorXd& inflowLow,
                               const Eigen::VectorXd& inflowHigh) const {
    tradeAtEdges(ex, before, after, edges_, footprint_.width, inflowLow, inflowHigh);
}

}  // namespace flexehd::cosim
