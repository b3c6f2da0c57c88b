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
#include "cosim/io/YamlDocument.hpp"
#include "cosim/io/YamlSection.hpp"

namespace flexehd::cosim {
namespace {

using namespace casefile;
namespace fs = std::filesystem;

}  // namespace

EngineCase readCaseFile(const std::string& path, const CaseFileOptions& options) {
    const fs::path absolute = fs::absolute(fs::path(path)).lexically_normal();
    const YamlSource ctx{path, absolute.parent_path()};

    const YAML::Node root = loadYamlDocument(path, "the case file");
    const YamlSection top(ctx, root, "",
                          {"name", "engine", "piston", "lubricant", "contact", "cylinder_pressure", "bodies", "grid",
                           "time", "coupling", "output", "liner", "thermal", "rings", "ring_gas", "acoustics"});
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
    requireRingPackForItsLoads(top, c);
    readCylinderPressure(top, c);
    readGrid(top, c.piston, c.grid);
    if (c.lubricant.supply.model == OilSupplyModel::LinerLayer) {  // time.*_tolerance's defaults
        c.time.lateralTolerance = TimeSpec::kStarvedLateralTolerance;
        c.time.tiltTolerance = TimeSpec::kStarvedTiltTolerance;
    }
    readTime(top, c.time);
    if (c.hasFlexibleBody()) c.coupling.maxIterations = CouplingSpec::kFlexiblePasses;  // coupling.max_iterations' default
    const YamlSection coupling = readCoupling(top, c.coupling);
    requireSupportedMassConserving(coupling, c);
    requireOilControlRingOnPiston(lubricant, c);
    requireReplenishWithinReach(lubricant, c);
    readOutput(top, c.output);
    readAcoustics(top, c);
    return c;
}

}  // namespace flexehd::cosim
