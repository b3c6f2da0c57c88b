// `flexehd run` says where the grid does not resolve the thinnest film (docs/lube.md section 8):
// summary.json min_film_region_nodes counts the nodes across the region h ≤ h_min + max(h_min, σ)
// along the bore and the skirt, and a count below 4 is a warning naming the grid key. The example
// engine's hd.yaml on its own 48 x 144 grid resolves it (7 nodes around the bore); on 24 x 72 it
// does not (3), and there its largest contact force is twice the fine grid's.
#include "CliRunner.hpp"
#include "TestFiles.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using namespace flexehd;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {

struct GridRun {
    test::CommandResult result;
    nlohmann::json summary;
};

// One cycle of hd.yaml on `axial` x `circumferential` nodes.
GridRun oneCycle(const std::string& name, int axial, int circumferential) {
    const fs::path dir = test::scratchDir() / name;
    fs::create_directories(dir);
    std::string casePath = test::coarseHdCase(dir, dir / "out", {{"max_cycles: 5", "max_cycles: 1"}});
    std::ifstream in(casePath);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    text.replace(text.find("axial_nodes: 24"), 15, "axial_nodes: " + std::to_string(axial));
    text.replace(text.find("circumferential_nodes: 72"), 25, "circumferential_nodes: " + std::to_string(circumferential));
    test::writeFile(casePath, text);
    GridRun r{test::runFlexehd("run --quiet " + casePath), {}};
    std::ifstream s(dir / "out" / "summary.json");
    if (s) r.summary = nlohmann::json::parse(s);
    return r;
}

}  // namespace

TEST(FilmResolution, TheExampleGridResolvesTheThinnestFilmAndTheCoarseGridSaysItDoesNot) {
    const GridRun fine = oneCycle("fine", 48, 144), coarse = oneCycle("coarse", 24, 72);
    ASSERT_EQ(fine.result.status, 0) << fine.result.err;
    ASSERT_EQ(coarse.result.status, 0) << coarse.result.err;
    const auto nodes = [](const GridRun& r, const char* along) {
        return r.summary.at("min_film_region_nodes").at(along).get<double>();
    };
    EXPECT_GE(nodes(fine, "circumferential"), 4.0);
    EXPECT_THAT(fine.result.err, Not(HasSubstr("thinnest film's region")));
    EXPECT_LT(nodes(coarse, "circumferential"), 4.0);
    EXPECT_THAT(coarse.result.err, HasSubstr("grid node(s) around the bore"));
    EXPECT_THAT(coarse.result.err, HasSubstr("raise grid.circumferential_nodes"));
    // The warning is about something real: where the thinnest film is under-resolved, the
    // contact force it carries differs from the resolved grid's by more than a quarter.
    const double fineForce = fine.summary.at("contact_force_max_n").get<double>();
    const double coarseForce = coarse.summary.at("contact_force_max_n").get<double>();
    EXPECT_GT(std::abs(coarseForce - fineForce), 0.25 * fineForce) << coarseForce << " N against " << fineForce << " N";
}
