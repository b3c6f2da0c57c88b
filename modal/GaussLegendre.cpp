#include "modal/GaussLegendre.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace flexehd::modal {

QuadratureRule gaussLegendre(int n) {
    if (n < 1) throw std::invalid_argument("Gauss-Legendre rule of " + std::to_string(n) + " points: needs >= 1");
    QuadratureRule rule;
    rule.nodes.assign(static_cast<std::size_t>(n), 0.0);
    rule.weights.assign(static_cast<std::size_t>(n), 0.0);
    for (int i = 0; i < n; ++i) {
        double t = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));  // A&S 22.16.6's first guess
        double dp = 1.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = t;  // P_{k−1}, P_k by the three-term recurrence (A&S 22.7.10)
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (t * p1 - p0) / (t * t - 1.0);
            const double step = p1 / dp;
            t -= step;
            if (std::abs(step) < 1e-16) break;
        }
        const auto k = static_cast<std::size_t>(i);
        rule.nodes[k] = 0.5 * (1.0 - t);
        rule.weights[k] = 1.0 / ((1.0 - t * t) * dp * dp);  // half of A&S 25.4.29's weight, for [0, 1]
    }
    return rule;
}

}  // namespace flexehd::modal
