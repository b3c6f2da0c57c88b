// `flexehd bearing`: a plain 360° journal bearing (stationary sleeve, journal spinning at N rev/s)
// solved by the lubrication library, with the dimensionless numbers of the design charts
// (Raimondi & Boyd 1958): Sommerfeld number, attitude angle, friction and flow variables,
// pressure ratio. Film h = c(1 + ε cos θ), θ from the maximum film (docs/lube.md §1).
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include <spdlog/spdlog.h>

#include "cosim/MemoryBudget.hpp"
#include "cosim/cli/CliSupport.hpp"
#include "cosim/cli/Commands.hpp"
#include "lube/FilmIntegrals.hpp"
#include "lube/JfoSolver.hpp"
#include "lube/ReynoldsSolver.hpp"

namespace flexehd::cli {
namespace {

constexpr double kPi = std::numbers::pi;

struct BearingArgs {
    double radius = 0.05;
    double length = 0.0;        // 0: from --length-over-diameter
    double lengthOverDiameter = 0.0;
    double clearance = 50e-6;
    double eccentricity = -1.0;  // required
    double speed = 50.0;         // rev/s
    double viscosity = 0.01;
    std::string cavitation = "reynolds";
    std::string solver = "fast";
    std::string grid = "128x33";
    double tolerance = 1e-8;
    double omega = 0.0;  // PSOR / JFO over-relaxation, 0 = automatic
    bool infinitelyLong = false;
    bool noGroove = false;
    bool json = false;
};

enum class Model { FullSommerfeld, HalfSommerfeld, Reynolds, Jfo };

Model parseCavitation(const std::string& s) {
    if (s == "none" || s == "full-sommerfeld") return Model::FullSommerfeld;
    if (s == "half-sommerfeld") return Model::HalfSommerfeld;
    if (s == "reynolds") return Model::Reynolds;
    if (s == "jfo") return Model::Jfo;
    throw std::invalid_argument("unknown cavitation model '" + s +
                                "' (expected none, full-sommerfeld, half-sommerfeld, reynolds or jfo)");
}

lube::SolverKind parseSolver(const std::string& s) {
    if (s == "psor") return lube::SolverKind::Psor;
    if (s == "active-set") return lube::SolverKind::ActiveSet;
    if (s == "fast" || s == "multigrid") return lube::SolverKind::Multigrid;
    throw std::invalid_argument("unknown solver '" + s +
                                "' (expected psor, active-set, multigrid or fast = multigrid)");
}

// "NTHETAxNZ", e.g. 128x33.
std::pair<int, int> parseGrid(const std::string& s) {
    const auto x = s.find_first_of("xX");
    std::size_t used1 = 0, used2 = 0;
    int nt = 0, nz = 0;
    try {
        if (x == std::string::npos) throw std::invalid_argument("");
        nt = std::stoi(s.substr(0, x), &used1);
        nz = std::stoi(s.substr(x + 1), &used2);
    } catch (const std::exception&) {
        throw std::invalid_argument("--grid '" + s + "': expected NTHETAxNZ, e.g. 128x33");
    }
    if (used1 != x || used2 != s.size() - x - 1)
        throw std::invalid_argument("--grid '" + s + "': expected NTHETAxNZ, e.g. 128x33");
    if (nt < 8 || nz < 3)
        throw std::invalid_argument("--grid '" + s + "': need at least 8 circumferential and 3 axial nodes");
    return {nt, nz};
}

std::string str(double v) {
    std::ostringstream o;
    o << v;
    return o.str();
}

void requirePositive(double v, const char* what) {
    if (!(v > 0.0) || !std::isfinite(v))
        throw std::invalid_argument(std::string(what) + " must be positive and finite (got " + str(v) + ")");
}

const char* name(Model m) {
    switch (m) {
        case Model::FullSommerfeld: return "full-sommerfeld";
        case Model::HalfSommerfeld: return "half-sommerfeld";
        case Model::Reynolds: return "reynolds";
        case Model::Jfo: return "jfo";
    }
    return "";
}

const char* name(lube::SolverKind s) {
    switch (s) {
        case lube::SolverKind::Psor: return "psor";
        case lube::SolverKind::ActiveSet: return "active-set";
        case lube::SolverKind::Multigrid: return "multigrid";
    }
    return "";
}

void runBearing(const BearingArgs& a) {
    Stopwatch total;
    // Validation: every message names the option.
    requirePositive(a.radius, "--radius");
    requirePositive(a.clearance, "--clearance");
    requirePositive(a.speed, "--speed");
    requirePositive(a.viscosity, "--viscosity");
    requirePositive(a.tolerance, "--tolerance");
    if (!(a.omega == 0.0 || (a.omega > 0.0 && a.omega < 2.0)))
        throw std::invalid_argument("--omega must be in (0, 2), or 0 for automatic");
    if (!(a.eccentricity > 0.0 && a.eccentricity < 1.0))
        throw std::invalid_argument("--eccentricity must be in (0, 1), the journal touches the sleeve at 1 (got " +
                                    str(a.eccentricity) + ")");
    if (a.length > 0.0 && a.lengthOverDiameter > 0.0)
        throw std::invalid_argument("give either --length or --length-over-diameter, not both");
    if (a.length != 0.0) requirePositive(a.length, "--length");
    if (a.lengthOverDiameter != 0.0) requirePositive(a.lengthOverDiameter, "--length-over-diameter");
    if (a.clearance >= a.radius)
        throw std::invalid_argument("--clearance must be smaller than --radius");
    const Model model = parseCavitation(a.cavitation);
    const lube::SolverKind solverKind = parseSolver(a.solver);
    const auto [nTheta, nZgiven] = parseGrid(a.grid);
    cosim::requireFilmMemory("--grid " + a.grid, nTheta, nZgiven, 0);  // reads as NTHETA × NZ

    const double R = a.radius, c = a.clearance, eps = a.eccentricity, mu = a.viscosity;
    const double D = 2 * R;
    const double L = a.length > 0.0 ? a.length : (a.lengthOverDiameter > 0.0 ? a.lengthOverDiameter : 1.0) * D;
    const double N = a.speed, omega = 2 * kPi * N;

    // Grid: open ends at ambient 0, or (infinitely long) one axial cell with zero-flux ends. The
    // oil is supplied by a full-length axial groove at the maximum film θ = 0 at ambient pressure
    // (the boundary condition of Raimondi & Boyd; also the datum p = 0 where the infinitely long
    // Sommerfeld solutions vanish). Without it a mass-conserving (JFO) film drains dry.
    if (model == Model::Jfo && a.noGroove)
        throw std::invalid_argument("--cavitation jfo needs the supply groove (drop --no-groove): "
                                    "a mass-conserving film without a supply drains dry");
    if (a.infinitelyLong && a.noGroove)
        throw std::invalid_argument("--infinitely-long needs the groove as its pressure datum (drop --no-groove)");
    const int nZ = a.infinitelyLong ? 2 : nZgiven;
    lube::FilmGrid grid = lube::FilmGrid::fullCircumference(R, lube::FilmGrid::uniform(-0.5 * L, 0.5 * L, nZ), nTheta);
    if (a.infinitelyLong) {
        grid.setEdge(lube::Edge::AxialLow, lube::EdgeCondition::Symmetry);
        grid.setEdge(lube::Edge::AxialHigh, lube::EdgeCondition::Symmetry);
    }
    if (!a.noGroove)
        for (int i = 0; i < nZ; ++i) grid.fixNode(grid.index(i, 0), 0.0);
    lube::FilmState film;
    film.h.resize(grid.size());
    for (int k = 0; k < grid.size(); ++k) film.h[k] = c * (1 + eps * std::cos(grid.theta(grid.thetaIndex(k))));
    film.inner.circumferential = omega * R;  // journal surface speed; sleeve at rest
    const lube::Lubricant oil(mu);

    spdlog::info("journal bearing R = {} m, L = {} m{}, c = {} m, eps = {}, N = {} rev/s, mu = {} Pa s",
                 R, L, a.infinitelyLong ? " (infinitely long)" : "", c, eps, N, mu);
    // JFO: psor = the projected Gauss-Seidel sweeps of Ausas et al.; every other choice (the
    // default fast included) = the active-set method on sparse LU (there is no JFO multigrid).
    const bool jfoSweeps = a.solver == "psor";
    const char* solverName = model != Model::Jfo ? name(solverKind)
                             : jfoSweeps        ? "jfo-gauss-seidel"
                                                : "jfo-active-set";
    spdlog::info("solving: {} cavitation, {} solver, grid {}x{} (theta x z)", name(model), solverName,
                 nTheta, nZ);
    if (model == Model::Jfo && solverKind == lube::SolverKind::Multigrid && a.solver != "fast")
        spdlog::warn("--cavitation jfo has no multigrid method: using the active-set method");

    Stopwatch solveTime;
    Eigen::VectorXd p, fraction;
    int iterations = 0, coarseIterations = 0;
    double residual = 0.0;
    if (model == Model::Jfo) {
        lube::JfoOptions opt;
        opt.control.tolerance = a.tolerance;
        opt.omega = a.omega;
        opt.method = jfoSweeps ? lube::JfoMethod::GaussSeidel : lube::JfoMethod::ActiveSet;
        const lube::JfoSolver jfo(grid, oil, opt);
        lube::JfoResult r = jfo.solve(film);
        p = std::move(r.pressure);
        fraction = std::move(r.fraction);
        iterations = r.iterations + r.factorizations;  // sweeps, or LU factorizations
        residual = r.residual;
    } else {
        lube::ReynoldsOptions opt;
        opt.cavitation = model == Model::Reynolds         ? lube::Cavitation::Reynolds
                         : model == Model::HalfSommerfeld ? lube::Cavitation::HalfSommerfeld
                                                          : lube::Cavitation::None;
        opt.solver = solverKind;
        opt.control.tolerance = a.tolerance;
        opt.omega = a.omega;
        lube::ReynoldsSolver rs(grid, oil, opt);
        lube::ReynoldsResult r = rs.solve(film);
        p = std::move(r.pressure);
        iterations = r.iterations;
        coarseIterations = r.coarseIterations;
        residual = r.residual;
    }
    const double seconds = solveTime.seconds();
    spdlog::info("solved: {} iterations ({} on coarse grids), residual {:.2e}, {:.3f} s", iterations,
                 coarseIterations, residual, seconds);

    const Eigen::VectorXd* phi = fraction.size() ? &fraction : nullptr;
    lube::FilmIntegralOptions io;
    io.filmFraction = phi;
    const lube::FilmLoads f = lube::integrateFilm(grid, film, oil, p, io);
    // Film force on the journal: along +x (line of centres, towards the maximum film) and −y.
    const double W = std::hypot(f.pressureForce.x(), f.pressureForce.y());
    const double attitude = std::atan2(-f.pressureForce.y(), f.pressureForce.x()) * 180 / kPi;
    const double P = W / (L * D);                             // specific load
    const double S = (R / c) * (R / c) * mu * N / P;          // Sommerfeld number
    const double torque = -f.moment.z();                      // friction torque on the journal (opposes ω)
    const double frictionCoeff = torque / (R * W);
    // Inlet flow: through the line at θ = Δθ/2 next to the maximum film; side leakage: out of
    // both ends (the face fluxes extrapolated to the ends, docs/lube.md §5).
    const double qIn = lube::circumferentialFlow(grid, film, oil, p, 0, phi);
    const double qSide = a.infinitelyLong ? 0.0
                                          : lube::axialEdgeFlow(grid, film, oil, p, lube::Edge::AxialHigh, phi) -
                                                lube::axialEdgeFlow(grid, film, oil, p, lube::Edge::AxialLow, phi);
    const double flowVariable = qIn / (R * c * N * L);
    const double pRatio = P / f.maxPressure;
    const double cavFraction = f.cavitatedArea / f.filmArea;

    if (a.json) {
        nlohmann::json doc;
        doc["input"] = {{"radius_m", R},
                        {"length_m", L},
                        {"length_over_diameter", L / D},
                        {"infinitely_long", a.infinitelyLong},
                        {"supply_groove", !a.noGroove},
                        {"clearance_m", c},
                        {"eccentricity", eps},
                        {"speed_rev_s", N},
                        {"viscosity_pa_s", mu},
                        {"cavitation", name(model)},
                        {"solver", solverName},
                        {"grid", {{"circumferential", nTheta}, {"axial", nZ}}},
                        {"tolerance", a.tolerance}};
        doc["load_n"] = W;
        doc["load_components_n"] = {{"along_line_of_centres", f.pressureForce.x()},
                                    {"perpendicular", -f.pressureForce.y()}};
        doc["specific_load_pa"] = P;
        doc["attitude_deg"] = attitude;
        doc["sommerfeld"] = S;
        doc["friction_torque_nm"] = torque;
        doc["friction_power_w"] = torque * omega;
        doc["friction_coefficient"] = frictionCoeff;
        doc["friction_variable"] = (R / c) * frictionCoeff;
        doc["inlet_flow_m3_s"] = qIn;
        doc["side_flow_m3_s"] = qSide;
        doc["flow_variable"] = flowVariable;
        doc["side_flow_ratio"] = qSide / qIn;
        doc["max_pressure_pa"] = f.maxPressure;
        doc["max_pressure_ratio"] = pRatio;
        doc["min_film_m"] = f.minFilm;
        doc["cavitated_area_m2"] = f.cavitatedArea;
        doc["cavitated_fraction"] = cavFraction;
        doc["iterations"] = iterations;
        doc["coarse_iterations"] = coarseIterations;
        doc["residual"] = residual;
        doc["seconds"] = seconds;
        doc["total_seconds"] = total.seconds();
        doc["peak_memory_mib"] = peakMemoryMiB();
        printJson(doc);
    } else {
        std::printf("journal bearing: R = %g m, L = %g m (L/D = %g%s), c = %g m, eps = %g, N = %g rev/s, mu = %g Pa s\n",
                    R, L, L / D, a.infinitelyLong ? ", infinitely long" : "", c, eps, N, mu);
        std::printf("%s cavitation, %s solver, grid %dx%d (theta x z)\n\n", name(model), solverName,
                    nTheta, nZ);
        auto row = [](const char* what, double v, const char* unit) {
            std::printf("  %-34s %14.6g  %s\n", what, v, unit);
        };
        row("load W", W, "N");
        row("specific load P = W/(LD)", P, "Pa");
        row("attitude angle", attitude, "deg");
        row("Sommerfeld number (R/c)^2 mu N/P", S, "-");
        row("friction torque on journal", torque, "N m");
        row("friction power", torque * omega, "W");
        row("friction coefficient f", frictionCoeff, "-");
        row("friction variable (R/c) f", (R / c) * frictionCoeff, "-");
        row("inlet flow Q", qIn, "m^3/s");
        row("side flow Qs", qSide, "m^3/s");
        row("flow variable Q/(R c N L)", flowVariable, "-");
        row("max pressure", f.maxPressure, "Pa");
        row("pressure ratio P/p_max", pRatio, "-");
        row("min film", f.minFilm, "m");
        row("cavitated area", f.cavitatedArea, "m^2");
        row("cavitated fraction", cavFraction, "-");
        std::printf("\n  %d iterations (%d coarse), residual %.2e, solve %.3f s, total %.3f s\n", iterations,
                    coarseIterations, residual, seconds, total.seconds());
    }
}

}  // namespace

void addBearingCommand(CLI::App& app) {
    auto a = std::make_shared<BearingArgs>();
    CLI::App* cmd = app.add_subcommand(
        "bearing",
        "Plain 360-degree journal bearing (stationary sleeve, rotating journal): load, attitude, "
        "Sommerfeld number, friction, flows. SI units; speed in rev/s");
    cmd->add_option("--radius", a->radius, "Journal radius R [m]")->capture_default_str();
    cmd->add_option("--length", a->length, "Bearing length L [m] (or --length-over-diameter)");
    cmd->add_option("--length-over-diameter", a->lengthOverDiameter, "Length over diameter L/D [-] (default 1)");
    cmd->add_option("--clearance", a->clearance, "Radial clearance c [m]")->capture_default_str();
    cmd->add_option("--eccentricity", a->eccentricity, "Eccentricity ratio e/c in (0, 1) [-]")->required();
    cmd->add_option("--speed", a->speed, "Journal speed N [rev/s]")->capture_default_str();
    cmd->add_option("--viscosity", a->viscosity, "Dynamic viscosity mu [Pa s]")->capture_default_str();
    cmd->add_option("--cavitation", a->cavitation,
                    "none (= full-sommerfeld), half-sommerfeld, reynolds (Swift-Stieber) or jfo "
                    "(mass-conserving Elrod-Adams)")
        ->capture_default_str();
    cmd->add_option("--solver", a->solver,
                    "psor (baseline), active-set (Cholesky), multigrid or fast (= multigrid); with "
                    "jfo: psor = Gauss-Seidel sweeps, otherwise the active-set method (sparse LU)")
        ->capture_default_str();
    cmd->add_option("--grid", a->grid, "Nodes NTHETAxNZ, circumferential x axial (even NTHETA for multigrid)")
        ->capture_default_str();
    cmd->add_flag("--infinitely-long", a->infinitelyLong,
                  "Infinitely long bearing: no side leakage (zero-flux ends, one axial cell); loads are "
                  "for the length L");
    cmd->add_flag("--no-groove", a->noGroove,
                  "No supply groove (default: a full-length axial groove at the maximum film, theta = 0, "
                  "at ambient pressure 0, as in Raimondi-Boyd)");
    cmd->add_option("--tolerance", a->tolerance, "Relative natural residual to stop at [-]")->capture_default_str();
    cmd->add_option("--omega", a->omega, "Over-relaxation of psor and jfo in (0, 2) [-]; 0 = automatic")
        ->capture_default_str();
    cmd->add_flag("--json", a->json, "Print one JSON object on stdout instead of the table");
    cmd->callback([a] { runBearing(*a); });
}

}  // namespace flexehd::cli
