#pragma once
// The YAML reading kit of every reader (case, thermal case, study): where in which file a value
// stands, for messages of the form "FILE: key.path (line N): what was expected, got what", and a
// mapping with a fixed set of keys whose unknown keys are errors naming the closest valid one.
#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace flexehd::cosim {

/// The file being read.
struct YamlSource {
    std::string file;           ///< as given, for messages
    std::filesystem::path dir;  ///< its directory, absolute: relative paths in it resolve here

    /// Throws std::runtime_error "FILE: keyPath (line N): msg" (keyPath "" = "(top level)"; the
    /// line of `at` when it has one).
    [[noreturn]] void fail(const std::string& keyPath, const YAML::Node& at, const std::string& msg) const;
    /// `p` against dir when relative, normalised.
    std::filesystem::path resolve(const std::string& p) const;
};

/// A mapping at `path` with the keys `keys`: an absent or empty section reads as empty; a
/// non-mapping, an unknown key (with a "did you mean" guess), a non-scalar key or a key given
/// twice is an error.
class YamlSection {
public:
    YamlSection(const YamlSource& src, YAML::Node node, std::string path, std::vector<std::string> keys);

    const YamlSource& source() const { return src_; }
    const YAML::Node& node() const { return node_; }
    /// "path.key" (or "key" at the top level).
    std::string keyPath(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
    /// The key is given (possibly with an empty value).
    bool has(const std::string& key) const { return node_.IsMap() && node_[key].IsDefined(); }
    /// The key is given with a value.
    bool hasValue(const std::string& key) const { return has(key) && !node_[key].IsNull(); }
    YAML::Node get(const std::string& key) const { return node_.IsMap() ? node_[key] : YAML::Node(); }

    /// Fails at the key's value (or at the section when the key is absent).
    [[noreturn]] void fail(const std::string& key, const std::string& msg) const;
    [[noreturn]] void missing(const std::string& key, const std::string& expected) const;

private:
    const YamlSource& src_;
    YAML::Node node_;
    std::string path_;
    std::vector<std::string> keys_;
};

}  // namespace flexehd::cosim
