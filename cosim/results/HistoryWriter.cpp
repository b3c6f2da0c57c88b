#include "cosim/results/HistoryWriter.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "cosim/io/TextTable.hpp"

namespace flexehd::cosim {
namespace {

// One column of history.csv: its header name and the StepRecord member it holds (exactly one
// of `real`, `integer` is set). The single table drives the header, append() and read().
struct Column {
    const char* name;
    double StepRecord::*real;
    int StepRecord::*integer;
    bool oil = false;  // a column of the mass-conserving film only
};

const std::vector<Column>& table() {
    static const std::vector<Column> t{
        {"cycle", nullptr, &StepRecord::cycle},
        {"crank_deg", &StepRecord::crankDeg, nullptr},
        {"time_s", &StepRecord::time, nullptr},
        {"lateral_m", &StepRecord::lateral, nullptr},
        {"tilt_rad", &StepRecord::tilt, nullptr},
        {"lateral_velocity_m_per_s", &StepRecord::lateralVelocity, nullptr},
        {"tilt_rate_rad_per_s", &StepRecord::tiltRate, nullptr},
        {"side_force_n", &StepRecord::sideForce, nullptr},
        {"film_force_n", &StepRecord::filmForce, nullptr},
        {"film_moment_n_m", &StepRecord::filmMoment, nullptr},
        {"contact_force_n", &StepRecord::contactForce, nullptr},
        {"hard_contact_force_n", &StepRecord::hardContactForce, nullptr},
        {"friction_force_n", &StepRecord::frictionForce, nullptr},
        {"liner_friction_hydrodynamic_n", &StepRecord::linerHydrodynamicFriction, nullptr},
        {"liner_friction_boundary_n", &StepRecord::linerBoundaryFriction, nullptr},
        {"dissipated_power_w", &StepRecord::dissipatedPower, nullptr},
        {"boundary_friction_power_w", &StepRecord::boundaryFrictionPower, nullptr},
        {"cylinder_pressure_pa", &StepRecord::cylinderPressure, nullptr},
        {"min_film_m", &StepRecord::minFilm, nullptr},
        {"max_pressure_pa", &StepRecord::maxPressure, nullptr},
        {"elastic_film_change_m", &StepRecord::elasticFilmChange, nullptr},
        {"oil_in_m3_per_s", &StepRecord::oilIn, nullptr, true},
        {"oil_out_m3_per_s", &StepRecord::oilOut, nullptr, true},
        {"side_leakage_m3_per_s", &StepRecord::sideLeakage, nullptr, true},
        {"film_oil_m3", &StepRecord::filmOil, nullptr, true},
        {"wetted_share", &StepRecord::wettedShare, nullptr, true},
        {"liner_oil_m3", &StepRecord::linerOil, nullptr, true},
        {"replenished_oil_m3", &StepRecord::replenishedOil, nullptr, true},
        {"coupling_iterations", nullptr, &StepRecord::couplingIterations},
        {"step_deg", &StepRecord::stepDeg, nullptr},
    };
    return t;
}

constexpr const char* kComments =
    "# flexehd history: one line per accepted time step; columns, units and signs in "
    "docs/results-format.md\n"
    "# units: SI, named by each column's suffix (_m, _s, _rad, _m_per_s, _rad_per_s, _n, _n_m, _w, _pa); "
    "crank_deg and step_deg in degrees, crank_deg 0-720 within the cycle (0 = gas-exchange TDC, "
    "360 = firing TDC); max_pressure_pa is gauge (relative to the crankcase), cylinder_pressure_pa absolute\n"
    "# signs: forces and moments act ON the piston (liner_friction_* ON the liner), cylinder frame (+x major thrust side, +z towards "
    "the head, y pin axis); lateral > 0 towards +x; tilt about +y, > 0 = top of the piston towards "
    "+x; moments about the pin axis (+y)\n";

}  // namespace

const std::vector<std::string>& HistoryWriter::columns(bool oil) {
    static const auto names = [](bool withOil) {
        std::vector<std::string> n;
        for (const auto& c : table())
            if (withOil || !c.oil) n.emplace_back(c.name);
        return n;
    };
    static const std::vector<std::string> base = names(false), all = names(true);
    return oil ? all : base;
}

namespace {

// The further contacts' column names, checked against the table's and each other.
std::vector<std::string> checkedContactColumns(bool oil, std::vector<std::string> contactColumns) {
    std::vector<std::string> names = HistoryWriter::columns(oil);
    for (const std::string& name : contactColumns) {
        if (name.empty() || name.find_first_of(", \t\r\n") != std::string::npos)
            throw std::invalid_argument("history column '" + name + "': a column name is not empty and has no comma or space");
        if (std::find(names.begin(), names.end(), name) != names.end())
            throw std::invalid_argument("history column '" + name + "' is there twice");
        names.push_back(name);
    }
    return contactColumns;
}

}  // namespace

HistoryWriter::HistoryWriter(const std::string& path, bool oilColumns, std::vector<std::string> contactColumns)
    : path_(path),
      oil_(oilColumns),
      contactColumns_(checkedContactColumns(oilColumns, std::move(contactColumns))),
      out_(path) {
    // The column names first, then the comments: numpy.genfromtxt(names=True) takes its names
    // from the first line and skips '#' lines after it, pandas.read_csv(comment='#') skips them.
    std::string header;
    for (std::size_t c = 0; c < table().size(); ++c) {
        if (table()[c].oil && !oil_) continue;
        if (c) header += ',';
        header += table()[c].name;
    }
    for (const std::string& name : contactColumns_) header += ',' + name;
    header += '\n';
    header += kComments;
    out_.append(header);
}

void HistoryWriter::append(const StepRecord& r) {
    // Check everything first: a refused record leaves no partial line behind.
    for (const auto& c : table())
        if (c.real && (oil_ || !c.oil) && !std::isfinite(r.*c.real))
            throw std::runtime_error(fmt::format("'{}': column '{}' is {} at crank angle {:.9g}° (cycle {}); "
                                                 "history rows must be finite",
                                                 path_, c.name, r.*c.real, r.crankDeg, r.cycle));
    if (r.contactValues.size() != contactColumns_.size())
        throw std::logic_error(fmt::format("'{}': a record with {} contact values for {} contact columns", path_,
                                           r.contactValues.size(), contactColumns_.size()));
    for (std::size_t k = 0; k < contactColumns_.size(); ++k)
        if (!std::isfinite(r.contactValues[k]))
            throw std::runtime_error(fmt::format("'{}': column '{}' is {} at crank angle {:.9g}° (cycle {}); "
                                                 "history rows must be finite",
                                                 path_, contactColumns_[k], r.contactValues[k], r.crankDeg, r.cycle));
    std::string line;
    line.reserve(320);
    auto out = std::back_inserter(line);
    for (std::size_t k = 0; k < table().size(); ++k) {
        const auto& c = table()[k];
        if (c.oil && !oil_) continue;
        if (k) line += ',';
        if (c.real)
            fmt::format_to(out, "{:.{}g}", r.*c.real, kSignificantDigits);
        else
            fmt::format_to(out, "{}", r.*c.integer);
    }
    for (double v : r.contactValues) fmt::format_to(out, ",{:.{}g}", v, kSignificantDigits);
    line += '\n';
    out_.append(line);
}

std::vector<StepRecord> HistoryWriter::read(const std::string& path, bool* partialLastLine) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open history file '" + path + "'");
    if (partialLastLine) *partialLastLine = false;

    std::vector<StepRecord> records;
    std::vector<int> columnOf;  // file column of each table() entry
    std::size_t fileColumns = 0;
    DataLines lines(in);
    while (lines.next()) {
        const int lineNumber = lines.number();
        if (!lines.terminated()) {  // a run killed in the middle of writing its last line
            if (columnOf.empty())
                throw std::runtime_error("'" + path + "': the header line (line " + std::to_string(lineNumber) +
                                         ") is incomplete");
            if (partialLastLine) *partialLastLine = true;
            break;
        }
        const auto fields = split(lines.text());
        if (columnOf.empty()) {  // the header
            fileColumns = fields.size();
            for (const auto& c : table()) {
                int found = -1;
                for (std::size_t f = 0; f < fields.size(); ++f)
                    if (fields[f] == c.name) found = static_cast<int>(f);
                if (found < 0 && c.oil) {  // a run with the Reynolds condition: no oil columns
                    columnOf.push_back(-1);
                    continue;
                }
                if (found < 0)
                    throw std::runtime_error("'" + path + "': header (line " + std::to_string(lineNumber) +
                                             ") has no column '" + c.name + "'; is this a flexehd history.csv?");
                columnOf.push_back(found);
            }
            continue;
        }
        if (fields.size() != fileColumns)
            throw std::runtime_error("'" + path + "' line " + std::to_string(lineNumber) + ": " +
                                     std::to_string(fields.size()) + " values, the header has " +
                                     std::to_string(fileColumns) + " columns");
        StepRecord r;
        for (std::size_t k = 0; k < table().size(); ++k) {
            const auto& c = table()[k];
            if (columnOf[k] < 0) continue;
            const std::string_view value = fields[static_cast<std::size_t>(columnOf[k])];
            const bool ok = c.real ? parseNumber(value, r.*c.real) : parseWhole(value, r.*c.integer);
            if (!ok)
                throw std::runtime_error("'" + path + "' line " + std::to_string(lineNumber) + ", column '" + c.name +
                                         "': '" + std::string(value) + "' is not " +
                                         (c.real ? "a finite number" : "an integer"));
        }
        records.push_back(r);
    }
    if (in.bad()) throw std::runtime_error("error reading '" + path + "'");
    if (columnOf.empty()) throw std::runtime_error("'" + path + "' has no header line (empty history file)");
    return records;
}

}  // namespace flexehd::cosim
