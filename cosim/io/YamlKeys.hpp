#pragma once
// Helpers shared by the YAML readers (case, thermal case, study): the "did you mean" guess for a
// mistyped key or value, lists of valid keys, and what a node is, for error messages.
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

namespace flexehd::cosim {

/// The candidate the word is most plausibly a typo of, or "" if none is close: a candidate that
/// contains the word or is contained in it (`speed` → `speed_rpm`), else the one at the smallest
/// edit distance (case ignored) if that is at most max(2, length/3).
std::string closestKey(const std::string& word, const std::vector<std::string>& candidates);

/// "a, b, c".
std::string joinedKeys(const std::vector<std::string>& items);

/// "nothing", "a mapping", "a list" or the quoted scalar.
std::string describeNode(const YAML::Node& n);

}  // namespace flexehd::cosim
