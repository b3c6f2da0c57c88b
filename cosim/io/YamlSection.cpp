#include "cosim/io/YamlSection.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include <fmt/format.h>

#include "cosim/io/YamlKeys.hpp"

namespace flexehd::cosim {

void YamlSource::fail(const std::string& keyPath, const YAML::Node& at, const std::string& msg) const {
    const std::string line = at.IsDefined() && at.Mark().line >= 0 ? fmt::format(" (line {})", at.Mark().line + 1) : "";
    throw std::runtime_error(fmt::format("{}: {}{}: {}", file, keyPath.empty() ? "(top level)" : keyPath, line, msg));
}

std::filesystem::path YamlSource::resolve(const std::string& p) const {
    std::filesystem::path path(p);
    if (path.is_relative()) path = dir / path;
    return path.lexically_normal();
}

YamlSection::YamlSection(const YamlSource& src, YAML::Node node, std::string path, std::vector<std::string> keys)
    // An absent key gives yaml-cpp's "invalid" node, which throws on most uses (even on
    // assignment): replace it by a fresh null node.
    : src_(src), node_(node.IsDefined() ? node : YAML::Node()), path_(std::move(path)), keys_(std::move(keys)) {
    if (node_.IsNull()) return;
    if (!node_.IsMap())
        src_.fail(path_, node_,
                  fmt::format("expected a mapping with the keys {}, got {}", joinedKeys(keys_), describeNode(node_)));
    std::set<std::string> seen;
    for (const auto& kv : node_) {
        const YAML::Node& k = kv.first;
        if (!k.IsScalar()) src_.fail(keyPath("?"), k, "keys must be plain names, got " + describeNode(k));
        const std::string name = k.Scalar();
        if (std::find(keys_.begin(), keys_.end(), name) == keys_.end()) {
            const std::string guess = closestKey(name, keys_);
            src_.fail(keyPath(name), k,
                      fmt::format("unknown key{}; valid keys here: {}",
                                  guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess), joinedKeys(keys_)));
        }
        if (!seen.insert(name).second) src_.fail(keyPath(name), k, "key given twice");
    }
}

void YamlSection::fail(const std::string& key, const std::string& msg) const {
    const YAML::Node n = get(key);
    src_.fail(keyPath(key), n.IsDefined() ? n : node_, msg);
}

void YamlSection::missing(const std::string& key, const std::string& expected) const {
    src_.fail(keyPath(key), node_, "required key missing: expected " + expected);
}

}  // namespace flexehd::cosim
