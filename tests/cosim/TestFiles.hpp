#pragma once
// Small helpers of the co-simulation tests: writing a text file, the example's hd.yaml on a coarse
// grid, plus TestScratch.hpp's scratch directory and exception message.
#include "../TestScratch.hpp"

#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace flexehd::test {

inline void writeFile(const std::filesystem::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
}

#ifdef FLEXEHD_SOURCE_DIR
/// examples/engine86/hd.yaml on the coarse 24 x 72 grid with its pressure table found from anywhere,
/// its output in `out`, and each (from, to) of `edits` replaced (std::logic_error if hd.yaml lacks
/// a `from`); written to DIR/case.yaml, whose path it returns.
inline std::string coarseHdCase(const std::filesystem::path& dir, const std::filesystem::path& out,
                                const std::vector<std::pair<std::string, std::string>>& edits = {}) {
    const std::string source = std::string(FLEXEHD_SOURCE_DIR) + "/examples/engine86/";
    std::ifstream in(source + "hd.yaml");
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    auto replace = [&](const std::string& from, const std::string& to) {
        const auto at = s.find(from);
        if (at == std::string::npos) throw std::logic_error("hd.yaml lacks: " + from);
        s.replace(at, from.size(), to);
    };
    replace("cylinder_pressure: cylinder_pressure.csv", "cylinder_pressure: " + source + "cylinder_pressure.csv");
    replace("axial_nodes: 48", "axial_nodes: 24");
    replace("circumferential_nodes: 144", "circumferential_nodes: 72");
    replace("directory: ../../out/engine86/hd", "directory: " + out.string());
    for (const auto& [from, to] : edits) replace(from, to);
    writeFile(dir / "case.yaml", s);
    return (dir / "case.yaml").string();
}
#endif

}  // namespace flexehd::test
