#include "cosim/results/RunSummary.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>

#include "cosim/contact/SkirtContact.hpp"
#include "cosim/results/CycleMetrics.hpp"

namespace flexehd::cosim {
namespace {

using Json = nlohmann::json;

struct Source {
    const RunSummaryInput& in;
    std::optional<CycleMetrics> m;  // with two records or more
    std::array<ClearanceRange, 3> centred;  // at TDC, mid-stroke, BDC (computed once)
    const RunStatistics& st() const { return in.sim.statistics(); }
};

struct Entry {
    const char* key;  // dotted for nested objects
    std::function<Json(const Source&)> value;  // null: not written
};

// The cycle figures: summary.json's key and its value of a cycle's CycleMetrics.
struct Figure {
    const char* key;
    double (*value)(const CycleMetrics&);
};

const std::vector<Figure>& figures() {
    static const std::vector<Figure> f{
        {"friction_power_mean_w", [](const CycleMetrics& m) { return m.frictionPowerMean; }},
        {"boundary_friction_power_mean_w", [](const CycleMetrics& m) { return m.boundaryFrictionPowerMean; }},
        {"friction_energy_per_cycle_j", [](const CycleMetrics& m) { return m.frictionEnergy; }},
        {"fmep_pa", [](const CycleMetrics& m) { return m.fmep; }},
        {"slap_kinetic_energy_max_j", [](const CycleMetrics& m) { return m.slapEnergyMax; }},
        {"slap_kinetic_energy_max_crank_deg", [](const CycleMetrics& m) { return m.slapEnergyDeg; }},
        {"lateral_min_m", [](const CycleMetrics& m) { return m.lateralMin; }},
        {"lateral_max_m", [](const CycleMetrics& m) { return m.lateralMax; }},
        {"tilt_min_rad", [](const CycleMetrics& m) { return m.tiltMin; }},
        {"tilt_max_rad", [](const CycleMetrics& m) { return m.tiltMax; }},
        {"min_film_m", [](const CycleMetrics& m) { return m.minFilm; }},
        {"min_film_crank_deg", [](const CycleMetrics& m) { return m.minFilmDeg; }},
        {"max_pressure_pa", [](const CycleMetrics& m) { return m.maxPressure; }},
        {"min_film_region_nodes.circumferential", [](const CycleMetrics& m) { return double(m.minFilmNodesCircumferential); }},
        {"min_film_region_nodes.circumferential_crank_deg",
         [](const CycleMetrics& m) { return m.minFilmNodesCircumferentialDeg; }},
        {"min_film_region_nodes.axial", [](const CycleMetrics& m) { return double(m.minFilmNodesAxial); }},
        {"min_film_region_nodes.axial_crank_deg", [](const CycleMetrics& m) { return m.minFilmNodesAxialDeg; }},
        {"contact_force_max_n", [](const CycleMetrics& m) { return m.contactForceMax; }},
        {"hard_contact_force_max_n", [](const CycleMetrics& m) { return m.hardContactForceMax; }},
        {"side_force_max_n", [](const CycleMetrics& m) { return m.sideForceMax; }},
    };
    return f;
}

// A cycle figure: written when the last cycle has two records or more.
Entry metric(const Figure& f) {
    return {f.key, [v = f.value](const Source& s) { return s.m ? Json(v(*s.m)) : Json(); }};
}

// The undeformed film with the piston centred (the hot running clearance with a thermal file)
// at TDC, mid-stroke and BDC: centred_clearance_m.{tdc,mid_stroke,bdc}.{min,mean,max}.
void addCentredClearance(std::vector<Entry>& table) {
    static const char* const keys[3][3] = {
        {"centred_clearance_m.tdc.min", "centred_clearance_m.tdc.mean", "centred_clearance_m.tdc.max"},
        {"centred_clearance_m.mid_stroke.min", "centred_clearance_m.mid_stroke.mean", "centred_clearance_m.mid_stroke.max"},
        {"centred_clearance_m.bdc.min", "centred_clearance_m.bdc.mean", "centred_clearance_m.bdc.max"}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            table.push_back({keys[i][j], [i, j](const Source& s) {
                                 const ClearanceRange& r = s.centred[std::size_t(i)];
                                 return Json(j == 0 ? r.min : j == 1 ? r.mean : r.max);
                             }});
}

// The wear maxima are written once a cycle finished.
bool wearDone(const Source& s) { return s.in.wear && s.in.wear->finished(); }

// A figure of the liner's vibration report (acoustics.json), once a cycle's record was written.
Json acousticsFigure(const Source& s, const char* pointer) {
    return s.in.acoustics ? s.in.acoustics->value(Json::json_pointer(pointer), Json()) : Json();
}

// Where in the cycle the last two cycles differ: per sector of crank angle, its range and error.
Json periodicityBySector(const RunStatistics& st) {
    Json sectors = Json::array();
    const double width = RunStatistics::kPeriodicitySectorDeg;
    for (std::size_t k = 0; k < st.periodicityErrorBySector.size(); ++k)
        sectors.push_back({{"from_deg", width * double(k)},
                           {"to_deg", width * double(k + 1)},
                           {"error_m", st.periodicityErrorBySector[k]}});
    return sectors;
}

const char* bodyModel(BodyModel m) { return m == BodyModel::Flexible ? "flexible" : "rigid"; }

const std::vector<Entry>& entries() {
    static const std::vector<Entry> table = [] {
    std::vector<Entry> t = {
        {"status", [](const Source& s) { return Json(s.in.status); }},
        {"message", [](const Source& s) { return s.in.message.empty() ? Json() : Json(s.in.message); }},
        {"case", [](const Source& s) { return Json(s.in.c.path); }},
        {"name", [](const Source& s) { return Json(s.in.c.name); }},
        {"bodies.piston", [](const Source& s) { return Json(bodyModel(s.in.c.pistonBody.model)); }},
        {"bodies.liner", [](const Source& s) { return Json(bodyModel(s.in.c.linerBody.model)); }},
        {"cycle", [](const Source& s) { return s.m ? Json(s.in.cycle.back().cycle) : Json(); }},
    };
    for (const Figure& f : figures()) t.push_back(metric(f));
    t.insert(t.end(), {
        {"cycles", [](const Source& s) { return Json(s.st().cycles); }},
        {"periodic", [](const Source& s) { return Json(s.st().periodic); }},
        {"periodicity_error_m", [](const Source& s) { return Json(s.st().periodicityError); }},
        {"periodicity_tolerance_m", [](const Source& s) { return Json(s.in.c.time.periodicityTolerance); }},
        {"periodicity_error_by_sector", [](const Source& s) { return periodicityBySector(s.st()); }},
        {"wear.piston_rate_max_m_per_h", [](const Source& s) { return wearDone(s) ? Json(s.in.wear->maxima().pistonRate) : Json(); }},
        {"wear.piston_max_z_m", [](const Source& s) { return wearDone(s) ? Json(s.in.wear->maxima().pistonZ) : Json(); }},
        {"wear.piston_max_theta_deg", [](const Source& s) { return wearDone(s) ? Json(s.in.wear->maxima().pistonThetaDeg) : Json(); }},
        {"wear.liner_rate_max_m_per_h", [](const Source& s) { return wearDone(s) ? Json(s.in.wear->maxima().linerRate) : Json(); }},
        {"wear.liner_max_depth_m", [](const Source& s) { return wearDone(s) ? Json(s.in.wear->maxima().linerDepth) : Json(); }},
        {"wear.liner_max_theta_deg", [](const Source& s) { return wearDone(s) ? Json(s.in.wear->maxima().linerThetaDeg) : Json(); }},
        {"acoustics.erp_total_w", [](const Source& s) { return acousticsFigure(s, "/erp/total_w"); }},
        {"acoustics.erp_total_db", [](const Source& s) { return acousticsFigure(s, "/erp/total_db"); }},
        {"acoustics.velocity_rms_m_per_s", [](const Source& s) { return acousticsFigure(s, "/velocity/rms_m_per_s"); }},
        {"acoustics.sample_rate_hz", [](const Source& s) { return acousticsFigure(s, "/record/sample_rate_hz"); }},
        {"acoustics.liner_input_power_w", [](const Source& s) { return acousticsFigure(s, "/energy/input_power_mean_w"); }},
        {"acoustics.max_step_deg",
         [](const Source& s) { return s.in.c.acoustics.enabled ? Json(s.in.c.time.maxStepDeg) : Json(); }},
        {"oil.liner_volume_m3", [](const Source& s) { return s.st().oil ? Json(s.st().linerOil) : Json(); }},
        {"oil.film_volume_m3", [](const Source& s) { return s.st().oil ? Json(s.st().filmOil) : Json(); }},
        {"oil.periodicity_error", [](const Source& s) { return s.st().oil ? Json(s.st().oilPeriodicityError) : Json(); }},
        {"oil.periodicity_tolerance",
         [](const Source& s) { return s.st().oil ? Json(s.in.c.time.oilPeriodicityTolerance) : Json(); }},
        {"oil.replenished_per_cycle_m3", [](const Source& s) { return s.st().oil ? Json(s.st().replenishedOil) : Json(); }},
        {"oil.side_leakage_per_cycle_m3", [](const Source& s) { return s.st().oil ? Json(s.st().leakedOil) : Json(); }},
        {"iterations.steps", [](const Source& s) { return Json(s.st().steps); }},
        {"iterations.rejected_steps", [](const Source& s) { return Json(s.st().rejectedSteps); }},
        {"iterations.film_solves", [](const Source& s) { return Json(s.st().filmSolves); }},
        {"iterations.jacobians", [](const Source& s) { return Json(s.st().jacobians); }},
        {"iterations.fallback_film_solves", [](const Source& s) { return Json(s.st().fallbackSolves); }},
        {"iterations.resolved_steps", [](const Source& s) { return Json(s.st().resolvedSteps); }},
        {"iterations.film_solves_per_step_mean",
         [](const Source& s) {
             const RunStatistics& st = s.st();
             return Json(st.steps > 0 ? double(st.filmSolves) / double(st.steps) : 0.0);
         }},
        {"iterations.film_solves_per_step_max", [](const Source& s) { return Json(s.st().maxIterations); }},
        {"iterations.smallest_step_deg", [](const Source& s) { return Json(s.st().minStepDeg); }},
        {"load_mapping_conservation_error_max", [](const Source& s) { return Json(s.st().worstMappingError); }},
        {"timings_s.setup", [](const Source& s) { return Json(s.st().timings.setup); }},
        {"timings_s.film", [](const Source& s) { return Json(s.st().timings.film); }},
        {"timings_s.structure", [](const Source& s) { return Json(s.st().timings.structure); }},
        {"timings_s.mapping", [](const Source& s) { return Json(s.st().timings.mapping); }},
        {"timings_s.modal", [](const Source& s) { return Json(s.st().timings.modal); }},
        {"timings_s.dynamics",
         [](const Source& s) { return Json(std::max(0.0, s.st().timings.dynamics - s.in.outputInRun)); }},
        {"timings_s.output", [](const Source& s) { return Json(s.in.outputSeconds + s.in.outputInRun); }},
        {"timings_s.total", [](const Source& s) { return Json(s.in.totalSeconds); }},
    });
    addCentredClearance(t);
    return t;
    }();
    return table;
}

// "a.b" → JSON pointer "/a/b".
Json::json_pointer pointer(const std::string& dotted) {
    std::string p = "/" + dotted;
    std::replace(p.begin(), p.end(), '.', '/');
    return Json::json_pointer(p);
}

// A figure of column k of the records' contact values over the cycle (at least two records).
Json columnFigure(const std::vector<StepRecord>& cycle, std::size_t k, CycleStatistic statistic, double volume) {
    double least = cycle.front().contactValues[k], largest = least, integral = 0.0;
    const bool departing = statistic == CycleStatistic::Departures || statistic == CycleStatistic::DepartureAngles;
    Json departures = Json::array();
    for (std::size_t i = 1; i < cycle.size(); ++i) {
        const double v = cycle[i].contactValues[k];
        if (departing && cycle[i - 1].contactValues[k] <= 0.0 && v > 0.0) departures.push_back(cycle[i].crankDeg);
        least = std::min(least, v);
        largest = std::max(largest, v);
        integral += 0.5 * (v + cycle[i - 1].contactValues[k]) * (cycle[i].time - cycle[i - 1].time);
    }
    const double duration = cycle.back().time - cycle.front().time;
    switch (statistic) {
        case CycleStatistic::Minimum: return least;
        case CycleStatistic::Maximum: return largest;
        case CycleStatistic::Mean: return duration > 0.0 ? integral / duration : cycle.front().contactValues[k];
        case CycleStatistic::Fmep: return integral / volume;
        case CycleStatistic::Departures: return static_cast<double>(departures.size());
        case CycleStatistic::DepartureAngles: return departures;
    }
    return 0.0;
}

// The further contacts' figures (ContactColumns.hpp) of the last cycle, when it has two records;
// with contacts' friction mean effective pressures, their sum with the skirt's as fmep_total_pa.
void addContactFigures(const RunSummaryInput& in, Json& d) {
    if (in.cycle.size() < 2) return;
    const std::vector<ContactColumn> columns = in.sim.contactColumns();
    const double volume = sweptVolume(in.c.engine);
    bool fmep = false;
    double total = d.contains("fmep_pa") ? d["fmep_pa"].get<double>() : 0.0;
    for (std::size_t k = 0; k < columns.size(); ++k)
        for (const ColumnFigure& f : columns[k].figures) {
            if (d.contains(pointer(f.key)))
                throw std::logic_error("summary.json: the contact figure '" + f.key + "' repeats a key");
            const Json value = columnFigure(in.cycle, k, f.statistic, volume);
            d[pointer(f.key)] = value;
            if (f.statistic == CycleStatistic::Fmep) {
                fmep = true;
                total += value.get<double>();
            }
        }
    if (fmep) d["fmep_total_pa"] = total;
}

// A run that did not become periodic: each cycle figure's mean, least, largest value and standard
// deviation over the cycles after the first (the start's transient), when there are two or more.
void addCycleToCycle(const RunSummaryInput& in, Json& d) {
    if (!in.cycles || in.sim.statistics().periodic) return;
    std::vector<const CycleSeries::Cycle*> used;
    for (const CycleSeries::Cycle& c : in.cycles->cycles())
        if (c.number > 1) used.push_back(&c);
    if (used.size() < 2) return;
    Json& out = d["cycle_to_cycle"];
    for (const CycleSeries::Cycle* c : used) out["cycles"].push_back(c->number);
    const double n = static_cast<double>(used.size());
    for (const Figure& f : figures()) {
        double sum = 0.0, least = f.value(used.front()->metrics), largest = least;
        for (const CycleSeries::Cycle* c : used) {
            const double v = f.value(c->metrics);
            sum += v;
            least = std::min(least, v);
            largest = std::max(largest, v);
        }
        const double mean = sum / n;
        double squares = 0.0;
        for (const CycleSeries::Cycle* c : used) squares += (f.value(c->metrics) - mean) * (f.value(c->metrics) - mean);
        out[f.key] = {{"mean", mean}, {"min", least}, {"max", largest}, {"std", std::sqrt(squares / n)}};
    }
}

}  // namespace

nlohmann::json runSummary(const RunSummaryInput& in) {
    Source s{in, std::nullopt, {}};
    const double crankDeg[3] = {0.0, 90.0, 180.0};
    const SkirtContact& skirt = in.sim.contact<SkirtContact>();
    for (int i = 0; i < 3; ++i) s.centred[std::size_t(i)] = skirt.centredClearance(in.sim.linerOffset(crankDeg[i]));
    if (in.cycle.size() >= 2) {
        s.m = cycleMetrics(in.cycle, in.sim.dynamics(), sweptVolume(in.c.engine));
    }
    Json d = Json::object();
    for (const Entry& e : entries()) {
        Json v = e.value(s);
        if (!v.is_null()) d[pointer(e.key)] = std::move(v);
    }
    addContactFigures(in, d);
    addCycleToCycle(in, d);
    return d;
}

const std::vector<std::string>& runSummaryKeys() {
    static const std::vector<std::string> keys = [] {
        std::vector<std::string> k;
        for (const Entry& e : entries()) k.push_back(e.key);
        // A non-periodic run's spread over its cycles (addCycleToCycle).
        for (const Figure& f : figures())
            for (const char* statistic : {"mean", "min", "max", "std"})
                k.push_back(std::string("cycle_to_cycle.") + f.key + "." + statistic);
        return k;
    }();
    return keys;
}

}  // namespace flexehd::cosim
