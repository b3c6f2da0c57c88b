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
// lube::RingFilm, the asperity load by the Greenwood–Tripp law over its nodes). h_min is the
// separation of the surfaces' mean planes: below zero the asperities carry what the film cannot
// (down to −2σ); the film sees the gap down to a floor of 0.05σ (its minimum, not a result).
#include <limits>
#include <optional>
#include <vector>

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
    /// ring (Pa). Throws std::runtime_error when no balance exists between −2σ (without asperities
    /// the film's floor) and 1e3 h_min,n.
    /// guess: where to start looking for the balance (NaN: at h_min,n).
    RingRadialStep step(double gapNow, double dt, const lube::RingFilmState& conditions, double backPressure,
                        double guess = std::numeric_limits<double>::quiet_NaN()) const;

    /// The asperity load (N/m) at the minimum gap h (m): the Greenwood–Tripp pressure over the
    /// face (trapezoidal rule, 400 intervals), interpolated by cubic Hermite on its values and
    /// slopes every 0.01σ (within 4e-8 of Simpson's rule on 4000 intervals: its test).
    double asperityLoad(double h) const;
    /// The least gap the film sees (m): 0.05σ with asperities, else 1e-10 m.
    double filmFloor() const;

    static constexpr double kFilmFloor = 0.05;   ///< the film's floor in σ
    static constexpr double kDeepestGap = 2.0;   ///< the bracket's lower end: −2σ (the asperity law's table)

private:
    /// ∫ p_c(h + drop(x)) dx over the face, or the integral of its slope dp_c/dh.
    double faceIntegral(double h, bool slope) const;

    lube::RingFilm film_;
    std::optional<lube::GreenwoodTripp> asperity_;
    double tension_;
    double tableLow_ = 0.0, tableStep_ = 1.0;
    std::vector<double> tableLoad_, tableSlope_;
};

}  // namespace flexehd::cosim
