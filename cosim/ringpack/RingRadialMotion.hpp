#pragma once
// RingRadialMotion: a ring's radial equilibrium, its minimum film as the unknown of each step
// (docs/ring-pack.md). Per unit circumference, the ring's tension and the gas pressure behind it
// press the face against the liner; the film and the asperities push back:
//
//   T + p_back b = W_film(h_min, ḣ_min) + W_asperity(h_min),
//
// with the ring's radial motion as the film's squeeze (its inertia left out), ḣ_min by backward
// Euler from the last step. The right-hand side falls as h_min grows at a given h_min,n, so each
// step's h_min is bracketed and found by bisection with secant steps (the film of each trial by
// lube::RingFilm, the asperity load by the Greenwood–Tripp law over its nodes).
#include <optional>

#include "lube/GreenwoodTripp.hpp"
#include "lube/RingFilm.hpp"

namespace flexehd::cosim {

struct RingRadialStep {
    double minimumGap = 0.0;    ///< h_min at the step's end (m)
    double squeezeRate = 0.0;   ///< (h_min − h_min,n)/Δt (m/s)
    double filmLoad = 0.0;      ///< N/m
    double asperityLoad = 0.0;  ///< N/m
    lube::RingFilmResult film;
};

class RingRadialMotion {
public:
    /// tension: the ring's elastic load per unit circumference (N/m, ≥ 0); asperity: the contact
    /// law (none: no contact).
    RingRadialMotion(lube::RingFilm film, std::optional<lube::GreenwoodTripp> asperity, double tension);

    /// The step of dt (s) from h_min,n (m) with the liner's sliding speed and the edge pressures of
    /// `conditions` (its gap and squeeze rate are the unknowns) and the gauge pressure behind the
    /// ring (Pa). Throws std::runtime_error when no balance exists between 1e-4 σ (or 1e-10 m)
    /// and 1e3 h_min,n.
    RingRadialStep step(double gapNow, double dt, const lube::RingFilmState& conditions, double backPressure) const;

    /// The asperity load (N/m) at the minimum gap h (m).
    double asperityLoad(double h) const;

private:
    lube::RingFilm film_;
    std::optional<lube::GreenwoodTripp> asperity_;
    double tension_;
};

}  // namespace flexehd::cosim
