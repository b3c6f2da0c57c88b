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

// The line for a message: bytes outside printable ASCII and valid UTF-8 as \xNN.
std::string printable(std::string_view line) {
    std::string out;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const auto b = static_cast<unsigned char>(line[i]);
        std::size_t n = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E ? 4 : 0;
        bool valid = n > 0 && i + n <= line.size() && (b >= 0x20 || b == '\t');
        for (std::size_t k = 1; valid && k < n; ++k) valid = (static_cast<unsigned char>(line[i + k]) >> 6) == 0x2;
        if (valid) {
            out.append(line.substr(i, n));
            i += n - 1;
        } else {
            out += fmt::format("\\x{:02X}", b);
        }
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
