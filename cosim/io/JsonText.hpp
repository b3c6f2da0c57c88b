#pragma once
// JsonText: a JSON document as the text of a results file. A string that is not valid UTF-8 (a
// case file's name or path in Latin-1) is written with U+FFFD in place of each bad byte, so that
// no finished run loses its summary to the writer; and the check of a text for UTF-8.
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace flexehd::cosim {

/// doc.dump(indent) with each byte that is not valid UTF-8 replaced by U+FFFD.
std::string jsonText(const nlohmann::json& doc, int indent = -1);

/// The position of the first byte of `s` that does not belong to a valid UTF-8 sequence
/// (std::string::npos: all valid).
std::size_t invalidUtf8At(const std::string& s);

}  // namespace flexehd::cosim
