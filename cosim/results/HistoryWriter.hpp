#pragma once
// HistoryWriter: history.csv, one StepRecord per line (docs/results-format.md).
//
// The file starts with a few '#' comment lines (units, sign conventions), then a header line
// whose column names carry the unit (`crank_deg`, `lateral_m`, `side_force_n`, …), then one
// line per accepted step, printed with 9 significant digits. Each line is written whole,
// unbuffered (fem::AppendFile), so a run killed between steps leaves a valid CSV of complete
// lines, and a line that cannot be written (a full disk) is cut back, never left half. Non-finite
// values are refused (std::runtime_error naming the column and the crank angle): the file
// never holds NaN or Inf.
#include <string>
#include <vector>

#include "cosim/coupling/StepRecord.hpp"
#include "fem/AppendFile.hpp"

namespace flexehd::cosim {

class HistoryWriter {
public:
    /// Creates (or truncates) `path` and writes the comment and header lines.
    /// Throws std::runtime_error naming the file if it cannot be written.
    /// oilColumns: the mass-conserving film's oil columns too (oil_in_m3_per_s … liner_oil_m3).
    /// contactColumns: the further contacts' own columns (PistonSimulation::contactColumns), after
    /// step_deg, their values StepRecord::contactValues; std::invalid_argument for an empty name,
    /// one with a comma or space, or one that repeats a column.
    explicit HistoryWriter(const std::string& path, bool oilColumns = false,
                           std::vector<std::string> contactColumns = {});

    /// Writes one line. Throws std::runtime_error naming the column and the crank angle if a
    /// value is NaN or Inf (nothing is written then), or naming the file and the reason on an
    /// I/O error (the file then ends with the previous line); std::logic_error when the record's contact values do not match the
    /// contact columns.
    void append(const StepRecord& record);

    /// Column names of the header line, in file order.
    static const std::vector<std::string>& columns(bool oil = false);
    /// Significant digits of the printed values (a round trip is exact to this precision).
    static constexpr int kSignificantDigits = 9;

    /// Reads a history file: '#' and blank lines are skipped, columns are matched by their
    /// header name (order free, unknown columns — the further contacts' among them — ignored, a missing one is an error but for the
    /// oil columns, 0 when absent). A last
    /// line without its terminating newline is the partial line of a run killed while
    /// writing: it is dropped (and `*partialLastLine` set when given). Any other malformed
    /// line throws std::runtime_error naming the file, the line number and the column.
    static std::vector<StepRecord> read(const std::string& path, bool* partialLastLine = nullptr);

private:
    std::string path_;
    bool oil_;
    std::vector<std::string> contactColumns_;  // checked before the file is touched
    fem::AppendFile out_;
};

}  // namespace flexehd::cosim
