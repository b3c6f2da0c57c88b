#include "cosim/casefile/PressureTable.hpp"

#include <sstream>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "cosim/casefile/CaseValues.hpp"
#include "cosim/engine/CylinderPressure.hpp"
#include "cosim/io/TextTable.hpp"

namespace flexehd::cosim {

using casefile::readWholeFile;

std::vector<PressureSample> readPressureTable(const std::string& path) {
    std::string error;
    const std::string content = readWholeFile(path, error);
    if (!error.empty()) throw std::runtime_error(path + ": " + error);
    std::vector<PressureSample> samples;
    std::vector<int> lines;
    std::istringstream in(content);
    DataLines table(in);
    bool headerAllowed = true;
    while (table.next()) {
        const int lineNo = table.number();
        const std::string_view line = table.text();
        const std::vector<std::string_view> fields = splitFields(line);
        double angle = 0.0, pressure = 0.0;
        const bool firstIsNumber = !fields.empty() && parseNumber(fields[0], angle);
        if (headerAllowed && !firstIsNumber) {  // a header line
            headerAllowed = false;
            continue;
        }
        headerAllowed = false;
        if (fields.size() != 2 || !firstIsNumber || !parseNumber(fields[1], pressure))
            throw std::runtime_error(
                fmt::format("{}:{}: expected two numbers, crank angle in deg and absolute pressure in Pa, got '{}'",
                            path, lineNo, line));
        samples.push_back({angle, pressure});
        lines.push_back(lineNo);
    }
    try {
        const CylinderPressure check(samples);
        if (check.peak() < 1e4)
            throw std::runtime_error(
                fmt::format("{}: the peak pressure is {:g}: the table must hold absolute pressures in Pa (bar or MPa?)",
                            path, check.peak()));
    } catch (const PressureTableError& e) {
        if (e.sample() == PressureTableError::npos) throw std::runtime_error(path + ": " + e.reason());
        throw std::runtime_error(fmt::format("{}:{}: {}", path, lines[e.sample()], e.reason()));
    }
    return samples;
}

}  // namespace flexehd::cosim
