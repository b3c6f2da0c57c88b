#include "cosim/study/BodyCache.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

namespace flexehd::cosim {

namespace fs = std::filesystem;

unsigned long long fnv1a64(const std::string& bytes, unsigned long long hash) {
    for (const unsigned char c : bytes) {
        hash ^= c;
        hash *= 0x100000001b3ULL;
    }
    return hash;
}

std::vector<BodyBuild> variantBodies(const Study& study, const StudyVariant& variant) {
    std::vector<BodyBuild> builds;
    const fs::path dir = fs::absolute(study.path).parent_path();
    for (const auto& [body, recipe] : study.reduce) {
        std::string mesh = recipe.mesh;
        std::map<std::string, std::string> options(recipe.options.begin(), recipe.options.end());  // sorted: canonical
        const std::string prefix = "reduce." + body + ".";
        for (std::size_t p = 0; p < study.parameters.size(); ++p) {
            if (study.parameters[p].rfind(prefix, 0) != 0) continue;
            const std::string option = study.parameters[p].substr(prefix.size());
            if (option == "mesh") {
                const fs::path m(YAML::Load(variant.values[p]).as<std::string>());
                mesh = (m.is_relative() ? dir / m : m).lexically_normal().string();
            } else {
                options[option] = variant.values[p];
            }
        }
        BodyBuild b{body, "", {"reduce", "--mesh", mesh}};
        for (const auto& [option, text] : options) {
            std::string flag = "--" + option;
            std::replace(flag.begin(), flag.end(), '_', '-');
            const YAML::Node v = YAML::Load(text);
            if (v.IsSequence()) {
                for (const auto& item : v) b.args.insert(b.args.end(), {flag, item.as<std::string>()});
            } else {
                b.args.insert(b.args.end(), {flag, v.as<std::string>()});
            }
        }
        std::ifstream in(mesh, std::ios::binary);
        if (!in) throw std::runtime_error(fmt::format("{}: variant {}: cannot read the mesh {}", study.path, variant.id, mesh));
        // The mesh by its content, not its path: the same file anywhere gives the same body.
        unsigned long long h = fnv1a64(std::string(std::istreambuf_iterator<char>(in), {}));
        for (std::size_t i = 0; i < b.args.size(); ++i)
            if (i != 2) h = fnv1a64(b.args[i] + '\n', h);
        b.file = (fs::path(study.directory) / "cache" / fmt::format("{}-{:016x}.h5", body, h)).string();
        builds.push_back(std::move(b));
    }
    return builds;
}

}  // namespace flexehd::cosim
