// EdgeTrade: a cover's edges and the liner's oil layer over a step (docs/coupling.md §6).
#include "cosim/oil/EdgeTrade.hpp"

#include <algorithm>

namespace flexehd::cosim {

void tradeAtEdges(LinerOilExchange& ex, double before, double after, const std::array<double, 2>& edges,
                  const std::vector<double>& width, const Eigen::VectorXd& inflowLow, const Eigen::VectorXd& inflowHigh) {
    double shortfall = 0.0;
    for (int e = 0; e < 2; ++e) {
        const int out = e == 0 ? -1 : 1;
        const double a = before + edges[static_cast<std::size_t>(e)], b = after + edges[static_cast<std::size_t>(e)];
        const double lo = std::min(a, b), hi = std::max(a, b);
        const bool advancing = (b - a) * out > 0.0;
        const Eigen::VectorXd& q = e == 0 ? inflowLow : inflowHigh;
        for (int j = 0; j < static_cast<int>(width.size()); ++j) {
            if (!(width[static_cast<std::size_t>(j)] > 0.0)) continue;
            if (advancing) {  // what it covered, less what the film took in: the bank in front
                const double bank = ex.was.volume(j, lo, hi, ex.before) - q[j] * ex.dt;
                shortfall += ex.next.addOutside(j, b, out, bank, ex.after);
            } else {  // the outflow, on the strip it uncovered (a net inflow leaves it none)
                const double left = -q[j] * ex.dt;
                if (hi > lo) ex.next.deposit(j, lo, hi, std::max(left, 0.0), ex.before);
                if (!(hi > lo) || left < 0.0) shortfall += ex.next.addOutside(j, b, out, left, ex.after);
            }
        }
    }
    ex.shortfall += shortfall;
}

}  // namespace flexehd::cosim
