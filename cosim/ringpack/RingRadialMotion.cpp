#include "cosim/ringpack/RingRadialMotion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace flexehd::cosim {

RingRadialMotion::RingRadialMotion(lube::RingFilm film, std::optional<lube::GreenwoodTripp> asperity, double tension,
                                   int faces)
    : film_(std::move(film)), asperity_(std::move(asperity)), tension_(tension), faces_(faces) {
    if (!(tension >= 0.0) || !std::isfinite(tension))
        throw std::invalid_argument("RingRadialMotion: the tension must be >= 0 N/m, got " + std::to_string(tension));
    if (faces < 1) throw std::invalid_argument("RingRadialMotion: at least one face, got " + std::to_string(faces));
    if (!asperity_) return;
    // The asperity load and its slope on nodes every 0.01σ from −kDeepestGap σ to the law's end
    // (8σ: beyond it no asperity touches), for the cubic Hermite interpolant of asperityLoad.
    const double sigma = asperity_->sigma();
    tableLow_ = -kDeepestGap * sigma;
    tableStep_ = 0.01 * sigma;
    const int n = static_cast<int>(std::lround((8.0 + kDeepestGap) / 0.01));
    tableLoad_.resize(static_cast<std::size_t>(n) + 1);
    tableSlope_.resize(tableLoad_.size());
    for (int k = 0; k <= n; ++k) {
        const double h = tableLow_ + k * tableStep_;
        tableLoad_[static_cast<std::size_t>(k)] = faceIntegral(h, false);
        tableSlope_[static_cast<std::size_t>(k)] = faceIntegral(h, true);
    }
}

double RingRadialMotion::filmFloor() const { return asperity_ ? kFilmFloor * asperity_->sigma() : 1e-10; }

double RingRadialMotion::faceIntegral(double h, bool slope) const {
    const lube::RingFaceProfile& f = film_.profile();
    const int n = 400;  // trapezoids across the face
    const double dx = (f.upper() - f.lower()) / n;
    double w = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double g = h + f.drop(f.lower() + i * dx);
        w += (i == 0 || i == n ? 0.5 : 1.0) * (slope ? asperity_->pressureSlope(g) : asperity_->pressure(g)) * dx;
    }
    return w;
}

double RingRadialMotion::asperityLoad(double h) const {
    if (!asperity_) return 0.0;
    const double t = (h - tableLow_) / tableStep_;
    if (t < 0.0) return faceIntegral(h, false);
    const auto k = static_cast<std::size_t>(t);
    if (k + 1 >= tableLoad_.size()) return 0.0;
    const double s = t - static_cast<double>(k), s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * tableLoad_[k] + (s3 - 2 * s2 + s) * tableStep_ * tableSlope_[k] +
           (-2 * s3 + 3 * s2) * tableLoad_[k + 1] + (s3 - s2) * tableStep_ * tableSlope_[k + 1];
}

double RingRadialMotion::faceFilms(const lube::RingFilmState& c, double dt, const RingSupply* supply,
                                   RingRadialStep& s, std::vector<std::vector<char>>& cavitated) const {
    s.states.resize(supply ? static_cast<std::size_t>(faces_) : 1);
    if (!supply) {  // flooded: the faces are alike
        s.faces.resize(1);
        s.states[0] = c;
        s.faces[0] = film_.solve(c, &cavitated[0]);
        return s.faces[0].load;
    }
    // In the order the liner meets them: U > 0 (the liner moving towards the crown) meets the
    // bottom face first. The next face's supply: what the last one's trailing edge lets out.
    s.faces.resize(static_cast<std::size_t>(faces_));
    const bool upwards = c.slidingSpeed >= 0.0;
    double load = 0.0, film = supply->film;
    for (int k = 0; k < faces_; ++k) {
        const auto f = static_cast<std::size_t>(upwards ? k : faces_ - 1 - k);
        lube::RingFilmState fc = c;
        fc.supplyFilm = film;
        s.states[f] = fc;
        s.faces[f] = film_.step(fc, dt, supply->previousFraction[f], &cavitated[f]);
        load += s.faces[f].load;
        const double out = -(upwards ? s.faces[f].inflowHigh : s.faces[f].inflowLow);
        film = std::abs(c.slidingSpeed) > 0.0 ? std::max(out, 0.0) / std::abs(c.slidingSpeed) : 0.0;
    }
    return load / faces_;
}

void RingRadialMotion::trial(double h, double gapNow, double dt, const lube::RingFilmState& conditions,
                             const RingSupply* supply, RingRadialStep& s,
                             std::vector<std::vector<char>>& cavitated) const {
    // The film sees the gap down to its floor (the asperities' mean planes may come closer).
    const double floor = filmFloor();
    lube::RingFilmState c = conditions;
    c.withFriction = false;  // the trials need the load; the balance's film gets its friction at the end
    c.minimumGap = std::max(h, floor);
    c.nominalGap = h;
    c.squeezeRate = (c.minimumGap - std::max(gapNow, floor)) / dt;
    s.filmLoad = faceFilms(c, dt, supply, s, cavitated);
    s.minimumGap = h;
    s.squeezeRate = c.squeezeRate;
    s.asperityLoad = asperityLoad(h);
}

void RingRadialMotion::checkStep(double gapNow, double dt, const RingSupply* supply) const {
    if (supply && supply->previousFraction.size() != static_cast<std::size_t>(faces_))
        throw std::invalid_argument(fmt::format("RingRadialMotion::step: {} faces' film fractions for {} faces",
                                                supply->previousFraction.size(), faces_));
    if (!std::isfinite(gapNow) || !(dt > 0.0) || (!asperity_ && !(gapNow > 0.0)))
        throw std::invalid_argument("RingRadialMotion::step: the step must be positive and the last gap finite (positive "
                                    "without asperities)");
}

RingRadialStep RingRadialMotion::at(double gap, double gapNow, double dt, const lube::RingFilmState& conditions,
                                    const RingSupply* supply) const {
    checkStep(gapNow, dt, supply);
    RingRadialStep s;
    std::vector<std::vector<char>> cavitated(static_cast<std::size_t>(faces_));
    trial(gap, gapNow, dt, conditions, supply, s, cavitated);
    for (std::size_t f = 0; f < s.faces.size(); ++f) film_.addFriction(s.states[f], s.faces[f]);
    return s;
}

RingRadialStep RingRadialMotion::step(double gapNow, double dt, const lube::RingFilmState& conditions,
                                      double backPressure, double guess, const RingSupply* supply,
                                      double stop) const {
    checkStep(gapNow, dt, supply);
    const double load = tension_ + backPressure * (film_.profile().upper() - film_.profile().lower());
    RingRadialStep s;
    const double floor = filmFloor();
    // Each trial's films start from the last trial's cavitated sets.
    std::vector<std::vector<char>> cavitated(static_cast<std::size_t>(faces_));
    // The resistance W_film + W_asperity − load at the trial gap h (falls as h grows).
    auto excess = [&](double h) {
        trial(h, gapNow, dt, conditions, supply, s, cavitated);
        return s.filmLoad + s.asperityLoad - load;
    };
    // The bracket: from the guess (or the last gap) outwards in growing steps, within [lowest, highest].
    const double lowest = asperity_ ? -kDeepestGap * asperity_->sigma() : floor;
    const bool stopped = std::isfinite(stop);
    if (stopped && !(stop > floor))
        throw std::invalid_argument(fmt::format("RingRadialMotion::step: the ring's stop ({:.4g} m) must lie above the "
                                                "film's floor ({:.4g} m)",
                                                stop, floor));
    const double highest = stopped ? stop : 1e3 * std::max(gapNow, floor);
    const double scale = asperity_ ? asperity_->sigma() : std::max(gapNow, floor);
    const bool guessed = std::isfinite(guess);
    double lo = std::clamp(guessed ? guess : gapNow, lowest, highest), hi = lo;
    double flo = excess(lo), fhi = flo;
    for (double step = (guessed ? 1e-3 : 1e-2) * scale; flo < 0.0 || fhi > 0.0; step *= 4.0) {
        const bool down = flo < 0.0;  // the balance lies below: too little resistance at lo
        if (!down && hi >= highest && stopped) {  // at its stop, the last trial's (hi's) state
            for (std::size_t f = 0; f < s.faces.size(); ++f) film_.addFriction(s.states[f], s.faces[f]);
            s.atStop = true;
            return s;
        }
        if ((down && lo <= lowest) || (!down && hi >= highest))
            throw std::runtime_error(fmt::format("RingRadialMotion: no radial balance of the ring between gaps {:.4g} "
                                                 "and {:.4g} m (load {:.4g} N/m)",
                                                 lowest, highest, load));
        if (down) {
            hi = lo;
            fhi = flo;
            lo = std::max(lo - step, lowest);
            flo = excess(lo);
        } else {
            lo = hi;
            flo = fhi;
            hi = std::min(hi + step, highest);
            fhi = excess(hi);
        }
    }
    // The balance's films with their friction.
    auto balanced = [&]() -> RingRadialStep {
        for (std::size_t f = 0; f < s.faces.size(); ++f) film_.addFriction(s.states[f], s.faces[f]);
        return s;
    };
    if (flo == 0.0 || fhi == 0.0) {
        excess(flo == 0.0 ? lo : hi);
        return balanced();
    }
    // Regula falsi with the Illinois modification (superlinear), bisection where the secant
    // leaves the bracket.
    const double resolution = 1e-12 * std::max(scale, std::abs(hi));
    for (int it = 0; it < 200; ++it) {
        double h = hi - fhi * (hi - lo) / (fhi - flo);
        if (!(h > lo && h < hi)) h = 0.5 * (lo + hi);
        const double f = excess(h);
        if (std::abs(f) <= 1e-10 * load || hi - lo <= resolution) return balanced();
        if (f > 0.0) {
            lo = h;
            flo = f;
            fhi *= 0.5;
        } else {
            hi = h;
            fhi = f;
            flo *= 0.5;
        }
    }
    throw std::runtime_error("RingRadialMotion: the radial balance did not converge in 200 iterations");
}

}  // namespace flexehd::cosim
