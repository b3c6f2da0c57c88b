#pragma once
// The typed values of the case file (its section readers): numbers with their quantity and sign, whole
// numbers with their range, booleans, names, choices, and the checks of the files a case names.
// Every message says what was expected, as "expected a positive length in m, got 'abc'".
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "cosim/io/TextTable.hpp"
#include "cosim/io/YamlSection.hpp"

namespace flexehd::cosim::casefile {

/// "a " or "an " before the phrase.
std::string withArticle(const std::string& phrase);

enum class Sign { Any, Positive, NonNegative };

struct Quantity {
    const char* what;  ///< "length"
    const char* unit;  ///< "m"
};

inline constexpr Quantity kLength{"length", "m"};
inline constexpr Quantity kMass{"mass", "kg"};
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDeg = kPi / 180.0;

/// "a positive length in m".
std::string expectation(Quantity q, Sign sign);
/// Number at `key`; `def` if absent (and not required).
double number(const YamlSection& s, const std::string& key, Quantity q, Sign sign, double def, bool required = false);
/// A whole number of `what` from minimum to maximum; `def` if absent.
int integer(const YamlSection& s, const std::string& key, int minimum, int maximum, int def, const char* what);
bool boolean(const YamlSection& s, const std::string& key, bool def);
/// A non-empty text (`what` describes it); `def` if absent (and not required).
std::string text(const YamlSection& s, const std::string& key, const std::string& def, const std::string& what,
                 bool required = false);
/// One of `options` (the YAML spelling), returned as its index.
std::size_t choice(const YamlSection& s, const std::string& key, const std::vector<std::string>& options,
                   std::size_t def);
using cosim::readWholeFile;  // the file's contents, or "" with `error` saying why (io/TextTable.hpp)
/// HDF5's signature at offset 0, 512, 1024, … (after a user block).
bool looksLikeHdf5(const std::filesystem::path& path);

}  // namespace flexehd::cosim::casefile
