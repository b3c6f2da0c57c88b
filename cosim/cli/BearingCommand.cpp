// `flexehd bearing`: the options as a lube::JournalBearing, its solution as a table or JSON.
#include <optional>
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include <spdlog/spdlog.h>

#include "cosim/coupling/MemoryBudget.hpp"
#include "cosim/cli/CliSupport.hpp"
#include "cosim/cli/Commands.hpp"
#include "lube/JournalBearing.hpp"

namespace flexehd::cli {
namespace {

struct BearingArgs {
    double radius = 0.05;
    std::optional<double> length;              // not given: from --length-over-diameter
    std::optional<double> lengthOverDiameter;  // not given: 1
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
    double grooveAngle = 0.0;     // deg from the maximum film
    double supplyFraction = 1.0;  // film fraction of the groove's oil
    bool json = false;
};

lube::BearingCavitation parseCavitation(const std::string& s) {
    if (s == "none" || s == "full-sommerfeld") return lube::BearingCavitation::FullSommerfeld;
    if (s == "half-sommerfeld") return lube::BearingCavitation::HalfSommerfeld;
    if (s == "reynolds") return lube::BearingCavitation::Reynolds;
    if (s == "jfo") return lube::BearingCavitation::MassConserving;
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

constexpr double kToleranceFloor = 1e-14;

void requirePositive(double v, const char* what) {
    if (!(v > 0.0) || !std::isfinite(v))
        throw std::invalid_argument(std::string(what) + " must be positive and finite (got " + str(v) + ")");
}

// The options as a bearing specification; every message names the option.
lube::JournalBearingSpec bearingSpec(const BearingArgs& a) {
    requirePositive(a.radius, "--radius");
    requirePositive(a.clearance, "--clearance");
    requirePositive(a.speed, "--speed");
    requirePositive(a.viscosity, "--viscosity");
    requirePositive(a.tolerance, "--tolerance");
    // The residual is relative: below about 100 ulp it is rounding noise, which no iteration lowers.
    if (a.tolerance < kToleranceFloor)
        throw std::invalid_argument("--tolerance " + str(a.tolerance) +
                                    " is below what double precision can reach (the residual is relative: about " +
                                    str(kToleranceFloor) + " is the least an iteration can reach); give " +
                                    str(kToleranceFloor) + " or more");
    if (!(a.omega == 0.0 || (a.omega > 0.0 && a.omega < 2.0)))
        throw std::invalid_argument("--omega must be in (0, 2), or 0 for automatic");
    if (!(a.eccentricity > 0.0 && a.eccentricity < 1.0))
        throw std::invalid_argument("--eccentricity must be in (0, 1), the journal touches the sleeve at 1 (got " +
                                    str(a.eccentricity) + ")");
    if (a.length && a.lengthOverDiameter)
        throw std::invalid_argument("give either --length or --length-over-diameter, not both");
    if (a.length) requirePositive(*a.length, "--length");
    if (a.lengthOverDiameter) requirePositive(*a.lengthOverDiameter, "--length-over-diameter");
    if (a.clearance >= a.radius)
        throw std::invalid_argument("--clearance must be smaller than --radius");
    lube::JournalBearingSpec s;
    s.cavitation = parseCavitation(a.cavitation);
    s.solver = parseSolver(a.solver);
    const auto [nTheta, nZ] = parseGrid(a.grid);
    cosim::requireFilmMemory("--grid " + a.grid, nTheta, nZ, 0);  // reads as NTHETA × NZ
    if (s.cavitation == lube::BearingCavitation::MassConserving && a.noGroove)
        throw std::invalid_argument("--cavitation jfo needs the supply groove (drop --no-groove): "
                                    "a mass-conserving film without a supply drains dry");
    if (a.infinitelyLong && a.noGroove)
        throw std::invalid_argument("--infinitely-long needs the groove as its pressure datum (drop --no-groove)");
    if (!(a.grooveAngle >= 0.0 && a.grooveAngle < 360.0))
        throw std::invalid_argument("--groove-angle must be in [0, 360) deg from the maximum film (got " +
                                    str(a.grooveAngle) + ")");
    if (!(a.supplyFraction > 0.0 && a.supplyFraction <= 1.0))
        throw std::invalid_argument("--supply-fraction must be in (0, 1]: the share of the gap the supplied oil fills "
                                    "(got " + str(a.supplyFraction) + ")");
    if (a.supplyFraction < 1.0 && s.cavitation != lube::BearingCavitation::MassConserving)
        throw std::invalid_argument("--supply-fraction below 1 (a starved supply) needs --cavitation jfo: the other "
                                    "models take as much oil as the film wants");
    if (a.noGroove && (a.grooveAngle != 0.0 || a.supplyFraction < 1.0))
        throw std::invalid_argument("--groove-angle and --supply-fraction place and feed the groove: drop --no-groove");
    s.radius = a.radius;
    s.clearance = a.clearance;
    s.eccentricity = a.eccentricity;
    s.speed = a.speed;
    s.viscosity = a.viscosity;
    s.length = a.length ? *a.length : a.lengthOverDiameter.value_or(1.0) * 2 * a.radius;
    s.infinitelyLong = a.infinitelyLong;
    s.supplyGroove = !a.noGroove;
    s.grooveAngleDeg = a.grooveAngle;
    s.supplyFraction = a.supplyFraction;
    s.circumferentialNodes = nTheta;
    s.axialNodes = nZ;
    s.tolerance = a.tolerance;
    s.omega = a.omega;
    return s;
}

nlohmann::json resultJson(const lube::JournalBearingSpec& s, const lube::JournalBearingResult& r) {
    nlohmann::json doc;
    doc["input"] = {{"radius_m", s.radius},
                    {"length_m", s.length},
                    {"length_over_diameter", s.length / (2 * s.radius)},
                    {"infinitely_long", s.infinitelyLong},
                    {"supply_groove", s.supplyGroove},
                    {"groove_angle_deg", r.grooveAngleDeg},
                    {"supply_fraction", s.supplyFraction},
                    {"clearance_m", s.clearance},
                    {"eccentricity", s.eccentricity},
                    {"speed_rev_s", s.speed},
                    {"viscosity_pa_s", s.viscosity},
                    {"cavitation", lube::name(s.cavitation)},
                    {"solver", r.solverName},
                    {"grid", {{"circumferential", s.circumferentialNodes}, {"axial", r.axialNodes}}},
                    {"tolerance", s.tolerance}};
    doc["load_n"] = r.load;
    doc["load_components_n"] = {{"along_line_of_centres", r.loadAlongLineOfCentres},
                                {"perpendicular", r.loadPerpendicular}};
    doc["specific_load_pa"] = r.specificLoad;
    doc["attitude_deg"] = r.attitudeDeg;
    doc["sommerfeld"] = r.sommerfeld;
    doc["friction_torque_nm"] = r.frictionTorque;
    doc["friction_power_w"] = r.frictionPower;
    doc["friction_coefficient"] = r.frictionCoefficient;
    doc["friction_variable"] = r.frictionVariable;
    doc["inlet_flow_m3_s"] = r.inletFlow;
    doc["return_flow_m3_s"] = r.returnFlow;
    doc["side_flow_m3_s"] = r.sideFlow;
    doc["flow_variable"] = r.flowVariable;
    doc["side_flow_ratio"] = r.sideFlow / r.inletFlow;
    doc["max_pressure_pa"] = r.maxPressure;
    doc["max_pressure_ratio"] = r.maxPressureRatio;
    doc["min_film_m"] = r.minFilm;
    doc["cavitated_area_m2"] = r.cavitatedArea;
    doc["cavitated_fraction"] = r.cavitatedFraction;
    doc["iterations"] = r.iterations;
    doc["coarse_iterations"] = r.coarseIterations;
    doc["residual"] = r.residual;
    doc["seconds"] = r.solveSeconds;
    const lube::FilmResolution& fr = r.resolution;
    doc["grid_resolution"] = {{"min_region_width_deg", fr.regionWidthDeg},
                              {"nodes_across_min_region", fr.nodesAcross},
                              {"needed_circumferential_nodes", fr.neededCircumferentialNodes},
                              {"resolved", fr.resolved},
                              {"expected_load_deficit", fr.expectedLoadDeficit}};
    return doc;
}

// Refuses a result with a non-finite number: the inputs are beyond what double precision resolves
// (a length or clearance of 1e-300 m, a speed of 1e300 rev/s), and nan or inf tells nothing.
void requireFiniteResult(const lube::JournalBearingResult& r) {
    const std::pair<const char*, double> figures[] = {
        {"load", r.load}, {"attitude angle", r.attitudeDeg}, {"Sommerfeld number", r.sommerfeld},
        {"friction torque", r.frictionTorque}, {"friction power", r.frictionPower},
        {"friction coefficient", r.frictionCoefficient}, {"friction variable", r.frictionVariable},
        {"inlet flow", r.inletFlow}, {"return flow", r.returnFlow}, {"side flow", r.sideFlow},
        {"flow variable", r.flowVariable}, {"max pressure", r.maxPressure},
        {"pressure ratio", r.maxPressureRatio}, {"min film", r.minFilm}, {"cavitated area", r.cavitatedArea},
        {"cavitated fraction", r.cavitatedFraction}, {"residual", r.residual}};
    std::string bad;
    for (const auto& [what, v] : figures)
        if (!std::isfinite(v)) bad += (bad.empty() ? "" : ", ") + std::string(what);
    if (!bad.empty())
        throw std::runtime_error("the result is not finite (" + bad +
                                 "): the inputs are beyond what double precision resolves; check the magnitudes "
                                 "of --radius, --length, --clearance, --speed and --viscosity (SI units: m, rev/s, "
                                 "Pa s)");
}

// The largest circumferential grid the command offers to solve: 65536 × 33 nodes take about
// 0.1 GB and a few seconds with multigrid (docs/lube.md §8); a minimum film that needs more is
// beyond what a grid can resolve (and far below any real surface roughness).
constexpr int kMaxCircumferentialNodes = 65536;
constexpr int kDefaultCircumferentialNodes = 128;

std::string fixed(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

// A measured load deficit as a percentage: "more than 99", "35", "3.6".
std::string percentText(double deficit) {
    if (deficit > 0.99) return "more than 99";
    return deficit >= 0.1 ? fixed(100 * deficit, 0) : fixed(100 * deficit, 1);
}

// "0.981", "0.99999993": ε with enough digits to differ from 1.
std::string eccentricityText(double e) {
    const int digits = std::max(3, int(std::ceil(-std::log10(1 - e))) + 1);
    return fixed(std::floor(e * std::pow(10.0, digits)) / std::pow(10.0, digits), digits);
}

// The film's minimum region against the grid (docs/lube.md §8): refuses when no grid the command
// solves resolves it, or when the given grid sees less than one node across it (the load would be
// 70–100 % low: meaningless); warns when fewer than kMinFilmRegionNodes span it.
void checkFilmResolution(const lube::JournalBearingSpec& s, const std::string& gridText) {
    const lube::FilmResolution fr = lube::filmResolution(s.eccentricity, s.circumferentialNodes);
    if (fr.resolved) return;
    const std::string region = "the film's minimum region (h < 2 h_min, " + str(fr.regionWidthDeg) + " deg wide)";
    const int nz = s.axialNodes;
    if (fr.neededCircumferentialNodes > kMaxCircumferentialNodes)
        throw std::invalid_argument(
            "--eccentricity " + str(s.eccentricity) + ": " + region + " needs NTHETA >= " +
            fixed(fr.neededCircumferentialNodes, 0) + " circumferential nodes (" + str(lube::kMinFilmRegionNodes) +
            " across it) for a grid-converged load, more than the largest grid this command solves (NTHETA " +
            std::to_string(kMaxCircumferentialNodes) +
            "): the eccentricity is beyond what a grid can resolve (the minimum film is " + str(1 - s.eccentricity) +
            " of the clearance). The default grid (" + std::to_string(kDefaultCircumferentialNodes) +
            "x33) resolves eccentricities up to " +
            eccentricityText(lube::largestResolvedEccentricity(kDefaultCircumferentialNodes)) + ", the largest (" +
            std::to_string(kMaxCircumferentialNodes) + "x33) up to " +
            eccentricityText(lube::largestResolvedEccentricity(kMaxCircumferentialNodes)));
    const std::string needed = fixed(fr.neededCircumferentialNodes, 0);
    const std::string advice = "use --grid " + needed + "x" + std::to_string(nz) + " (NTHETA >= " + needed + ")";
    const std::string deficit = percentText(fr.expectedLoadDeficit);
    if (fr.nodesAcross < 1.0)
        throw std::invalid_argument("--grid " + gridText + " at --eccentricity " + str(s.eccentricity) + ": " + region +
                                    " falls between two grid nodes (" + fixed(fr.nodesAcross, 2) +
                                    " circumferential nodes across it); the load would be meaningless (measured: " +
                                    deficit + " % low); " + advice);
    spdlog::warn("{} is spanned by only {} circumferential nodes; the load is not grid-converged (expect it about {} % "
                 "low); {}",
                 region, fixed(fr.nodesAcross, 1), deficit, advice);
}

void printTable(const lube::JournalBearingSpec& s, const lube::JournalBearingResult& r, double totalSeconds) {
    const double D = 2 * s.radius;
    std::printf("journal bearing: R = %g m, L = %g m (L/D = %g%s), c = %g m, eps = %g, N = %g rev/s, mu = %g Pa s\n",
                s.radius, s.length, s.length / D, s.infinitelyLong ? ", infinitely long" : "", s.clearance,
                s.eccentricity, s.speed, s.viscosity);
    std::printf("%s cavitation, %s solver, grid %dx%d (theta x z)", lube::name(s.cavitation), r.solverName.c_str(),
                s.circumferentialNodes, r.axialNodes);
    if (s.supplyGroove)
        std::printf(", groove at %g deg from the maximum film%s", r.grooveAngleDeg,
                    s.supplyFraction < 1.0 ? (", starved supply: film fraction " + str(s.supplyFraction)).c_str() : "");
    std::printf("\n\n");
    auto row = [](const char* what, double v, const char* unit) {
        std::printf("  %-34s %14.6g  %s\n", what, v, unit);
    };
    row("load W", r.load, "N");
    row("specific load P = W/(LD)", r.specificLoad, "Pa");
    row("attitude angle", r.attitudeDeg, "deg");
    row("Sommerfeld number (R/c)^2 mu N/P", r.sommerfeld, "-");
    row("friction torque on journal", r.frictionTorque, "N m");
    row("friction power", r.frictionPower, "W");
    row("friction coefficient f", r.frictionCoefficient, "-");
    row("friction variable (R/c) f", r.frictionVariable, "-");
    row("inlet flow Q", r.inletFlow, "m^3/s");
    row("return flow into the groove", r.returnFlow, "m^3/s");
    row("side flow Qs", r.sideFlow, "m^3/s");
    row("flow variable Q/(R c N L)", r.flowVariable, "-");
    row("max pressure", r.maxPressure, "Pa");
    row("pressure ratio P/p_max", r.maxPressureRatio, "-");
    row("min film", r.minFilm, "m");
    row("cavitated area", r.cavitatedArea, "m^2");
    row("cavitated fraction", r.cavitatedFraction, "-");
    if (!r.resolution.resolved)
        std::printf("\n  NOT GRID-CONVERGED: %.2g circumferential nodes across the minimum film region (h < 2 h_min, "
                    "%.3g deg wide); the load is about %s %% low; use NTHETA >= %.0f\n",
                    r.resolution.nodesAcross, r.resolution.regionWidthDeg,
                    percentText(r.resolution.expectedLoadDeficit).c_str(),
                    r.resolution.neededCircumferentialNodes);
    std::printf("\n  %d iterations (%d coarse), residual %.2e, solve %.3f s, total %.3f s\n", r.iterations,
                r.coarseIterations, r.residual, r.solveSeconds, totalSeconds);
}

void runBearing(const BearingArgs& a) {
    Stopwatch total;
    const lube::JournalBearingSpec s = bearingSpec(a);
    const lube::JournalBearing bearing(s);
    checkFilmResolution(s, a.grid);
    spdlog::info("journal bearing R = {} m, L = {} m{}, c = {} m, eps = {}, N = {} rev/s, mu = {} Pa s", s.radius,
                 s.length, s.infinitelyLong ? " (infinitely long)" : "", s.clearance, s.eccentricity, s.speed,
                 s.viscosity);
    if (s.cavitation == lube::BearingCavitation::MassConserving && s.solver == lube::SolverKind::Multigrid &&
        a.solver != "fast")
        spdlog::warn("--cavitation jfo has no multigrid method: using the active-set method");
    spdlog::info("solving: {} cavitation, {} solver, grid {}x{} (theta x z)", lube::name(s.cavitation),
                 bearing.methodName(), s.circumferentialNodes, s.infinitelyLong ? 2 : s.axialNodes);
    const lube::JournalBearingResult r = bearing.solve();
    requireFiniteResult(r);
    spdlog::info("solved: {} iterations ({} on coarse grids), residual {:.2e}, {:.3f} s", r.iterations,
                 r.coarseIterations, r.residual, r.solveSeconds);
    if (a.json) {
        nlohmann::json doc = resultJson(s, r);
        doc["total_seconds"] = total.seconds();
        doc["peak_memory_mib"] = peakMemoryMiB();
        printJson(doc);
    } else {
        printTable(s, r, total.seconds());
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
    cmd->add_option("--groove-angle", a->grooveAngle,
                    "Where the supply groove is, from the maximum film in the direction of rotation [deg], "
                    "in [0, 360); the nearest grid column")
        ->capture_default_str();
    cmd->add_option("--supply-fraction", a->supplyFraction,
                    "Film fraction of the oil the groove supplies, in (0, 1] [-]: below 1 a starved supply "
                    "(with --cavitation jfo)")
        ->capture_default_str();
    cmd->add_option("--tolerance", a->tolerance, "Relative natural residual to stop at [-]")->capture_default_str();
    cmd->add_option("--omega", a->omega, "Over-relaxation of psor and jfo in (0, 2) [-]; 0 = automatic")
        ->capture_default_str();
    cmd->add_flag("--json", a->json, "Print one JSON object on stdout instead of the table");
    cmd->callback([a] { runBearing(*a); });
}

}  // namespace flexehd::cli
