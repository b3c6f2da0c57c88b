// The case key `rings`: the ring pack read from the case file or from the file it names, the
// tension as a load per unit circumference, the rings placed on the ring belt, and the errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "cosim/casefile/CaseFile.hpp"
#include "cosim/run/CaseRun.hpp"

#include "MinimalCaseFile.hpp"
#include "TestFiles.hpp"

using namespace flexehd::cosim;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;
using flexehd::test::errorOf;
using flexehd::test::scratchDir;
using flexehd::test::writeFile;

namespace fs = std::filesystem;

namespace {


// Two rings as a case file's list; the tests edit it.
const char* kTwoRings = R"(rings:
  - name: top
    kind: compression
    height: 1.15e-3
    radial_width: 3.2e-3
    face: {crown_height: 8.0e-6, vertex_offset: 0.0}
    tangential_force: 9.0
    closed_gap: 0.25e-3
    mass: 7.5e-3
    groove: {lower_flank: 0.0253, side_clearance: 0.05e-3, back_clearance: 0.6e-3}
  - name: oil
    kind: oil_control
    height: 2.43e-3
    radial_width: 2.6e-3
    lands: {width: 0.4e-3, separation: 2.03e-3, crown_height: 4.0e-6}
    elastic_pressure: 1.0e6
    closed_gap: 0.3e-3
    mass: 6.5e-3
    roughness: 0.2e-6
    groove: {lower_flank: 0.0138, side_clearance: 0.07e-3, back_clearance: 1.2e-3}
)";

using Edits = std::vector<std::pair<std::string, std::string>>;

// DIR/case.yaml: kMinimalCase and `rings` (kTwoRings), with the edits applied (each must be found).
std::string caseWith(const fs::path& dir, const Edits& edits = {}, const std::string& rings = kTwoRings) {
    std::string text = std::string(flexehd::test::kMinimalCase) + rings;
    for (const auto& [from, to] : edits) {
        const auto pos = text.find(from);
        if (pos == std::string::npos) throw std::logic_error("test ring text lacks: " + from);
        text.replace(pos, from.size(), to);
    }
    writeFile(dir / "case.yaml", text);
    writeFile(dir / "p.csv", flexehd::test::kMinimalPressureTable);
    return (dir / "case.yaml").string();
}

std::string caseError(const fs::path& dir, const Edits& edits) {
    const std::string path = caseWith(dir, edits);
    return errorOf([&] { readCaseFile(path); });
}

}  // namespace

TEST(CaseFileRings, ThePackIsReadWithItsTensionPerUnitCircumference) {
    const fs::path dir = scratchDir();
    const EngineCase c = readCaseFile(caseWith(dir));
    ASSERT_EQ(c.rings.size(), 2u);
    const RingSpec& top = c.rings[0];
    EXPECT_EQ(top.name, "top");
    EXPECT_EQ(top.kind, RingKind::Compression);
    EXPECT_EQ(top.face.crownHeight, 8.0e-6);
    EXPECT_TRUE(top.face.table.empty());
    // The tangential force F_t holds each half of the ring against the radial load w per unit
    // length on the half circumference: 2 F_t = w D.
    EXPECT_NEAR(top.tensionPerLength, 2.0 * 9.0 / 0.086, 1e-12);
    EXPECT_EQ(top.roughness, c.contact.sigma);  // the skirt's by default
    EXPECT_NEAR(top.top(), 0.0253 + 1.15e-3, 1e-15);
    EXPECT_NEAR(top.grooveTop(), 0.0253 + 1.2e-3, 1e-15);
    const RingSpec& oil = c.rings[1];
    EXPECT_EQ(oil.kind, RingKind::OilControl);
    ASSERT_TRUE(oil.lands.has_value());
    EXPECT_EQ(oil.lands->separation, 2.03e-3);
    // The elastic pressure acts on the two lands' faces.
    EXPECT_NEAR(oil.tensionPerLength, 1.0e6 * 2.0 * 0.4e-3, 1e-9);
    EXPECT_EQ(oil.roughness, 0.2e-6);
    EXPECT_TRUE(readCaseFile(caseWith(dir, {}, "")).rings.empty());
}

TEST(CaseFileRings, TheShippedPackReadsFromItsFileOnTheExamplePiston) {
    const fs::path dir = scratchDir();
    const std::string pack = std::string(FLEXEHD_SOURCE_DIR) + "/examples/engine86/rings.yaml";
    const EngineCase c = readCaseFile(caseWith(dir, {}, "rings: " + pack + "\n"));
    ASSERT_EQ(c.rings.size(), 3u);
    EXPECT_EQ(c.rings[0].name, "top");
    EXPECT_EQ(c.rings[1].kind, RingKind::Scraper);
    EXPECT_EQ(c.rings[1].face.table.size(), 7u);
    EXPECT_EQ(c.rings[2].kind, RingKind::OilControl);
    // In the grooves of meshes/piston.geo: 1.2, 1.5 and 2.5 mm wide.
    EXPECT_NEAR(c.rings[0].grooveTop() - c.rings[0].groove.lowerFlank, 1.2e-3, 1e-12);
    EXPECT_NEAR(c.rings[1].grooveTop() - c.rings[1].groove.lowerFlank, 1.5e-3, 1e-12);
    EXPECT_NEAR(c.rings[2].grooveTop() - c.rings[2].groove.lowerFlank, 2.5e-3, 1e-12);
    // Errors in the named file name that file.
    writeFile(dir / "pack.yaml", "rings:\n  - name: top\n    kind: compresion\n");
    EXPECT_THAT(errorOf([&] { readCaseFile(caseWith(dir, {}, "rings: pack.yaml\n")); }),
                AllOf(StartsWith((dir / "pack.yaml").string() + ": rings[0].kind"), HasSubstr("compression")));
    EXPECT_THAT(errorOf([&] { readCaseFile(caseWith(dir, {}, "rings: none.yaml\n")); }),
                AllOf(HasSubstr("rings"), HasSubstr("cannot read the ring-pack file"), HasSubstr("none.yaml")));
    writeFile(dir / "bad.yaml", "rings: [\n");
    EXPECT_THAT(errorOf([&] { readCaseFile(caseWith(dir, {}, "rings: bad.yaml\n")); }),
                HasSubstr("YAML syntax error"));
}

TEST(CaseFileRings, BadRingsAreRefusedNamingTheKey) {
    const fs::path dir = scratchDir();
    const std::string file = (dir / "case.yaml").string();
    auto error = [&](const std::string& from, const std::string& to) { return caseError(dir, {{from, to}}); };
    EXPECT_THAT(error("height: 1.15e-3", "height: -1.15e-3"), StartsWith(file + ": rings[0].height"));
    EXPECT_THAT(error("height: 1.15e-3", "height: 1.15"), AllOf(StartsWith(file + ": rings[0].height"),
                                                                 HasSubstr("check the units")));
    EXPECT_THAT(error("kind: compression", "kind: piston"), StartsWith(file + ": rings[0].kind"));
    EXPECT_THAT(error("closed_gap: 0.25e-3", "closed_gap: 0.25e-3\n    tension: 3"),
                AllOf(StartsWith(file + ": rings[0].tension"), HasSubstr("tangential_force")));
    EXPECT_THAT(error("tangential_force: 9.0", "tangential_force: 9.0\n    elastic_pressure: 1e5"),
                AllOf(StartsWith(file + ": rings[0].elastic_pressure"), HasSubstr("one of them")));
    EXPECT_THAT(error("name: oil", "name: top"), AllOf(StartsWith(file + ": rings[1].name"), HasSubstr("two rings")));
    // The face.
    EXPECT_THAT(error("vertex_offset: 0.0", "vertex_offset: 0.6e-3"),
                AllOf(StartsWith(file + ": rings[0].face.vertex_offset"), HasSubstr("height/2")));
    EXPECT_THAT(error("face: {crown_height: 8.0e-6, vertex_offset: 0.0}",
                      "face: {table: [[-0.5e-3, 1e-6], [0.2e-3, 0.0], [0.1e-3, 2e-6]]}"),
                AllOf(StartsWith(file + ": rings[0].face.table[2]"), HasSubstr("ascending")));
    EXPECT_THAT(error("face: {crown_height: 8.0e-6, vertex_offset: 0.0}", "face: {table: [[-0.5e-3, 1e-6]]}"),
                StartsWith(file + ": rings[0].face.table"));
    EXPECT_THAT(error("face: {crown_height: 8.0e-6, vertex_offset: 0.0}",
                      "face: {crown_height: 8.0e-6, table: [[-0.5e-3, 1e-6], [0.5e-3, 0.0]]}"),
                HasSubstr("one of them"));
    EXPECT_THAT(error("face: {crown_height: 8.0e-6, vertex_offset: 0.0}", "lands: {width: 1e-4}"),
                StartsWith(file + ": rings[0].lands"));
    EXPECT_THAT(error("lands: {width: 0.4e-3, separation: 2.03e-3", "lands: {width: 0.4e-3, separation: 2.2e-3"),
                AllOf(StartsWith(file + ": rings[1].lands.separation"), HasSubstr("do not fit")));
    // The groove: the ring taller than it, off the ring belt, above the deck, overlapping.
    EXPECT_THAT(error("side_clearance: 0.05e-3", "side_clearance: -0.01e-3"),
                AllOf(StartsWith(file + ": rings[0].groove.side_clearance"), HasSubstr("taller")));
    EXPECT_THAT(error("lower_flank: 0.0138", "lower_flank: 0.009"),
                AllOf(StartsWith(file + ": rings[1].groove.lower_flank"), HasSubstr("piston.skirt_top = 0.0108")));
    EXPECT_THAT(error("lower_flank: 0.0253", "lower_flank: 0.033"),
                AllOf(StartsWith(file + ": rings[0].groove.lower_flank"), HasSubstr("above the deck")));
    EXPECT_THAT(error("lower_flank: 0.0138", "lower_flank: 0.0240"),
                AllOf(StartsWith(file + ": rings[1].groove.lower_flank"), HasSubstr("ring 'top'"),
                      HasSubstr("may not overlap")));
    EXPECT_THAT(error("back_clearance: 0.6e-3", "back_clerance: 0.6e-3"),
                AllOf(StartsWith(file + ": rings[0].groove.back_clerance"), HasSubstr("did you mean 'back_clearance'")));
    EXPECT_THAT(error("  pin_tdc_depth: 0.0335\n", ""), AllOf(HasSubstr("engine.pin_tdc_depth"),
                                                               HasSubstr("required with rings")));
}

TEST(CaseFileRings, TheRunRefusesTheOilControlBandBesideThePacksOilControlRing) {
    const fs::path dir = scratchDir();
    const EngineCase c = readCaseFile(caseWith(
        dir, {{"rings:\n", "lubricant: {cavitation: mass_conserving, supply: {model: liner_layer, thickness: 3e-6, "
                             "oil_control_ring: {bottom: 0.0138, top: 0.0163, thickness: 3e-6}}}\n"
                             "rings:\n"}}));
    EXPECT_THAT(errorOf([&] { runCase(c); }),
                AllOf(StartsWith(c.path + ": lubricant.supply.oil_control_ring"), HasSubstr("oil-control ring 'oil'")));
}

// ring_gas: the lands' gas between the rings (docs/case-file.md, "ring_gas"): read with its
// defaults, and bad values refused naming the key.
TEST(CaseFileRings, TheLandsGasIsReadAndBadValuesAreRefused) {
    const fs::path dir = scratchDir();
    const std::string file = (dir / "case.yaml").string();
    const EngineCase none = readCaseFile(caseWith(dir));
    EXPECT_EQ(none.ringGas.model, RingGasModel::None);
    const EngineCase lands = readCaseFile(caseWith(dir, {}, std::string(kTwoRings) + "ring_gas: {model: lands}\n"));
    EXPECT_EQ(lands.ringGas.model, RingGasModel::Lands);
    EXPECT_EQ(lands.ringGas.dischargeCoefficient, 0.86);
    EXPECT_EQ(lands.ringGas.landClearance, 0.3e-3);
    EXPECT_TRUE(lands.ringGas.landTemperatures.empty());
    EXPECT_FALSE(lands.ringGas.ringLift);
    EXPECT_TRUE(readCaseFile(caseWith(dir, {}, std::string(kTwoRings) + "ring_gas: {model: lands, ring_lift: true}\n"))
                    .ringGas.ringLift);
    const EngineCase given = readCaseFile(caseWith(
        dir, {},
        std::string(kTwoRings) +
            "ring_gas: {model: lands, discharge_coefficient: 0.7, land_clearance: 0.4e-3, land_temperatures: [470]}\n"));
    EXPECT_EQ(given.ringGas.dischargeCoefficient, 0.7);
    EXPECT_EQ(given.ringGas.landClearance, 0.4e-3);
    EXPECT_EQ(given.ringGas.landTemperatures, std::vector<double>{470.0});
    auto error = [&](const std::string& gas) {
        const std::string path = caseWith(dir, {}, std::string(kTwoRings) + gas);
        return errorOf([&] { readCaseFile(path); });
    };
    // The ring pack's loads on the flexible piston need the pack's gas with the rings' positions.
    CaseFileOptions noBodyFiles;
    noBodyFiles.checkBodyFiles = false;
    const std::string piston = "bodies: {piston: {file: p.h5, loads: [gas_pressure, ring_pack]}}\n";
    EXPECT_TRUE(readCaseFile(caseWith(dir, {}, std::string(kTwoRings) + "ring_gas: {model: lands, ring_lift: true}\n" + piston),
                             noBodyFiles)
                    .pistonBody.loads.ringPack);
    for (const std::string gas : {"", "ring_gas: {model: lands}\n"}) {
        const std::string path = caseWith(dir, {}, std::string(kTwoRings) + gas + piston);
        EXPECT_THAT(errorOf([&] { readCaseFile(path, noBodyFiles); }),
                    AllOf(StartsWith(file + ": bodies.piston.loads"), HasSubstr("ring_gas: {model: lands, ring_lift: true}")))
            << gas;
    }
    EXPECT_THAT(error("ring_gas: {model: blowby}\n"), StartsWith(file + ": ring_gas.model"));
    EXPECT_THAT(error("ring_gas: {model: lands, ring_lift: sometimes}\n"), StartsWith(file + ": ring_gas.ring_lift"));
    EXPECT_THAT(error("ring_gas: {model: lands, discharge_coefficient: 1.5}\n"),
                AllOf(StartsWith(file + ": ring_gas.discharge_coefficient"), HasSubstr("(0, 1]")));
    EXPECT_THAT(error("ring_gas: {model: lands, land_clearance: -1e-4}\n"), StartsWith(file + ": ring_gas.land_clearance"));
    EXPECT_THAT(error("ring_gas: {model: lands, land_temperatures: [470, 450]}\n"),
                AllOf(StartsWith(file + ": ring_gas.land_temperatures"), HasSubstr("1 temperatures")));
    EXPECT_THAT(error("ring_gas: {model: lands, land_temperatures: [-470]}\n"),
                AllOf(StartsWith(file + ": ring_gas.land_temperatures[0]"), HasSubstr("positive temperature")));
    // Grooves that meet leave no land for the gas.
    const std::string touching = caseWith(dir,
                                          {{"lower_flank: 0.0253", "lower_flank: 0.025300000000000003"},
                                           {"lower_flank: 0.0138", "lower_flank: 0.0228"}},
                                          std::string(kTwoRings) + "ring_gas: {model: lands}\n");
    EXPECT_THAT(errorOf([&] { readCaseFile(touching); }),
                AllOf(StartsWith(file + ": ring_gas.model"), HasSubstr("no land between")));
    // On the liner's oil layer the lands' gas runs (docs/ring-pack.md, "The pack's gas in a run").
    const std::string layer = caseWith(
        dir, {}, std::string(kTwoRings) + "ring_gas: {model: lands}\nlubricant: {cavitation: mass_conserving, supply: "
                                         "{model: liner_layer, thickness: 3e-6}}\n");
    EXPECT_EQ(readCaseFile(layer).ringGas.model, RingGasModel::Lands);
    // Without rings there is nothing to hold the gas.
    const std::string alone = caseWith(dir, {}, "ring_gas: {model: lands}\n");
    EXPECT_THAT(errorOf([&] { readCaseFile(alone); }), AllOf(StartsWith(file + ": ring_gas.model"), HasSubstr("ring pack")));
}
