// The case file's table of contents: the YAML document and its top-level keys, then each
// section by its reader (CaseSections.hpp) in the order the sections depend on each other,
// with the cross-section checks once the sections they span are read.
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/io/JsonText.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "cosim/casefile/CaseSections.hpp"
#include "cosim/casefile/CaseValues.hpp"
#include "cosim/casefile/CrossSectionChecks.hpp"
#include "cosim/io/YamlSection.hpp"

namespace flexehd::cosim {
namespace {

using namespace casefile;
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

YAML::Node loadCaseYaml(const std::string& path, const fs::path& absolute) {
    std::string error;
    const std::string raw = readWholeFile(absolute, error);
    if (!error.empty()) throw std::runtime_error(path + ": cannot read the case file: " + error);
    const std::string content = withLineFeeds(raw);
    if (const std::size_t nul = content.find('\0'); nul != std::string::npos)
        throw std::runtime_error(
            fmt::format("{}: the case file contains a NUL byte at line {} (a binary file?): expected YAML text", path,
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
    if (documents.size() > 1)
        throw std::runtime_error(fmt::format(
            "{}: the case file holds {} YAML documents; flexehd reads one (the second begins at line {}: remove "
            "the '---' and what follows, or put it in a case file of its own)",
            path, documents.size(), documents[1].Mark().line + 1));
    const YAML::Node root = documents.empty() ? YAML::Node() : documents.front();
    if (!root.IsDefined() || root.IsNull()) throw std::runtime_error(path + ": the case file is empty");
    return root;
}

}  // namespace

EngineCase readCaseFile(const std::string& path, const CaseFileOptions& options) {
    const fs::path absolute = fs::absolute(fs::path(path)).lexically_normal();
    const YamlSource ctx{path, absolute.parent_path()};

    const YAML::Node root = loadCaseYaml(path, absolute);
    const YamlSection top(ctx, root, "",
                          {"name", "engine", "piston", "lubricant", "contact", "cylinder_pressure", "bodies", "grid",
                           "time", "coupling", "output", "liner", "thermal", "rings", "ring_gas"});
    EngineCase c;
    c.path = absolute.string();
    c.name = text(top, "name", absolute.stem().string(), "a name (text)");
    if (const std::size_t bad = invalidUtf8At(c.name); top.has("name") && bad != std::string::npos)
        top.fail("name", fmt::format("expected UTF-8 text, got the byte 0x{:02X} at position {} (is the file saved in "
                                     "Latin-1? save it as UTF-8)",
                                     static_cast<unsigned char>(c.name[bad]), bad));

    // Bodies first: whether the liner is flexible decides whether engine.pin_tdc_depth is required.
    readBodies(top, options, c);
    const YamlSection engine = readEngine(top, c.engine);
    readLiner(top, c.engine, c.liner);
    readThermal(top, options, c.thermal);
    requirePinTdcDepth(engine, c);

    readPiston(top, c.engine, c.piston);
    requireSkirtBelowDeck(engine, c);

    const YamlSection lubricant = readLubricant(top, c.engine, c.lubricant);
    readContact(top, c.contact);
    readRings(top, engine, c);
    readRingGas(top, c);
    readCylinderPressure(top, c);
    readGrid(top, c.piston, c.grid);
    if (c.lubricant.supply.model == OilSupplyModel::LinerLayer) {  // time.*_tolerance's defaults
        c.time.lateralTolerance = TimeSpec::kStarvedLateralTolerance;
        c.time.tiltTolerance = TimeSpec::kStarvedTiltTolerance;
    }
    readTime(top, c.time);
    if (c.hasFlexibleBody() && c.lubricant.cavitation == CavitationModel::MassConserving)
        c.coupling.maxIterations = CouplingSpec::kMassConservingFlexiblePasses;  // coupling.max_iterations' default
    const YamlSection coupling = readCoupling(top, c.coupling);
    requireSupportedMassConserving(coupling, c);
    requireOilControlRingOnPiston(lubricant, c);
    requireReplenishWithinReach(lubricant, c);
    readOutput(top, c.output);
    return c;
}

}  // namespace flexehd::cosim
