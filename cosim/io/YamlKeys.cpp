#include "cosim/io/YamlKeys.hpp"

#include <algorithm>
#include <cctype>

namespace flexehd::cosim {

namespace {

std::string lower(std::string s) {
    for (auto& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return s;
}

/// Levenshtein distance, ignoring case (a typo in case is a typo).
std::size_t editDistance(const std::string& aIn, const std::string& bIn) {
    const std::string a = lower(aIn), b = lower(bIn);
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

}  // namespace

std::string closestKey(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t bestDist = std::string::npos;
    if (word.size() >= 3)
        for (const auto& c : candidates)
            if (lower(c).find(lower(word)) != std::string::npos || lower(word).find(lower(c)) != std::string::npos) {
                const std::size_t d = editDistance(word, c);
                if (d < bestDist) bestDist = d, best = c;
            }
    if (!best.empty()) return best;
    for (const auto& c : candidates) {
        const std::size_t d = editDistance(word, c);
        if (d < bestDist) bestDist = d, best = c;
    }
    return bestDist <= std::max<std::size_t>(2, word.size() / 3) ? best : "";
}

std::string joinedKeys(const std::vector<std::string>& items) {
    std::string out;
    for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
    return out;
}

std::string describeNode(const YAML::Node& n) {
    if (!n.IsDefined() || n.IsNull()) return "nothing";
    if (n.IsMap()) return "a mapping";
    if (n.IsSequence()) return n.size() == 0 ? "an empty list" : "a list";
    return "'" + n.Scalar() + "'";
}

}  // namespace flexehd::cosim
