#pragma once
// LinerOilLayer: the oil layer the liner carries outside the film contacts, a state over the
// liner's z and the layer's θ columns (docs/coupling.md §6).
//
// Cells of length Δ along the liner-frame z (uniform from zLow), one row per column j of width
// w_j (m, the column's arc R Δθ_j; 0 for a column no contact reaches). A cell holds the thickness
// t of the layer on its part outside the covers (LinerCovers: the bands the contacts cover); the
// oil under a cover is that contact's film. So the layer's volume is Σ t u w with u the
// uncovered length of the cell. Every operation conserves volume: what an edge covers is handed
// to the caller, what it uncovers is filled with what the caller deposits, a bank is put just
// outside an edge.
#include "cosim/oil/LinerCovers.hpp"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace flexehd::cosim {

class LinerOilLayer {
public:
    /// Cells of length `cell` covering [zLow, zHigh] (m); `width` per column (m, ≥ 0).
    LinerOilLayer(double zLow, double zHigh, double cell, std::vector<double> width);

    /// Sets the layer to thickness(z) (m, at the cell centres) on every column.
    void fill(const std::function<double(double)>& thickness);

    /// Volume (m³) of the layer of column j on [a, b] outside the covers (a ≤ b).
    double volume(int j, double a, double b, const LinerCovers& cover) const;
    /// Volume (m³) of the whole layer outside the covers.
    double volume(const LinerCovers& cover) const;
    /// Thickness (m) of column j's layer at z (the cell's; 0 outside the cells).
    double thicknessAt(int j, double z) const;

    /// Spreads the volume v (m³) evenly over [a, b] of column j, an interval the cover `before`
    /// had on it and the present covers leave free (the trailing edge's deposit).
    void deposit(int j, double a, double b, double v, const LinerCovers& before);
    /// Adds the volume v (m³, may be < 0) to the layer of column j just outside the edge at z on
    /// the side `outward` (−1 below, +1 above), the covers being `cover` (a bank in front of an
    /// edge). A negative v takes oil from there and further out, down to a dry liner; returns
    /// the volume that could not be taken (≥ 0, 0 when the layer had enough).
    double addOutside(int j, double z, int outward, double v, const LinerCovers& cover);
    /// Restores the layer outside the covers to thickness(z) on cells whose centre lies below
    /// zBelow (liner-frame z); returns the volume added (m³, < 0: removed).
    double restore(double zBelow, const std::function<double(double)>& thickness, const LinerCovers& cover);

    int cells() const { return nCells_; }
    int columns() const { return static_cast<int>(width_.size()); }
    double zLow() const { return zLow_; }
    double cellLength() const { return cell_; }
    double width(int j) const { return width_[static_cast<std::size_t>(j)]; }
    /// The layer's volume per liner area (m) of each cell, the covered parts counting as dry:
    /// cells × columns, column-major by cell (index c × columns + j).
    Eigen::VectorXd meanThickness(const LinerCovers& cover) const;

private:
    double uncovered(int c, int j, const LinerCovers& cover) const;
    double& t(int c, int j) { return t_[static_cast<std::size_t>(c) * width_.size() + static_cast<std::size_t>(j)]; }
    double t(int c, int j) const { return t_[static_cast<std::size_t>(c) * width_.size() + static_cast<std::size_t>(j)]; }
    int cellOf(double z) const;

    double zLow_, cell_;
    int nCells_;
    std::vector<double> width_;
    std::vector<double> t_;
};

}  // namespace flexehd::cosim
