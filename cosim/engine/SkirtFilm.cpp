#include "cosim/engine/SkirtFilm.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace flexehd::cosim {

double profileDrop(const std::vector<ProfilePoint>& t, double z) {
    if (t.empty()) return 0.0;
    if (z <= t.front().z) return t.front().drop;
    if (z >= t.back().z) return t.back().drop;
    const auto it = std::upper_bound(t.begin(), t.end(), z, [](double v, const ProfilePoint& p) { return v < p.z; });
    const ProfilePoint& b = *it;
    const ProfilePoint& a = *(it - 1);
    const double s = (z - a.z) / (b.z - a.z);
    return a.drop + s * (b.drop - a.drop);
}

namespace {
lube::FilmGrid makeGrid(const EngineSpec& e, const PistonSpec& p, const GridSpec& g) {
    if (g.axialNodes < 3 || g.circumferentialNodes < 8)
        throw std::invalid_argument("skirt film grid: need at least 3 axial x 8 circumferential nodes, got " +
                                    std::to_string(g.axialNodes) + " x " + std::to_string(g.circumferentialNodes));
    if (!(p.skirtTop > p.skirtBottom))
        throw std::invalid_argument("skirt film grid: skirt top must lie above the skirt bottom");
    return lube::FilmGrid::fullCircumference(0.5 * e.bore, lube::FilmGrid::uniform(p.skirtBottom, p.skirtTop, g.axialNodes),
                                             g.circumferentialNodes, 0.0);
}
}  // namespace

SkirtFilm::SkirtFilm(const EngineSpec& e, const PistonSpec& p, const GridSpec& g) : grid_(makeGrid(e, p, g)) {
    const int n = grid_.size();
    h0_.resize(n);
    z_.resize(n);
    cos_.resize(n);
    for (int k = 0; k < n; ++k) {
        const double th = grid_.theta(grid_.thetaIndex(k));
        const double z = grid_.z(grid_.axialIndex(k));
        z_[k] = z;
        cos_[k] = std::cos(th);
        h0_[k] = p.clearance + profileDrop(p.profile, z) + p.ovality * 0.5 * (1.0 - std::cos(2.0 * th));
    }
    // The two panels, centred on θ = 0 and π, at their true edges (docs/lube.md §1).
    const double pi = std::numbers::pi, a = p.skirtHalfAngle;
    if (a < 0.5 * pi) grid_.restrictToArcs({{-a, a}, {pi - a, pi + a}});
    const int film = grid_.filmNodeCount();
    if (film == 0) throw std::invalid_argument("skirt film grid: no node lies on a skirt panel");
}

void SkirtFilm::rigidThickness(double e, double beta, Eigen::VectorXd& h) const {
    h = h0_.array() - (e + z_.array() * beta) * cos_.array();
}

}  // namespace flexehd::cosim
