#pragma once
// RingOilExchange: an axisymmetric ring film and the liner's oil layer over a step
// (docs/ring-pack.md, "The rings on the liner's oil layer"). The ring covers the band of its face
// round the whole bore; its film is one for every θ column:
//  * its leading face meets the layer its advancing edge covers; as carried at the sliding speed
//    U that is a film of t = V / (Δt |U| πD) (V the strip's volume over the columns), which the
//    film takes in up to its inlet's capacity;
//  * its flows per unit circumference through each edge are shared out over the columns: what
//    comes in by the oil each column's strip held, what goes out by the column's width (the film
//    leaves the same layer all round);
//  * the trade itself is every cover's (EdgeTrade): the rest of the strip banked in front of the
//    advancing edge, the outflow laid on the strip the retreating edge uncovers.
#include "cosim/oil/LinerOil.hpp"

#include <Eigen/Core>

#include <array>

namespace flexehd::cosim {

class RingOilExchange {
public:
    /// edges: piston-frame z of the cover's lower and upper edge (m); footprint: the liner-frame z
    /// range they sweep over a revolution, the cell, and every θ column's width (m, round the bore).
    RingOilExchange(std::array<double, 2> edges, LinerFootprint footprint);

    const LinerFootprint& footprint() const { return footprint_; }
    LinerCover cover(double linerOffset) const { return {linerOffset + edges_[0], linerOffset + edges_[1]}; }
    /// The film (m) the layer brings to the leading face over the step from liner offset `before`
    /// to `after` (m) of dt (s) at sliding speed U (m/s, the liner relative to the ring, + towards
    /// the crown); without an advancing edge (or U = 0) the layer's mean thickness just in front
    /// of the face the liner moves towards.
    double supplyFilm(const LinerOilState& oil, double before, double after, double dt, double U) const;
    /// The flows qLow, qHigh (m²/s per unit circumference, + into the film) through the lower and
    /// upper edge as flows per column (m³/s) for the step from `before` to `after`.
    void columnFlows(const LinerOilState& oil, double before, double after, double qLow, double qHigh,
                     Eigen::VectorXd& low, Eigen::VectorXd& high) const;
    /// The trade of the accepted step from `before` to `after` with the flows per column.
    void exchange(LinerOilExchange& ex, double before, double after, const Eigen::VectorXd& inflowLow,
                  const Eigen::VectorXd& inflowHigh) const;
    /// πD: the columns' widths summed (m).
    double circumference() const { return circumference_; }

private:
    /// The oil over the strip an edge sweeps in the step, per column (m³).
    Eigen::VectorXd strip(const LinerOilState& oil, int edge, double before, double after) const;

    std::array<double, 2> edges_;
    LinerFootprint footprint_;
    double circumference_ = 0.0;
};

}  // namespace flexehd::cosim
