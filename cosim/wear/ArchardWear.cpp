// ArchardWear: the cycle's wear-rate maps of skirt and liner (docs/coupling.md §7).
#include "cosim/wear/ArchardWear.hpp"

#include <algorithm>
#include <cmath>

namespace flexehd::cosim {

ArchardWear::ArchardWear(const lube::FilmGrid& grid, double kPiston, double kLiner, double zLow, double zHigh)
    : grid_(grid), kPiston_(kPiston), kLiner_(kLiner), zLow_(zLow),
      cell_(grid.length() / (grid.nAxial() - 1)),
      cells_(std::max(1, static_cast<int>(std::ceil((zHigh - zLow) / cell_)))) {
    pistonSum_ = pistonRate_ = Eigen::VectorXd::Zero(grid.size());
    linerSum_ = linerRate_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(cells_) * grid.nTheta());
}

void ArchardWear::add(const Eigen::VectorXd& pc, double slidingSpeed, double linerOffset, double dt) {
    const lube::FilmGrid& g = grid_;
    const double u = std::abs(slidingSpeed);
    for (int k = 0; k < g.size(); ++k)
        if (g.kind(k) != lube::NodeKind::Void) pistonSum_[k] += kPiston_ * pc[k] * u * dt;
    // The liner cells the skirt covers: p_c at their piston-frame z, linear between the rows.
    const int nz = g.nAxial(), nt = g.nTheta();
    int i = 0;
    for (int c = 0; c < cells_; ++c) {
        const double z = linerCellZ(c) - linerOffset;
        if (z < g.z(0) || z > g.z(nz - 1)) continue;
        while (i + 2 < nz && g.z(i + 1) < z) ++i;
        const double w = (z - g.z(i)) / (g.z(i + 1) - g.z(i));
        for (int j = 0; j < nt; ++j) {
            const int a = g.index(i, j), b = g.index(i + 1, j);
            if (g.kind(a) == lube::NodeKind::Void || g.kind(b) == lube::NodeKind::Void) continue;
            linerSum_[static_cast<Eigen::Index>(c) * nt + j] += kLiner_ * ((1.0 - w) * pc[a] + w * pc[b]) * u * dt;
        }
    }
    time_ += dt;
}

void ArchardWear::finishCycle() {
    if (!(time_ > 0.0)) return;
    pistonRate_ = pistonSum_ / time_;
    linerRate_ = linerSum_ / time_;
    pistonSum_.setZero();
    linerSum_.setZero();
    time_ = 0.0;
    finished_ = true;
}

}  // namespace flexehd::cosim
