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
//
// On the liner's oil layer (RingSupply) the film is mass-conserving, a backward-Euler step of its
// content (lube::RingFilm::step); a ring with several alike faces in series at one gap (the
// oil-control ring's lands) solves them in the order the liner meets them: the leading face takes
// the layer, each next one what the face before it leaves on the liner, (its outflow)/|U|
// (docs/ring-pack.md, "The rings on the liner's oil layer").
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "lube/GreenwoodTripp.hpp"
#include "lube/RingFilm.hpp"

namespace flexehd::cosim {

/// The oil a mass-conserving ring film meets in a step.
struct RingSupply {
    double film = 0.0;  ///< m, the layer the leading face meets, as carried at the sliding speed
    /// Each face's film fraction at the step's start (faces bottom first, as many as the ring has).
    std::vector<Eigen::VectorXd> previousFraction;
};

struct RingRadialStep {
    double minimumGap = 0.0;    ///< h_min at the step's end (m)
    double squeezeRate = 0.0;   ///< (h_min − h_min,n)/Δt (m/s)
    double filmLoad = 0.0;      ///< N/m, per face (the faces' mean)
    bool atStop = false;        ///< the ring rests at its stop (the groove's root), off the liner
    double asperityLoad = 0.0;  ///< N/m, per face
    /// Each face's film, bottom first (flooded: one, the faces being alike), and its state.
    std::vector<lube::RingFilmResult> faces;
    std::vector<lube::RingFilmState> states;
};

class RingRadialMotion {
public:
    /// tension: the ring's elastic load per unit circumference on each face (N/m, ≥ 0); asperity:
    /// the contact law (none: no contact); faces: alike faces in series at one gap (≥ 1).
    RingRadialMotion(lube::RingFilm film, std::optional<lube::GreenwoodTripp> asperity, double tension,
                     int faces = 1);

    /// The step of dt (s) from h_min,n (m) with the liner's sliding speed and the edge pressures of
    /// `conditions` (its gap and squeeze rate are the unknowns) and the gauge pressure behind the
    /// ring (Pa). Throws std::runtime_error when no balance exists between −2σ (without asperities
    /// the film's floor) and 1e3 h_min,n.
    /// guess: where to start looking for the balance (NaN: at h_min,n); supply: the oil layer the
    /// ring runs on (null: flooded); stop: the largest gap (m), where the ring's back meets its
    /// groove's root (NaN: none, the search ends at 1e3 h_min,n): where even there the film and the
    /// gas on the face outweigh the load, the ring rests at its stop (the groove's root carrying
    /// the rest) instead of the throw.
    RingRadialStep step(double gapNow, double dt, const lube::RingFilmState& conditions, double backPressure,
                        double guess = std::numeric_limits<double>::quiet_NaN(),
                        const RingSupply* supply = nullptr,
                        double stop = std::numeric_limits<double>::quiet_NaN()) const;

    /// The ring's films at the gap h (m) of a step of dt (s) from h_min,n = gapNow (m), without
    /// its balance: a ring off the liner, moved by the gas (RingPackGas's radial collapse).
    RingRadialStep at(double gap, double gapNow, double dt, const lube::RingFilmState& conditions,
                      const RingSupply* supply = nullptr) const;

    /// The asperity load (N/m) at the minimum gap h (m): the Greenwood–Tripp pressure over the
    /// face (trapezoidal rule, 400 intervals), interpolated by cubic Hermite on its values and
    /// slopes every 0.01σ (within 4e-8 of Simpson's rule on 4000 intervals: its test).
    double asperityLoad(double h) const;
    /// The least gap the film sees (m): 0.05σ with asperities, else 1e-10 m.
    double filmFloor() const;

    int faces() const { return faces_; }
    const lube::RingFilm& film() const { return film_; }

    static constexpr double kFilmFloor = 0.05;   ///< the film's floor in σ
    static constexpr double kDeepestGap = 2.0;   ///< the bracket's lower end: −2σ (the asperity law's table)

private:
    void checkStep(double gapNow, double dt, const RingSupply* supply) const;
    /// The films and asperity load at the trial gap h into s (without friction).
    void trial(double h, double gapNow, double dt, const lube::RingFilmState& conditions, const RingSupply* supply,
               RingRadialStep& s, std::vector<std::vector<char>>& cavitated) const;
    /// ∫ p_c(h + drop(x)) dx over the face, or the integral of its slope dp_c/dh.
    double faceIntegral(double h, bool slope) const;
    /// The faces' films at the trial state c (gap, squeeze rate), each starting from its last
    /// cavitated set; their mean load (N/m).
    double faceFilms(const lube::RingFilmState& c, double dt, const RingSupply* supply, RingRadialStep& s,
                     std::vector<std::vector<char>>& cavitated) const;

    lube::RingFilm film_;
    std::optional<lube::GreenwoodTripp> asperity_;
    double tension_;
    int faces_;
    double tableLow_ = 0.0, tableStep_ = 1.0;
    std::vector<double> tableLoad_, tableSlope_;
};

}  // namespace flexehd::cosim
