#pragma once
// ArchardWear: Archard's wear law on the skirt and the liner (docs/coupling.md §7): the wear depth
// rate of a surface is k p_c |u| (k the surface's wear coefficient in m²/N, p_c the contact
// pressure — asperities and hard contact —, u the sliding speed), accumulated over a cycle into
// maps of the mean rate: on the skirt's film grid, and on the liner over its z (cells of the
// grid's axial spacing, liner frame) and the grid's θ columns, where a liner point wears while
// the skirt covers it (p_c interpolated between the grid rows at its piston-frame z).
#include "lube/FilmGrid.hpp"

#include <Eigen/Core>

namespace flexehd::cosim {

class ArchardWear {
public:
    /// kPiston, kLiner: wear coefficients (m²/N); the liner cells cover [zLow, zHigh] (liner frame, m).
    ArchardWear(const lube::FilmGrid& grid, double kPiston, double kLiner, double zLow, double zHigh);

    /// One accepted step of length dt (s): contact pressure per grid node (Pa), sliding speed
    /// (m/s) and the liner offset (liner-frame z of the grid's origin, m).
    void add(const Eigen::VectorXd& contactPressure, double slidingSpeed, double linerOffset, double dt);
    /// Ends the cycle: its mean rates become the maps; the next add starts a new cycle.
    void finishCycle();

    /// Mean wear depth rate of the last finished cycle (m/s): per grid node (0 off the skirt).
    const Eigen::VectorXd& pistonRate() const { return pistonRate_; }
    /// ... and per liner cell and grid column, index cell × nθ + column.
    const Eigen::VectorXd& linerRate() const { return linerRate_; }
    int linerCells() const { return cells_; }
    double linerCellZ(int c) const { return zLow_ + (c + 0.5) * cell_; }
    bool finished() const { return finished_; }

private:
    const lube::FilmGrid& grid_;
    double kPiston_, kLiner_, zLow_, cell_;
    int cells_;
    Eigen::VectorXd pistonSum_, linerSum_, pistonRate_, linerRate_;  // ∫ rate dt; mean rates
    double time_ = 0.0;
    bool finished_ = false;
};

}  // namespace flexehd::cosim
