#include "lube/MinimumFilmRegion.hpp"

namespace flexehd::lube {

MinimumFilmSpan minimumFilmSpan(const FilmGrid& g, const Eigen::VectorXd& h, double band) {
    MinimumFilmSpan s;
    for (int k = 0; k < g.size(); ++k)
        if (g.kind(k) != NodeKind::Void && (s.node < 0 || h[k] < s.minFilm)) {
            s.node = k;
            s.minFilm = h[k];
        }
    if (s.node < 0) return s;
    const double limit = s.minFilm + band;
    const int nt = g.nTheta(), nz = g.nAxial(), i0 = s.node / nt, j0 = s.node % nt;
    const auto inside = [&](int i, int j) { return g.kind(g.index(i, j)) != NodeKind::Void && h[g.index(i, j)] <= limit; };
    // Along the row: both ways from the thinnest node (around a periodic grid, at most once round).
    s.circumferential = 1;
    for (int d : {-1, 1})
        for (int step = 1; step < nt && s.circumferential < nt; ++step) {
            int j = j0 + d * step;
            if (g.periodic())
                j = (j % nt + nt) % nt;
            else if (j < 0 || j >= nt)
                break;
            if (!inside(i0, j)) break;
            ++s.circumferential;
        }
    const auto edge = [&](int i) { return i < 0 || i >= nz || g.kind(g.index(i, j0)) == NodeKind::Void; };
    s.atAxialEdge = edge(i0 - 1) || edge(i0 + 1);
    s.axial = 1;
    for (int d : {-1, 1})
        for (int i = i0 + d; i >= 0 && i < nz && inside(i, j0); i += d) ++s.axial;
    return s;
}

}  // namespace flexehd::lube
