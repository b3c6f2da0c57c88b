#pragma once
// The text-table kit of the CSV readers (pressure table, bore distortion, history.csv): blanks
// trimmed, a line split into fields, a whole field read as a number, and the data lines of a
// table with '#' comments and blank lines skipped.
#include <charconv>
#include <filesystem>
#include <istream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace flexehd::cosim {

/// The file's contents (a UTF-8 byte-order mark skipped), or "" with `error` saying in words why
/// it cannot be read ("no such file", "is a directory, not a file", ...).
std::string readWholeFile(const std::filesystem::path& path, std::string& error);

/// `s` without the blanks (space, tab, CR, LF) at either end.
std::string_view trim(std::string_view s);

/// The fields of `line` between the separators `sep`, each trimmed: "a, b" gives {"a", "b"},
/// "" one empty field, "a," an empty field after "a".
std::vector<std::string_view> split(std::string_view line, char sep = ',');

/// The fields of a data line: comma-separated when it holds a comma, else semicolon-separated
/// when it holds a semicolon, else separated by runs of white space (no empty fields).
std::vector<std::string_view> splitFields(std::string_view line);

/// A finite number that is the whole of `text` (blanks at either end and a leading '+'
/// allowed): "+1e-3" is one, "1e", "1 2", "" and "inf" are not.
bool parseNumber(std::string_view text, double& value);

/// A value of type T that is the whole of `text` (blanks at either end and a leading '+'
/// allowed), in range: what parseNumber and parseWhole share.
template <typename T>
bool parseField(std::string_view text, T& value) {
    text = trim(text);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    if (text.empty()) return false;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end;
}

/// A whole number that is the whole of `text` (blanks at either end and a leading '+' allowed)
/// and fits `Int`.
template <typename Int>
bool parseWhole(std::string_view text, Int& value) {
    return parseField(text, value);
}

/// The lines of a text table that hold something, one at a time: each trimmed and numbered
/// from 1; blank lines and '#' comments skipped.
class DataLines {
public:
    /// `skipByteOrderMark`: a UTF-8 byte-order mark that starts the first line is not part of it.
    explicit DataLines(std::istream& in, bool skipByteOrderMark = false)
        : in_(in), skipByteOrderMark_(skipByteOrderMark) {}

    /// Moves to the next data line; false at the end of the input.
    bool next();
    /// The line, trimmed (valid until the next call of next()).
    std::string_view text() const { return text_; }
    /// Its number in the input, from 1.
    int number() const { return number_; }
    /// Whether a newline ends it (false only for an unterminated last line).
    bool terminated() const { return terminated_; }

private:
    std::istream& in_;
    bool skipByteOrderMark_;
    std::string raw_;
    std::string_view text_;
    int number_ = 0;
    bool terminated_ = true;
};

}  // namespace flexehd::cosim
