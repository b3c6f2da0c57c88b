#include "lube/RingFilm.hpp"

#include "lube/FilmGrid.hpp"
#include "lube/JfoSolver.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace flexehd::lube {

namespace {

constexpr int kColumns = 3;  // θ columns of the mass-conserving film's grid (the solution does not depend on θ)

// x = A⁻¹ d for the tridiagonal A (sub a, diagonal b, super c), by the Thomas algorithm.
void tridiagonalSolve(const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& c,
                      std::vector<double>& d) {
    const std::size_t n = b.size();
    std::vector<double> cp(n);
    double m = b[0];
    cp[0] = c[0] / m;
    d[0] /= m;
    for (std::size_t i = 1; i < n; ++i) {
        m = b[i] - a[i] * cp[i - 1];
        cp[i] = c[i] / m;
        d[i] = (d[i] - a[i] * d[i - 1]) / m;
    }
    for (std::size_t i = n - 1; i-- > 0;) d[i] -= cp[i] * d[i + 1];
}

}  // namespace

RingFilm::RingFilm(RingFaceProfile profile, Lubricant lubricant, int nodes, double cavitationPressure, double roughness)
    : profile_(std::move(profile)), lubricant_(lubricant), pcav_(cavitationPressure), shear_(roughness) {
    if (nodes < 5) throw std::invalid_argument("RingFilm: at least 5 nodes across the face, got " + std::to_string(nodes));
    if (lubricant_.pressureDependent())
        throw std::invalid_argument("RingFilm: a constant-property lubricant only (no pressure-dependent viscosity)");
    x_ = Eigen::VectorXd::LinSpaced(nodes, profile_.lower(), profile_.upper());
    drop_.resize(nodes);
    for (int i = 0; i < nodes; ++i) drop_[i] = profile_.drop(x_[i]);
}

RingFilmResult RingFilm::solve(const RingFilmState& s, std::vector<char>* cavitated) const {
    return solveWith(s, 0.0, nullptr, cavitated);
}

RingFilmResult RingFilm::step(const RingFilmState& s, double dt, const Eigen::VectorXd& previousFraction) const {
    if (std::isnan(s.supplyFilm))
        throw std::invalid_argument("RingFilm::step: a step of the film's content needs the supply film (mass-conserving)");
    if (!(dt > 0.0) || previousFraction.size() != x_.size())
        throw std::invalid_argument("RingFilm::step: a positive step and the previous film fraction on the " +
                                    std::to_string(x_.size()) + " nodes expected");
    return solveWith(s, dt, &previousFraction);
}

RingFilmResult RingFilm::solveWith(const RingFilmState& s, double dt, const Eigen::VectorXd* previous,
                                   std::vector<char>* cavitated) const {
    if (!(s.minimumGap > 0.0) || !std::isfinite(s.minimumGap))
        throw std::invalid_argument("RingFilm: the minimum gap must be positive, got " + std::to_string(s.minimumGap));
    if (!std::isfinite(s.slidingSpeed) || !std::isfinite(s.squeezeRate) || !std::isfinite(s.pressureBelow) ||
        !std::isfinite(s.pressureAbove))
        throw std::invalid_argument("RingFilm: sliding speed, squeeze rate and edge pressures must be finite");
    const bool starved = !std::isnan(s.supplyFilm);
    if (starved && !(s.supplyFilm >= 0.0 && std::isfinite(s.supplyFilm)))
        throw std::invalid_argument("RingFilm: the supply film must be >= 0 m (or NaN: flooded), got " +
                                    std::to_string(s.supplyFilm));
    if (starved && s.squeezeRate != 0.0 && !previous)
        throw std::invalid_argument("RingFilm: the film fed by an oil layer solved steady: the squeeze rate must be 0 "
                                    "(RingFilm::step for a squeezing film)");
    const int n = static_cast<int>(x_.size());
    const double eta = lubricant_.referenceViscosity(), dx = x_[1] - x_[0];
    RingFilmResult r;
    r.x = x_;
    r.h = drop_.array() + s.minimumGap;
    if (starved) solveStarved(s, dt, previous, r);
    else solveFlooded(s, r, cavitated);
    // The Couette shear sees the nominal gap (the film's may be floored): Patir & Cheng's factor
    // φ_f(h/σ)/h of the rough surfaces (docs/lube.md §5), 1/h when smooth.
    const double nominal = std::isnan(s.nominalGap) ? s.minimumGap : s.nominalGap;
    for (int i = 0; i + 1 < n; ++i) {  // trapezoids between nodes
        const double hm = 0.5 * (r.h[i] + r.h[i + 1]), dpdx = (r.p[i + 1] - r.p[i]) / dx;
        r.load += 0.5 * (r.p[i] + r.p[i + 1]) * dx;
        // Shear on the ring (u = 0) from the liner's Couette flow, on the oil (φ; none where the
        // Reynolds condition cavitates both nodes), and the Poiseuille flow.
        const bool cavitated = !starved && r.p[i] <= pcav_ && r.p[i + 1] <= pcav_;
        const double phi = cavitated ? 0.0 : 0.5 * (r.fraction[i] + r.fraction[i + 1]);
        double couette = 0.0, slope = 0.0;
        shear_.couette(nominal + 0.5 * (drop_[i] + drop_[i + 1]), couette, slope);
        r.friction += (phi * eta * s.slidingSpeed * couette - 0.5 * hm * dpdx) * dx;
    }
    return r;
}

void RingFilm::solveStarved(const RingFilmState& s, double dt, const Eigen::VectorXd* previous,
                            RingFilmResult& r) const {
    const int n = static_cast<int>(x_.size());
    FilmGrid g = FilmGrid::fullCircumference(1.0, std::vector<double>(x_.data(), x_.data() + n), kColumns);
    g.setEdge(Edge::AxialLow, EdgeCondition::Pressure, std::max(s.pressureBelow, pcav_));
    g.setEdge(Edge::AxialHigh, EdgeCondition::Pressure, std::max(s.pressureAbove, pcav_));
    JfoOptions o;
    o.method = JfoMethod::ActiveSet;
    o.cavitationPressure = pcav_;
    o.control.tolerance = 1e-12;
    JfoSolver jfo(g, lubricant_, o);
    FilmState f;
    f.h.resize(g.size());
    for (int k = 0; k < g.size(); ++k) f.h[k] = r.h[g.axialIndex(k)];
    f.outer.axial = s.slidingSpeed;
    // The leading edge (where the liner comes from) takes in the layer's flux U t: its inlet
    // fraction makes the Couette inflow (|U|/2) h_f φ_in carry it.
    const int lead = s.slidingSpeed >= 0.0 ? 0 : n - 1, next = lead == 0 ? 1 : n - 2;
    const double hf = 0.5 * (r.h[lead] + r.h[next]);
    for (int j = 0; j < kColumns; ++j) jfo.setInletFraction(g.index(lead, j), std::min(1.0, 2.0 * s.supplyFilm / hf));
    JfoState before;
    if (previous) {  // the face moved by dt ḣ_min over the step
        before.h = f.h.array() - dt * s.squeezeRate;
        before.fraction.resize(g.size());
        for (int k = 0; k < g.size(); ++k) before.fraction[k] = (*previous)[g.axialIndex(k)];
    }
    const JfoResult res = jfo.solve(f, previous ? dt : 0.0, previous ? &before : nullptr);
    r.p.resize(n);
    r.fraction.resize(n);
    for (int i = 0; i < n; ++i) {
        r.p[i] = res.pressure[g.index(i, 0)];
        r.fraction[i] = res.fraction[g.index(i, 0)];
    }
    const double circumference = 2.0 * std::numbers::pi * g.radius();
    r.oil = jfo.oilVolume(f, res.fraction) / circumference;
    r.inflow = res.boundaryFlow.sum() / circumference;
}

void RingFilm::solveFlooded(const RingFilmState& s, RingFilmResult& r, std::vector<char>* cavitated) const {
    const int n = static_cast<int>(x_.size());
    const double eta = lubricant_.referenceViscosity(), dx = x_[1] - x_[0];
    // Faces f = i + ½: conductance c_f = h_f³/(12 η Δx), Couette flux (U/2) h_f; node i's balance
    // (c₋ + c₊) p_i − c₋ p_{i−1} − c₊ p_{i+1} = −(U/2)(h₊ − h₋) − Δx ∂h/∂t.
    std::vector<double> c(static_cast<std::size_t>(n - 1)), q(static_cast<std::size_t>(n - 1));
    for (int f = 0; f + 1 < n; ++f) {
        const double hf = 0.5 * (r.h[f] + r.h[f + 1]);
        c[static_cast<std::size_t>(f)] = hf * hf * hf / (12.0 * eta * dx);
        q[static_cast<std::size_t>(f)] = 0.5 * s.slidingSpeed * hf;
    }
    const double pLow = std::max(s.pressureBelow, pcav_), pHigh = std::max(s.pressureAbove, pcav_);
    // Primal–dual active set: nodes held at p_cav where the free solution falls below it; released
    // where the balance asks for more pressure than p_cav. The partition settles in a few passes,
    // from none held or from the caller's last one (the same solution: the problem's is unique).
    std::vector<char> own;
    std::vector<char>& held = cavitated ? *cavitated : own;
    if (held.size() != static_cast<std::size_t>(n)) held.assign(static_cast<std::size_t>(n), 0);
    std::vector<double> a(static_cast<std::size_t>(n)), b(static_cast<std::size_t>(n)), up(static_cast<std::size_t>(n)),
        rhs(static_cast<std::size_t>(n)), p(static_cast<std::size_t>(n));
    auto balance = [&](int i, const std::vector<double>& pv) {  // A p − b at node i
        const auto fm = static_cast<std::size_t>(i - 1), fp = static_cast<std::size_t>(i);
        return c[fm] * (pv[static_cast<std::size_t>(i)] - pv[fm]) + c[fp] * (pv[static_cast<std::size_t>(i)] - pv[fp + 1]) +
               q[fp] - q[fm] + dx * s.squeezeRate;
    };
    for (int pass = 0; pass < 4 * n; ++pass) {
        for (int i = 0; i < n; ++i) {
            const auto si = static_cast<std::size_t>(i);
            a[si] = up[si] = 0.0;
            if (i == 0 || i == n - 1 || held[si]) {
                b[si] = 1.0;
                rhs[si] = i == 0 ? pLow : i == n - 1 ? pHigh : pcav_;
                continue;
            }
            b[si] = c[si - 1] + c[si];
            a[si] = -c[si - 1];
            up[si] = -c[si];
            rhs[si] = -(q[si] - q[si - 1]) - dx * s.squeezeRate;
        }
        p = rhs;
        tridiagonalSolve(a, b, up, p);
        bool changed = false;
        for (int i = 1; i + 1 < n; ++i) {
            const auto si = static_cast<std::size_t>(i);
            if (!held[si] && p[si] < pcav_) held[si] = 1, changed = true;
            else if (held[si] && balance(i, p) < 0.0) held[si] = 0, changed = true;  // it wants p > p_cav
        }
        if (!changed) break;
        if (pass == 4 * n - 1) throw std::runtime_error("RingFilm: the cavitated set did not settle");
    }
    r.p = Eigen::Map<const Eigen::VectorXd>(p.data(), n);
    r.fraction = Eigen::VectorXd::Ones(n);
}

}  // namespace flexehd::lube
