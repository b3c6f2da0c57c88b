#include "cosim/io/TextTable.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

namespace flexehd::cosim {

std::string readWholeFile(const std::filesystem::path& path, std::string& error) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(path, ec)) {
        error = "no such file";
        return {};
    }
    if (fs::is_directory(path, ec)) {
        error = "is a directory, not a file";
        return {};
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = "cannot be opened for reading";
        return {};
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) error = "read error";
    std::string text = ss.str();
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // UTF-8 byte-order mark (spreadsheet CSV)
    return text;
}

namespace {
constexpr std::string_view kBlanks = " \t\r\n";
constexpr std::string_view kWhiteSpace = " \t\r\n\v\f";
constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
}  // namespace

std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(kBlanks);
    if (first == std::string_view::npos) return {};
    return s.substr(first, s.find_last_not_of(kBlanks) - first + 1);
}

std::vector<std::string_view> split(std::string_view line, char sep) {
    std::vector<std::string_view> fields;
    for (;;) {
        const auto pos = line.find(sep);
        fields.push_back(trim(line.substr(0, pos)));
        if (pos == std::string_view::npos) return fields;
        line.remove_prefix(pos + 1);
    }
}

std::vector<std::string_view> splitFields(std::string_view line) {
    if (line.find(',') != std::string_view::npos) return split(line, ',');
    if (line.find(';') != std::string_view::npos) return split(line, ';');
    std::vector<std::string_view> fields;
    for (auto first = line.find_first_not_of(kWhiteSpace); first != std::string_view::npos;
         first = line.find_first_not_of(kWhiteSpace, first)) {
        const auto end = line.find_first_of(kWhiteSpace, first);
        fields.push_back(line.substr(first, end == std::string_view::npos ? std::string_view::npos : end - first));
        first = end;
    }
    return fields;
}

bool parseNumber(std::string_view text, double& value) { return parseField(text, value) && std::isfinite(value); }

bool DataLines::next() {
    while (std::getline(in_, raw_)) {
        ++number_;
        // getline stops at the end of the input before a newline only on an unterminated last line.
        terminated_ = !in_.eof();
        if (number_ == 1 && skipByteOrderMark_ && raw_.rfind(kByteOrderMark, 0) == 0)
            raw_.erase(0, kByteOrderMark.size());
        text_ = trim(raw_);
        if (!text_.empty() && text_.front() != '#') return true;
    }
    return false;
}

}  // namespace flexehd::cosim
