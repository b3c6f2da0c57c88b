#include "cosim/casefile/CaseValues.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "cosim/io/YamlKeys.hpp"

namespace flexehd::cosim::casefile {

namespace fs = std::filesystem;

namespace {
const auto& joined = joinedKeys;
const auto& describe = describeNode;
}  // namespace

std::string withArticle(const std::string& phrase) {
    const bool vowel = !phrase.empty() && std::strchr("aeiou", phrase[0]) != nullptr;
    return (vowel ? "an " : "a ") + phrase;
}

// ---- typed values ---------------------------------------------------------------------------

std::string expectation(Quantity q, Sign sign) {
    const std::string adj = sign == Sign::Positive ? "positive " : sign == Sign::NonNegative ? "non-negative " : "";
    return withArticle(adj + q.what) + (q.unit[0] ? std::string(" in ") + q.unit : std::string());
}

/// Number at `key`; `def` if absent (and not required).
double number(const YamlSection& s, const std::string& key, Quantity q, Sign sign, double def, bool required) {
    if (!s.has(key)) {
        if (required) s.missing(key, expectation(q, sign));
        return def;
    }
    const YAML::Node n = s.get(key);
    double v = 0.0;
    if (!n.IsScalar() || !parseNumber(n.Scalar(), v))
        s.fail(key, fmt::format("expected {}, got {}", expectation(q, sign), describe(n)));
    if ((sign == Sign::Positive && !(v > 0.0)) || (sign == Sign::NonNegative && !(v >= 0.0)))
        s.fail(key, fmt::format("expected {}, got {}", expectation(q, sign), trim(n.Scalar())));
    return v;
}

int integer(const YamlSection& s, const std::string& key, int minimum, int maximum, int def, const char* what) {
    if (!s.has(key)) return def;
    const YAML::Node n = s.get(key);
    long long v = 0;
    const std::string expected = fmt::format("a whole number{}{} from {} to {}", *what ? " of " : "", what, minimum, maximum);
    if (!n.IsScalar() || !parseWhole(n.Scalar(), v))
        s.fail(key, fmt::format("expected {}, got {}", expected, describe(n)));
    if (v < minimum || v > maximum) s.fail(key, fmt::format("expected {}, got {}", expected, trim(n.Scalar())));
    return static_cast<int>(v);
}

bool boolean(const YamlSection& s, const std::string& key, bool def) {
    if (!s.has(key)) return def;
    const YAML::Node n = s.get(key);
    bool v = false;
    if (!n.IsScalar() || !YAML::convert<bool>::decode(n, v)) s.fail(key, "expected true or false, got " + describe(n));
    return v;
}

std::string text(const YamlSection& s, const std::string& key, const std::string& def, const std::string& what,
                 bool required) {
    if (!s.has(key)) {
        if (required) s.missing(key, what);
        return def;
    }
    const YAML::Node n = s.get(key);
    if (!n.IsScalar() || trim(n.Scalar()).empty()) s.fail(key, "expected " + what + ", got " + describe(n));
    return std::string(trim(n.Scalar()));
}

/// One of `options` (the YAML spelling), returned as its index.
std::size_t choice(const YamlSection& s, const std::string& key, const std::vector<std::string>& options, std::size_t def) {
    if (!s.has(key)) return def;
    const YAML::Node n = s.get(key);
    const std::string expected = "one of " + joined(options);
    if (!n.IsScalar()) s.fail(key, "expected " + expected + ", got " + describe(n));
    const std::string v(trim(n.Scalar()));
    for (std::size_t i = 0; i < options.size(); ++i)
        if (v == options[i]) return i;
    const std::string guess = closestKey(v, options);
    s.fail(key, fmt::format("expected {}, got '{}'{}", expected, v,
                            guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess)));
}

// ---- files ----------------------------------------------------------------------------------

/// HDF5 files carry an 8-byte signature at offset 0, 512, 1024, 2048, … (after a user block).
bool looksLikeHdf5(const fs::path& path) {
    static const char kSignature[8] = {'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};
    std::ifstream in(path, std::ios::binary);
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (!in || ec) return false;
    for (std::uintmax_t offset = 0; offset + 8 <= size; offset = offset == 0 ? 512 : 2 * offset) {
        char buf[8];
        in.seekg(static_cast<std::streamoff>(offset));
        if (!in.read(buf, 8)) return false;
        if (std::memcmp(buf, kSignature, 8) == 0) return true;
    }
    return false;
}


}  // namespace flexehd::cosim::casefile
