#include "cosim/ringpack/RingRadialMotion.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace flexehd::cosim {

RingRadialMotion::RingRadialMotion(lube::RingFilm film, std::optional<lube::GreenwoodTripp> asperity, double tension)
    : film_(std::move(film)), asperity_(std::move(asperity)), tension_(tension) {
    if (!(tension >= 0.0) || !std::isfinite(tension))
        throw std::invalid_argument("RingRadialMotion: the tension must be >= 0 N/m, got " + std::to_string(tension));
}

double RingRadialMotion::asperityLoad(double h) const {
    if (!asperity_) return 0.0;
    const lube::RingFaceProfile& f = film_.profile();
    const int n = 400;  // trapezoids across the face
    const double dx = (f.upper() - f.lower()) / n;
    double w = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double x = f.lower() + i * dx;
        w += (i == 0 || i == n ? 0.5 : 1.0) * asperity_->pressure(h + f.drop(x)) * dx;
    }
    return w;
}

RingRadialStep RingRadialMotion::step(double gapNow, double dt, const lube::RingFilmState& conditions,
                                      double backPressure) const {
    if (!(gapNow > 0.0) || !(dt > 0.0))
        throw std::invalid_argument("RingRadialMotion::step: the last gap and the step must be positive");
    const double load = tension_ + backPressure * (film_.profile().upper() - film_.profile().lower());
    RingRadialStep s;
    // The resistance W_film + W_asperity − load at the trial gap h (falls as h grows).
    auto excess = [&](double h) {
        lube::RingFilmState c = conditions;
        c.minimumGap = h;
        c.squeezeRate = (h - gapNow) / dt;
        s.film = film_.solve(c);
        s.minimumGap = h;
        s.squeezeRate = c.squeezeRate;
        s.filmLoad = s.film.load;
        s.asperityLoad = asperityLoad(h);
        return s.filmLoad + s.asperityLoad - load;
    };
    double lo = asperity_ ? 1e-4 * asperity_->sigma() : 1e-10, hi = 1e3 * gapNow;
    double flo = excess(lo), fhi = excess(hi);
    if (!(flo >= 0.0 && fhi <= 0.0))
        throw std::runtime_error(fmt::format("RingRadialMotion: no radial balance of the ring between gaps {:.4g} and "
                                             "{:.4g} m (load {:.4g} N/m)",
                                             lo, hi, load));
    // Bisection with a secant (regula falsi, Illinois) step: the bracket halves at worst.
    for (int it = 0; it < 200; ++it) {
        double h = hi - fhi * (hi - lo) / (fhi - flo);
        if (!(h > lo && h < hi) || it % 3 == 2) h = 0.5 * (lo + hi);
        const double f = excess(h);
        if (std::abs(f) <= 1e-10 * load || hi - lo <= 1e-12 * hi) return s;
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
