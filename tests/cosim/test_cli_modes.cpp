// The `flexehd modes` command as a user runs it: JSON output, ParaView files, errors.
#include <array>
#include <cstdlib>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../fem/TestData.hpp"
#include "CliRunner.hpp"

using flexehd::test::CommandResult;
using flexehd::test::dataPath;
using flexehd::test::runFlexehd;
using testing::HasSubstr;

namespace {
const std::string kSteel = " --E 2.1e11 --nu 0.3 --rho 7850";
}  // namespace

TEST(CliModes, JsonOutputOfCantilever) {
    const CommandResult r = runFlexehd("modes --mesh " + dataPath("beam.geo") + kSteel + " --fix clamped --count 4 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto doc = nlohmann::json::parse(r.out);  // stdout holds only the JSON object
    const auto f = doc.at("frequencies_hz").get<std::vector<double>>();
    ASSERT_EQ(f.size(), 4u);
    EXPECT_TRUE(std::is_sorted(f.begin(), f.end()));
    // Euler–Bernoulli cantilever, L = 1 m, h = 0.02 m: f1 = 1.875104² / 2π √(E h² / 12ρ).
    const double f1 = 1.875104 * 1.875104 / (2 * std::numbers::pi) * std::sqrt(2.1e11 * 4e-4 / (12 * 7850));
    EXPECT_NEAR(f[0] / f1, 1.0, 0.015);
    EXPECT_EQ(doc.at("dofs").get<int>(), 3 * doc.at("nodes").get<int>());
    EXPECT_GT(doc.at("elements").get<int>(), 0);
    EXPECT_EQ(doc.at("element_type"), "TET10");
    EXPECT_EQ(doc.at("rigid_body_modes"), 0);
    EXPECT_TRUE(doc.at("timings_s").contains("eigensolve"));
}

TEST(CliModes, ParaViewFilesOfFreeBody) {
    const auto dir = flexehd::test::scratchDir();
    const CommandResult r = runFlexehd("modes --mesh " + dataPath("beam.geo") + kSteel + " --order 1 --count 8 --json --out " +
                          dir.string());
    ASSERT_EQ(r.status, 0) << r.err;
    const auto doc = nlohmann::json::parse(r.out);
    EXPECT_EQ(doc.at("rigid_body_modes"), 6);
    EXPECT_EQ(doc.at("element_type"), "TET4");
    std::ifstream pvd(dir / "modes.pvd");
    std::stringstream s;
    s << pvd.rdbuf();
    for (int k = 1; k <= 8; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "mode_%03d.vtu", k);
        EXPECT_THAT(s.str(), HasSubstr("timestep=\"" + std::to_string(k) + "\" group=\"\" part=\"0\" file=\"" + name));
        ASSERT_TRUE(std::filesystem::exists(dir / name));
        std::ifstream vtu(dir / name);
        std::string head(2000, '\0');
        vtu.read(head.data(), head.size());
        EXPECT_THAT(head, HasSubstr("type=\"UnstructuredGrid\""));
        EXPECT_THAT(head, HasSubstr("Name=\"displacement_m\" NumberOfComponents=\"3\" format=\"appended\""));
        EXPECT_THAT(head, HasSubstr("Name=\"frequency_hz\""));
    }
    for (const auto& e : std::filesystem::directory_iterator(dir)) EXPECT_NE(e.path().extension(), ".tmp");
}

TEST(CliModes, RigidBodyModesCountedWhenOnlyFewModesAreAsked) {
    // Six modes of a free body are all rigid: the flag must not depend on the spectrum computed.
    const CommandResult r = runFlexehd("modes --mesh " + dataPath("beam.geo") + kSteel + " --count 6 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out).at("rigid_body_modes"), 6);
}

TEST(CliModes, UnknownGroupIsAnErrorListingTheGroups) {
    const CommandResult r = runFlexehd("modes --mesh " + dataPath("beam.geo") + kSteel + " --fix crown");
    EXPECT_EQ(r.status, 1);
    EXPECT_TRUE(r.out.empty());
    EXPECT_THAT(r.err, HasSubstr("no physical group 'crown'"));
    EXPECT_THAT(r.err, HasSubstr("clamped (surface)"));
}

TEST(CliModes, MissingMeshAndBadArgumentsFail) {
    CommandResult r = runFlexehd("modes --mesh /nonexistent.msh" + kSteel);
    EXPECT_NE(r.status, 0);
    EXPECT_THAT(r.err, HasSubstr("/nonexistent.msh"));
    r = runFlexehd("modes --mesh " + dataPath("beam.geo") + " --E 2.1e11 --nu 0.7 --rho 7850");
    EXPECT_NE(r.status, 0);
    EXPECT_THAT(r.err, HasSubstr("--nu"));
    r = runFlexehd("modes --mesh " + dataPath("beam.geo") + " --E nan --nu 0.3 --rho 7850");
    EXPECT_NE(r.status, 0);
    EXPECT_THAT(r.err, HasSubstr("--E: expected a number from 1e5 to 1e13, got 'nan'"));
    r = runFlexehd("modes --mesh " + dataPath("beam.geo") + kSteel + " --fix clamped:q");
    EXPECT_NE(r.status, 0);
    EXPECT_THAT(r.err, HasSubstr("components 'q'"));
}

// Many modes of a model: a basis the machine cannot hold is refused before the solve (under an
// address-space limit of 1 GB, 3000 modes of the cube's DOFs need 2 × 6001 × DOFs doubles).
TEST(CliModes, TooManyModesForTheMemoryAreRefused) {
    // An address-space limit leaves no room for AddressSanitizer's shadow memory.
    if (std::getenv("FLEXEHD_SANITIZE")) GTEST_SKIP() << "address-space limit under AddressSanitizer";
    const int limit = flexehd::test::defaultChildTimeout();
    const std::string cmd = flexehd::test::timeLimited("sh -c 'ulimit -v 1000000 && exec " + std::string(FLEXEHD_BINARY) +
                                                           " modes --mesh " + dataPath("beam.geo") + kSteel +
                                                           " --count 3000'", limit) + " 2>&1";
    FILE* p = popen(cmd.c_str(), "r");
    ASSERT_NE(p, nullptr);
    std::string out;
    std::array<char, 4096> buf;
    while (std::size_t n = fread(buf.data(), 1, buf.size(), p)) out.append(buf.data(), n);
    const int status = WEXITSTATUS(pclose(p));
    flexehd::test::failedByTimeLimit(status, "flexehd modes --count 3000 (address space 1 GB)", limit);
    EXPECT_EQ(status, 1) << out;
    EXPECT_THAT(out, HasSubstr("flexehd: error: --count 3000: the Lanczos basis for 3000 modes of "));
    EXPECT_THAT(out, HasSubstr("are available: ask for fewer modes"));
}
