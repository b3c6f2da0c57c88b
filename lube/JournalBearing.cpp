#include "lube/JournalBearing.hpp"

#include <chrono>
#include <cmath>
#include <numbers>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "lube/FilmIntegrals.hpp"
#include "lube/JfoSolver.hpp"

namespace flexehd::lube {
namespace {

constexpr double kPi = std::numbers::pi;

void requirePositive(double v, const char* what) {
    if (!(v > 0.0) || !std::isfinite(v)) {
        std::ostringstream o;
        o << "journal bearing: " << what << " must be positive and finite (got " << v << ")";
        throw std::invalid_argument(o.str());
    }
}

// The grid column of the groove: the one nearest to its angle.
int grooveColumn(const JournalBearingSpec& s) {
    const int n = s.circumferentialNodes;
    return static_cast<int>(std::lround(s.grooveAngleDeg / 360.0 * n)) % n;
}

// The bearing's film grid and film thickness: groove nodes held at 0, journal surface speed ωR.
FilmGrid bearingGrid(const JournalBearingSpec& s) {
    const int nZ = s.infinitelyLong ? 2 : s.axialNodes;
    FilmGrid grid = FilmGrid::fullCircumference(s.radius, FilmGrid::uniform(-0.5 * s.length, 0.5 * s.length, nZ),
                                                s.circumferentialNodes);
    if (s.infinitelyLong) {
        grid.setEdge(Edge::AxialLow, EdgeCondition::Symmetry);
        grid.setEdge(Edge::AxialHigh, EdgeCondition::Symmetry);
    }
    if (s.supplyGroove)
        for (int i = 0; i < nZ; ++i) grid.fixNode(grid.index(i, grooveColumn(s)), 0.0);
    return grid;
}

FilmState bearingFilm(const JournalBearingSpec& s, const FilmGrid& grid) {
    FilmState film;
    film.h.resize(grid.size());
    for (int k = 0; k < grid.size(); ++k)
        film.h[k] = s.clearance * (1 + s.eccentricity * std::cos(grid.theta(grid.thetaIndex(k))));
    film.inner.circumferential = 2 * kPi * s.speed * s.radius;  // journal; sleeve at rest
    return film;
}

struct FilmSolution {
    Eigen::VectorXd pressure, fraction;  // fraction: mass-conserving film only
    int iterations = 0, coarseIterations = 0;
    double residual = 0.0;
};

FilmSolution solveFilm(const JournalBearingSpec& s, const FilmGrid& grid, const FilmState& film,
                       const Lubricant& oil) {
    FilmSolution out;
    if (s.cavitation == BearingCavitation::MassConserving) {
        JfoOptions opt;
        opt.control.tolerance = s.tolerance;
        opt.omega = s.omega;
        opt.method = s.solver == SolverKind::Psor       ? JfoMethod::GaussSeidel
                     : s.solver == SolverKind::ActiveSet ? JfoMethod::ActiveSet
                                                         : JfoMethod::Multigrid;
        JfoSolver jfo(grid, oil, opt);
        if (s.supplyGroove)
            for (int i = 0; i < grid.nAxial(); ++i) jfo.setInletFraction(grid.index(i, grooveColumn(s)), s.supplyFraction);
        JfoResult r = jfo.solve(film);
        out.pressure = std::move(r.pressure);
        out.fraction = std::move(r.fraction);
        out.iterations = r.iterations + r.factorizations;
        out.residual = r.residual;
        return out;
    }
    ReynoldsOptions opt;
    opt.cavitation = s.cavitation == BearingCavitation::Reynolds         ? Cavitation::Reynolds
                     : s.cavitation == BearingCavitation::HalfSommerfeld ? Cavitation::HalfSommerfeld
                                                                         : Cavitation::None;
    opt.solver = s.solver;
    opt.control.tolerance = s.tolerance;
    opt.omega = s.omega;
    ReynoldsSolver rs(grid, oil, opt);
    ReynoldsResult r = rs.solve(film);
    out.pressure = std::move(r.pressure);
    out.iterations = r.iterations;
    out.coarseIterations = r.coarseIterations;
    out.residual = r.residual;
    return out;
}

}  // namespace

JournalBearing::JournalBearing(const JournalBearingSpec& spec) : spec_(spec) {
    requirePositive(spec.radius, "radius");
    requirePositive(spec.length, "length");
    requirePositive(spec.clearance, "clearance");
    requirePositive(spec.speed, "speed");
    requirePositive(spec.viscosity, "viscosity");
    requirePositive(spec.tolerance, "tolerance");
    if (!(spec.eccentricity > 0.0 && spec.eccentricity < 1.0))
        throw std::invalid_argument("journal bearing: the eccentricity ratio must be in (0, 1)");
    if (spec.clearance >= spec.radius)
        throw std::invalid_argument("journal bearing: the clearance must be smaller than the radius");
    if (!(spec.grooveAngleDeg >= 0.0 && spec.grooveAngleDeg < 360.0))
        throw std::invalid_argument("journal bearing: the groove angle must be in [0, 360) deg");
    if (!(spec.supplyFraction > 0.0 && spec.supplyFraction <= 1.0))
        throw std::invalid_argument("journal bearing: the supply's film fraction must be in (0, 1]");
    if (spec.supplyFraction < 1.0 && spec.cavitation != BearingCavitation::MassConserving)
        throw std::invalid_argument("journal bearing: a starved supply needs the mass-conserving film (the "
                                    "Reynolds models take as much oil as the film wants)");
    if (!spec.supplyGroove && (spec.grooveAngleDeg != 0.0 || spec.supplyFraction < 1.0))
        throw std::invalid_argument("journal bearing: a groove angle or a starved supply needs the groove");
    if (!spec.supplyGroove && (spec.infinitelyLong || spec.cavitation == BearingCavitation::MassConserving))
        throw std::invalid_argument("journal bearing: the supply groove is needed by a mass-conserving film "
                                    "(which drains dry without it) and by the infinitely long bearing (its "
                                    "pressure datum)");
}

const char* JournalBearing::methodName() const {
    if (spec_.cavitation != BearingCavitation::MassConserving) return name(spec_.solver);
    return spec_.solver == SolverKind::Psor ? "jfo-gauss-seidel" : "jfo-active-set";
}

JournalBearingResult JournalBearing::solve() const {
    const JournalBearingSpec& s = spec_;
    const FilmGrid grid = bearingGrid(s);
    const FilmState film = bearingFilm(s, grid);
    const Lubricant oil(s.viscosity);
    JournalBearingResult res;
    res.solverName = methodName();
    res.axialNodes = grid.nAxial();
    const int jg = grooveColumn(s);
    res.grooveAngleDeg = s.supplyGroove ? 360.0 * jg / s.circumferentialNodes : 0.0;
    const auto t0 = std::chrono::steady_clock::now();
    const FilmSolution sol = solveFilm(s, grid, film, oil);
    res.solveSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    res.iterations = sol.iterations;
    res.coarseIterations = sol.coarseIterations;
    res.residual = sol.residual;

    const Eigen::VectorXd* phi = sol.fraction.size() ? &sol.fraction : nullptr;
    FilmIntegralOptions io;
    io.filmFraction = phi;
    const FilmLoads f = integrateFilm(grid, film, oil, sol.pressure, io);
    // Film force on the journal: along +x (line of centres, towards the maximum film) and −y.
    const double R = s.radius, c = s.clearance, D = 2 * R, L = s.length, N = s.speed;
    res.loadAlongLineOfCentres = f.pressureForce.x();
    res.loadPerpendicular = -f.pressureForce.y();
    res.load = std::hypot(f.pressureForce.x(), f.pressureForce.y());
    res.attitudeDeg = std::atan2(-f.pressureForce.y(), f.pressureForce.x()) * 180 / kPi;
    res.specificLoad = res.load / (L * D);
    res.sommerfeld = (R / c) * (R / c) * s.viscosity * N / res.specificLoad;
    res.frictionTorque = -f.moment.z();  // opposes ω
    res.frictionPower = res.frictionTorque * (2 * kPi * N);
    res.frictionCoefficient = res.frictionTorque / (R * res.load);
    res.frictionVariable = (R / c) * res.frictionCoefficient;
    // Inlet flow: through the line half a cell downstream of the groove; the flow reaching the
    // groove through the line half a cell upstream; side leakage: out of both ends (the face
    // fluxes extrapolated to the ends, docs/lube.md §5).
    const int n = s.circumferentialNodes;
    res.inletFlow = circumferentialFlow(grid, film, oil, sol.pressure, jg, phi);
    res.returnFlow = circumferentialFlow(grid, film, oil, sol.pressure, (jg + n - 1) % n, phi);
    res.sideFlow = s.infinitelyLong ? 0.0
                                    : axialEdgeFlow(grid, film, oil, sol.pressure, Edge::AxialHigh, phi) -
                                          axialEdgeFlow(grid, film, oil, sol.pressure, Edge::AxialLow, phi);
    res.flowVariable = res.inletFlow / (R * c * N * L);
    res.maxPressure = f.maxPressure;
    res.maxPressureRatio = res.specificLoad / f.maxPressure;
    res.minFilm = f.minFilm;
    res.cavitatedArea = f.cavitatedArea;
    res.cavitatedFraction = f.cavitatedArea / f.filmArea;
    res.resolution = filmResolution(s.eccentricity, s.circumferentialNodes);
    return res;
}

namespace {

// The load's measured deficit against the grid-converged load at K nodes across the minimum
// region h < 2 h_min: the largest of L/D = 1 and infinitely long with the Reynolds condition,
// ε = 0.9 … 0.9999, made monotone (docs/lube.md §8, "Grid resolution of the minimum film").
double measuredLoadDeficit(double k) {
    static constexpr std::pair<double, double> kTable[] = {
        {0.14, 0.993}, {0.29, 0.971}, {0.46, 0.931}, {0.58, 0.889}, {0.91, 0.751}, {1.15, 0.634},
        {1.45, 0.503}, {1.82, 0.349}, {2.3, 0.208},  {2.9, 0.108},  {3.65, 0.053}, {4.6, 0.0365},
        {5.8, 0.0365}, {7.3, 0.0174}, {9.2, 0.010},  {11.6, 0.0078}};
    const auto& first = kTable[0];
    const auto& last = kTable[std::size(kTable) - 1];
    if (!(k > 0.0)) return 1.0;
    if (k <= first.first) return 1.0 - (1.0 - first.second) * (k / first.first) * (k / first.first);  // W ∝ K²
    if (k >= last.first) return last.second * (last.first / k) * (last.first / k);                   // O(Δθ²)
    for (std::size_t i = 1; i < std::size(kTable); ++i) {
        const auto& [k1, d1] = kTable[i];
        if (k > k1) continue;
        const auto& [k0, d0] = kTable[i - 1];
        const double t = std::log(k / k0) / std::log(k1 / k0);
        return std::exp((1 - t) * std::log(d0) + t * std::log(d1));
    }
    return last.second;
}

}  // namespace

FilmResolution filmResolution(double eccentricity, int circumferentialNodes) {
    if (!(eccentricity > 0.0 && eccentricity < 1.0))
        throw std::invalid_argument("journal bearing: the eccentricity ratio must be in (0, 1)");
    if (circumferentialNodes < 1) throw std::invalid_argument("journal bearing: no circumferential nodes");
    FilmResolution r;
    const double halfWidth = std::sqrt(2 * (1 - eccentricity) / eccentricity);  // Δθ, rad
    r.regionWidthDeg = 2 * halfWidth * 180 / kPi;
    r.nodesAcross = 2 * halfWidth / (2 * kPi / circumferentialNodes);
    r.resolved = r.nodesAcross >= kMinFilmRegionNodes;
    r.expectedLoadDeficit = r.resolved ? 0.0 : measuredLoadDeficit(r.nodesAcross);
    r.neededCircumferentialNodes = 16 * std::ceil(kMinFilmRegionNodes * kPi / halfWidth / 16 - 1e-12);
    return r;
}

double largestResolvedEccentricity(int circumferentialNodes) {
    const double halfWidth = kMinFilmRegionNodes * kPi / circumferentialNodes;
    return 2 / (2 + halfWidth * halfWidth);
}

const char* name(BearingCavitation m) {
    switch (m) {
        case BearingCavitation::FullSommerfeld: return "full-sommerfeld";
        case BearingCavitation::HalfSommerfeld: return "half-sommerfeld";
        case BearingCavitation::Reynolds: return "reynolds";
        case BearingCavitation::MassConserving: return "jfo";
    }
    return "";
}

const char* name(SolverKind s) {
    switch (s) {
        case SolverKind::Psor: return "psor";
        case SolverKind::ActiveSet: return "active-set";
        case SolverKind::Multigrid: return "multigrid";
    }
    return "";
}

}  // namespace flexehd::lube
