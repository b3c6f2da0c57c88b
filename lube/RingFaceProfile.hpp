#pragma once
// RingFaceProfile: the running face of a piston ring — its radial drop from the face's most
// prominent point over the axial position x across the face (x from the face's centre, positive
// towards the crown): a barrel parabola, drop = c (x − x_o)² / (b/2)² with crown height c, ring
// height b and the offset x_o of the parabola's vertex, or a table of (x, drop) interpolated
// linearly. The film thickness across the face is h(x) = h_min + drop(x) − min drop.
#include <utility>
#include <vector>

namespace flexehd::lube {

class RingFaceProfile {
public:
    /// Barrel face of height b (m) with crown height c (m, ≥ 0) and vertex offset x_o (m, |x_o| < b/2).
    static RingFaceProfile barrel(double height, double crownHeight, double offset = 0.0);
    /// Table of (x, drop) pairs (m), x strictly increasing, at least two rows; the face spans the
    /// table's x range.
    static RingFaceProfile table(std::vector<std::pair<double, double>> xDrop);

    /// Radial drop (m) at x (m, within the face), relative to the face's most prominent point.
    double drop(double x) const;
    double lower() const { return lower_; }  ///< the face's lower edge x (m)
    double upper() const { return upper_; }  ///< the face's upper edge x (m)
    /// Equivalent radius of curvature at the vertex of a barrel face (m): (b/2)² / (2c).
    double barrelRadius() const;

private:
    RingFaceProfile() = default;
    double lower_ = 0.0, upper_ = 0.0;
    double crown_ = 0.0, offset_ = 0.0;          // barrel
    std::vector<std::pair<double, double>> table_;  // table (empty: barrel)
    double tableMin_ = 0.0;
};

}  // namespace flexehd::lube
