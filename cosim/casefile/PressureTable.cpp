#include "cosim/casefile/PressureTable.hpp"
#include "cosim/io/JsonText.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "cosim/casefile/CaseValues.hpp"
#include "cosim/engine/CylinderPressure.hpp"
#include "cosim/io/TextTable.hpp"

namespace flexehd::cosim {

using casefile::readWholeFile;

namespace {

constexpr double kMaxCylinderPressure = 50e6;  // Pa, absolute

// A byte no text table holds: NUL and the control characters other than tab, CR and LF.
bool binaryByte(unsigned char b) { return b == 0x7F || (b < 0x20 && b != '\t' && b != '\r' && b != '\n'); }

// Refuses content that is not text (an image, a spreadsheet's binary file), naming the first line
// with a binary byte; its bytes are not echoed.
void requireText(const std::string& path, const std::string& content) {
    int line = 1;
    std::size_t column = 1;
    for (const char ch : content) {
        const auto b = static_cast<unsigned char>(ch);
        if (binaryByte(b))
            throw std::runtime_error(fmt::format(
                "{} is not a text table: line {} holds the byte 0x{:02X} at column {} (a binary file?): expected "
                "lines of two numbers, crank angle in deg and absolute pressure in Pa, separated by a comma",
                path, line, b, column));
        if (ch == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
}

// The line for a message: control bytes (but tab) and bytes that are not valid UTF-8
// (invalidUtf8At) as \xNN.
std::string printable(std::string_view line) {
    const auto control = [](char c) {
        const auto b = static_cast<unsigned char>(c);
        return b == 0x7F || (b < 0x20 && b != '\t');
    };
    std::string out, rest(line);
    while (!rest.empty()) {
        const auto firstControl = static_cast<std::size_t>(std::find_if(rest.begin(), rest.end(), control) - rest.begin());
        const std::size_t bad = std::min(invalidUtf8At(rest), firstControl);
        if (bad >= rest.size()) {
            out += rest;
            break;
        }
        out += rest.substr(0, bad) + fmt::format("\\x{:02X}", static_cast<unsigned char>(rest[bad]));
        rest.erase(0, bad + 1);
    }
    return out;
}

}  // namespace

std::vector<PressureSample> readPressureTable(const std::string& path) {
    std::string error;
    const std::string content = readWholeFile(path, error);
    if (!error.empty()) throw std::runtime_error(path + ": " + error);
    requireText(path, content);
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
                            path, lineNo, printable(line)));
        // Peak firing pressures reach about 25 MPa in heavy-duty diesels; beyond 50 MPa a table is in
        // the wrong unit or holds a typing error.
        if (pressure > kMaxCylinderPressure)
            throw std::runtime_error(fmt::format(
                "{}:{}: {:g} Pa is above {:g} MPa, beyond any engine's cylinder pressure (heavy-duty diesels peak "
                "near 25 MPa): expected absolute pressures in Pa",
                path, lineNo, pressure, kMaxCylinderPressure / 1e6));
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
