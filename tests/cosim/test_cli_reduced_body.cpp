// `flexehd inspect` and `flexehd export-modes` on a reduced-body file as a user runs them.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../fem/TestData.hpp"
#include "../modal/SyntheticBody.hpp"
#include "CliRunner.hpp"
#include "modal/ReducedBodyFile.hpp"

using flexehd::test::CommandResult;
using flexehd::test::runFlexehd;
using flexehd::test::scratchDir;
using testing::HasSubstr;

namespace {

/// A scratch directory holding body.h5, written from the synthetic body.
struct BodyFile {
    BodyFile() : dir(scratchDir()), body(flexehd::test::syntheticBody()), path((dir / "body.h5").string()) {
        flexehd::modal::writeReducedBody(body, path);
    }
    std::filesystem::path dir;
    flexehd::modal::ReducedBody body;
    std::string path;
};

}  // namespace

TEST(CliReducedBody, InspectJson) {
    const BodyFile f;
    const CommandResult r = runFlexehd("inspect " + f.path + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto doc = nlohmann::json::parse(r.out);  // stdout holds only the JSON object
    EXPECT_EQ(doc.at("format"), "flexehd-reduced-body");
    EXPECT_EQ(doc.at("format_version"), 1);
    EXPECT_EQ(doc.at("source_mesh").at("hash_fnv1a64"), f.body.meshHash);
    EXPECT_EQ(doc.at("source_mesh").at("path"), f.body.meshPath);
    EXPECT_EQ(doc.at("material").at("E_pa"), 2.1e11);
    EXPECT_EQ(doc.at("mesh").at("nodes"), f.body.mesh.numNodes());
    EXPECT_EQ(doc.at("mesh").at("element_type"), "TET10");
    EXPECT_EQ(doc.at("mesh").at("groups").size(), f.body.mesh.groups.size());
    ASSERT_EQ(doc.at("interfaces").size(), 2u);
    EXPECT_EQ(doc.at("interfaces")[1].at("group"), "xmax");
    EXPECT_EQ(doc.at("interfaces")[1].at("kind"), "rbe3");
    EXPECT_EQ(doc.at("interfaces")[1].at("reference_point_m"), (std::vector<double>{1.0, 0.5, 0.5}));
    EXPECT_EQ(doc.at("interfaces")[1].at("nodes"), f.body.interfaces[1].nodes.size());
    EXPECT_EQ(doc.at("modes"), 9);
    EXPECT_EQ(doc.at("rigid_body_modes"), 6);
    // JSON numbers are printed with round-trip precision.
    const auto freq = doc.at("frequencies_hz").get<std::vector<double>>();
    EXPECT_EQ(freq, std::vector<double>(f.body.frequenciesHz.data(), f.body.frequenciesHz.data() + 9));
    EXPECT_EQ(doc.at("damping_ratios").size(), 9u);
    EXPECT_EQ(doc.at("settings").at("static_correction"), (std::vector<std::string>{"xmax", "boundary"}));
    EXPECT_EQ(doc.at("settings").at("damping_ratio"), 0.02);
}

TEST(CliReducedBody, InspectSummary) {
    const BodyFile f;
    const CommandResult r = runFlexehd("inspect " + f.path);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("format version 1"));
    EXPECT_THAT(r.out, HasSubstr(f.body.meshHash));
    EXPECT_THAT(r.out, HasSubstr("TET10"));
    EXPECT_THAT(r.out, HasSubstr("xmin rbe2, reference point (0, 0.5, 0.5) m"));
    EXPECT_THAT(r.out, HasSubstr("9 (6 rigid-body)"));
    EXPECT_THAT(r.out, HasSubstr("frequency [Hz]"));
}

TEST(CliReducedBody, ExportModes) {
    const BodyFile f;
    const auto out = f.dir / "paraview";
    const CommandResult r = runFlexehd("export-modes " + f.path + " --out " + out.string() + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto doc = nlohmann::json::parse(r.out);
    EXPECT_EQ(doc.at("modes"), 9);
    const auto files = doc.at("output").at("files").get<std::vector<std::string>>();
    ASSERT_EQ(files.size(), 10u);
    EXPECT_EQ(files.front(), "mode_001.vtu");
    EXPECT_EQ(files.back(), "modes.pvd");
    for (const auto& name : files) EXPECT_TRUE(std::filesystem::exists(out / name)) << name;
    std::ifstream vtu(out / "mode_007.vtu");
    std::string head(2000, '\0');
    vtu.read(head.data(), head.size());
    EXPECT_THAT(head, HasSubstr("Name=\"displacement_m\""));
    EXPECT_THAT(head, HasSubstr("Name=\"eigenvalue_rad2_per_s2\""));
}

TEST(CliReducedBody, ClearErrors) {
    const auto dir = scratchDir();
    CommandResult r = runFlexehd("inspect " + (dir / "missing.h5").string());
    EXPECT_EQ(r.status, 1);
    EXPECT_TRUE(r.out.empty());
    EXPECT_THAT(r.err, HasSubstr("missing.h5' does not exist"));
    const auto text = (dir / "text.h5").string();
    std::ofstream(text) << "not HDF5\n";
    r = runFlexehd("export-modes " + text + " --out " + (dir / "out").string());
    EXPECT_EQ(r.status, 1);
    EXPECT_THAT(r.err, HasSubstr("not an HDF5 file or damaged"));
    r = runFlexehd("export-modes " + text);
    EXPECT_NE(r.status, 0);
    EXPECT_THAT(r.err, HasSubstr("--out"));
}
