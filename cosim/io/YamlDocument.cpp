#include "cosim/io/YamlDocument.hpp"
#include "cosim/io/TextTable.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include <fmt/format.h>

namespace flexehd::cosim {
namespace {

namespace fs = std::filesystem;

// Old Mac files end their lines with a lone CR, which yaml-cpp does not take for a line end:
// each lone CR becomes LF (CR LF stays as it is).
std::string withLineFeeds(const std::string& content) {
    std::string out;
    out.reserve(content.size());
    for (std::size_t i = 0; i < content.size(); ++i)
        out += content[i] == '\r' && (i + 1 == content.size() || content[i + 1] != '\n') ? '\n' : content[i];
    return out;
}

}  // namespace

YAML::Node loadYamlDocument(const std::string& path, const std::string& what) {
    std::string error;
    const std::string raw = readWholeFile(fs::path(path), error);
    if (!error.empty()) throw std::runtime_error(fmt::format("{}: cannot read {}: {}", path, what, error));
    const std::string content = withLineFeeds(raw);
    if (const std::size_t nul = content.find('\0'); nul != std::string::npos)
        throw std::runtime_error(
            fmt::format("{}: {} contains a NUL byte at line {} (a binary file?): expected YAML text", path, what,
                        1 + std::count(content.begin(), content.begin() + std::ptrdiff_t(nul), '\n')));
    std::vector<YAML::Node> documents;
    try {
        documents = YAML::LoadAll(content);
    } catch (const YAML::Exception& e) {
        throw std::runtime_error(
            fmt::format("{}:{}:{}: YAML syntax error: {}", path, e.mark.line + 1, e.mark.column + 1, e.msg));
    }
    // A trailing "---" or "..." with nothing after it adds an empty document: not a second one.
    while (documents.size() > 1 && documents.back().IsNull()) documents.pop_back();
    if (documents.size() > 1) {
        const std::string kind = what.rfind("the ", 0) == 0 ? what.substr(4) : what;  // "case file"
        throw std::runtime_error(fmt::format(
            "{}: {} holds {} YAML documents; flexehd reads one (the second begins at line {}: remove the '---' and "
            "what follows, or put it in a {} of its own)",
            path, what, documents.size(), documents[1].Mark().line + 1, kind));
    }
    const YAML::Node root = documents.empty() ? YAML::Node() : documents.front();
    if (!root.IsDefined() || root.IsNull()) throw std::runtime_error(fmt::format("{}: {} is empty", path, what));
    return root;
}

}  // namespace flexehd::cosim
