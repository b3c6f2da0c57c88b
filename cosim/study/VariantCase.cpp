#include "cosim/study/VariantCase.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "cosim/casefile/CaseFile.hpp"
#include "cosim/io/YamlDocument.hpp"

namespace flexehd::cosim {
namespace {

namespace fs = std::filesystem;

// Case-file keys holding paths, relative to the file that gives them (docs/case-file.md).
const char* const kPathKeys[] = {"cylinder_pressure", "output.directory", "bodies.piston.file", "bodies.liner.file",
                                 "rings"};

bool isPathKey(const std::string& key) {
    for (const char* k : kPathKeys)
        if (key == k) return true;
    return false;
}

std::string absolutePath(const std::string& p, const fs::path& dir) {
    const fs::path path(p);
    return (path.is_relative() ? dir / path : path).lexically_normal().string();
}

std::vector<std::string> split(const std::string& path) {
    std::vector<std::string> parts;
    std::size_t from = 0;
    for (std::size_t dot; (dot = path.find('.', from)) != std::string::npos; from = dot + 1)
        parts.push_back(path.substr(from, dot - from));
    parts.push_back(path.substr(from));
    return parts;
}

/// Sets root[a][b]…[z] = value, creating missing mappings. Throws if the path runs through
/// a value that is not a mapping.
void setKey(YAML::Node root, const std::string& path, const YAML::Node& value) {
    const std::vector<std::string> parts = split(path);
    YAML::Node cur = root;
    std::string prefix;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
        prefix += (i ? "." : "") + parts[i];
        if (!cur[parts[i]] || cur[parts[i]].IsNull()) cur[parts[i]] = YAML::Node(YAML::NodeType::Map);
        YAML::Node next = cur[parts[i]];
        if (!next.IsMap())
            throw std::runtime_error(fmt::format("{} is {} in the base case, not a mapping: set {} as a whole", prefix,
                                                 next.IsScalar() ? "'" + next.Scalar() + "'" : "a list", prefix));
        cur.reset(next);
    }
    cur[parts.back()] = value;
}

/// Sets a key to a value given as YAML text, making a path value absolute against `dir`.
void apply(YAML::Node root, const std::string& key, const std::string& valueText, const fs::path& dir) {
    YAML::Node value = YAML::Load(valueText);
    if (isPathKey(key) && value.IsScalar()) value = absolutePath(value.Scalar(), dir);
    if ((key == "bodies.piston" || key == "bodies.liner") && value.IsMap() && value["file"] && value["file"].IsScalar())
        value["file"] = absolutePath(value["file"].Scalar(), dir);
    setKey(root, key, value);
}

/// The base case with its relative paths made absolute.
YAML::Node loadBase(const Study& study) {
    YAML::Node root;
    try {
        root = loadYamlDocument(study.baseCase, "the case file");
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(fmt::format("{}: base_case: {}", study.path, e.what()));
    }
    if (!root.IsMap()) throw std::runtime_error(study.path + ": base case " + study.baseCase + " is not a mapping");
    const fs::path dir = fs::path(study.baseCase).parent_path();
    for (const char* k : kPathKeys) {
        const std::vector<std::string> parts = split(k);
        YAML::Node cur = root;
        bool found = true;
        for (const auto& p : parts) {
            if (!cur.IsMap() || !cur[p]) {
                found = false;
                break;
            }
            YAML::Node next = cur[p];
            cur.reset(next);
        }
        if (found && cur.IsScalar()) cur = absolutePath(cur.Scalar(), dir);
    }
    return root;
}

std::string emit(const YAML::Node& root, const std::string& header) {
    YAML::Emitter e;
    e << root;
    return header + e.c_str() + "\n";
}

}  // namespace

std::string variantCaseText(const Study& study, const StudyVariant& variant,
                            const std::map<std::string, std::string>& bodyFiles) {
    YAML::Node root = loadBase(study);
    const fs::path dir = fs::absolute(study.path).parent_path();
    root["name"] = study.name + " " + variant.id;
    std::string header = fmt::format("# flexehd sweep: study {}, variant {}, base case {}\n",
                                     fs::absolute(study.path).lexically_normal().string(), variant.id, study.baseCase);
    for (const auto& [key, value] : study.fixed) apply(root, key, value, dir);
    for (std::size_t p = 0; p < study.parameters.size(); ++p) {
        header += fmt::format("#   {} = {}\n", study.parameters[p], variant.values[p]);
        if (!isReduceParameter(study.parameters[p])) apply(root, study.parameters[p], variant.values[p], dir);
    }
    for (const auto& [body, file] : bodyFiles) {
        if (root["bodies"] && root["bodies"].IsMap() && root["bodies"][body] && root["bodies"][body].IsMap()) {
            YAML::Node b = root["bodies"][body];
            b["file"] = file;
        } else {
            YAML::Node m(YAML::NodeType::Map);
            m["file"] = file;
            setKey(root, "bodies." + body, m);
        }
    }
    return emit(root, header);
}

void checkCaseKeys(const Study& study) {
    const fs::path dir = fs::absolute(study.path).parent_path();
    const std::string tmp =
        (fs::temp_directory_path() / fmt::format("flexehd_sweep_check_{}.yaml", ::getpid())).string();
    auto check = [&](const std::string& where, const std::string& key, const std::string& value) {
        YAML::Node root = loadBase(study);
        try {
            apply(root, key, value, dir);
        } catch (const std::exception& e) {
            throw std::runtime_error(fmt::format("{}: {}: {}", study.path, where, e.what()));
        }
        std::ofstream(tmp) << emit(root, "");
        try {
            readCaseFile(tmp, CaseFileOptions{.checkBodyFiles = false});
        } catch (const std::exception& e) {
            std::string msg = e.what();
            if (msg.find("unknown key") == std::string::npos) return;  // a value error: the variant fails
            if (msg.rfind(tmp + ": ", 0) == 0) msg.erase(0, tmp.size() + 2);
            msg = std::regex_replace(msg, std::regex(R"( \(line \d+\))"), "");
            fs::remove(tmp);
            throw std::runtime_error(fmt::format("{}: {}: not a case-file key: {}", study.path, where, msg));
        }
    };
    for (const auto& [key, value] : study.fixed) check("set." + key, key, value);
    for (std::size_t p = 0; p < study.parameters.size(); ++p)
        if (!isReduceParameter(study.parameters[p]))
            check("parameters." + study.parameters[p], study.parameters[p], study.variants.front().values[p]);
    fs::remove(tmp);
}

}  // namespace flexehd::cosim
