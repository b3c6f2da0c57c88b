#include "lube/ColouredDifference.hpp"

namespace flexehd::lube {

SparseMatrix colouredThicknessDerivative(const FilmGrid& g, const GridColouring& colouring, const FilmState& film,
                                         const std::vector<int>& rowNodes, const Eigen::VectorXd& w0,
                                         const RowResidual& residual) {
    const int n = g.size();
    const int rows = int(rowNodes.size());
    std::vector<Eigen::Triplet<double>> trip;
    trip.reserve(static_cast<std::size_t>(5 * rows));
    FilmState fc = film;
    for (int c = 0; c < colouring.colours; ++c) {
        fc.h = film.h;
        bool any = false;
        for (int k = 0; k < n; ++k)
            if (colouring.colour[static_cast<std::size_t>(k)] == c && g.kind(k) != NodeKind::Void) {
                fc.h[k] *= 1.0 + 1e-7;
                any = true;
            }
        if (!any) continue;
        const Eigen::VectorXd wc = residual(fc);
        for (int i = 0; i < rows; ++i) {
            auto add = [&](int a) {
                if (colouring.colour[static_cast<std::size_t>(a)] != c || g.kind(a) == NodeKind::Void) return;
                const double v = (wc[i] - w0[i]) / (fc.h[a] - film.h[a]);
                if (v != 0.0) trip.emplace_back(i, a, v);
            };
            const int r = rowNodes[static_cast<std::size_t>(i)];
            add(r);
            forEachNeighbour(g, r, add);
        }
    }
    SparseMatrix d(rows, n);
    d.setFromTriplets(trip.begin(), trip.end());
    return d;
}

}  // namespace flexehd::lube
