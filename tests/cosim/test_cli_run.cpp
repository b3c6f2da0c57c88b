// `flexehd run` end to end on a coarse version of the shipped example (examples/engine86): the
// results directory is complete and valid, and the secondary motion stays within the bands the
// seed paper reports for this engine (Dlugoš et al. 2016, §4: lateral displacement of the order
// of ±0.06 mm, tilt within a few tenths of a degree, slap at firing TDC) — a regression check
// on a 16 × 48 grid, one cycle.
#include "cosim/results/HistoryWriter.hpp"
#include "CliRunner.hpp"

#include <array>
#include <cstdlib>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using flexehd::test::runFlexehd;

namespace {

const std::string kSource = FLEXEHD_SOURCE_DIR;

void replace(std::string& text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
}

/// The example case `name` with a coarse grid, one cycle, output into `dir`.
std::string coarseCase(const std::string& name, const fs::path& dir, const std::string& pistonFile = "") {
    std::ifstream in(kSource + "/examples/engine86/" + name);
    std::stringstream ss;
    ss << in.rdbuf();
    std::string t = ss.str();
    replace(t, "axial_nodes: 48", "axial_nodes: 16");
    replace(t, "circumferential_nodes: 144", "circumferential_nodes: 48");
    replace(t, "max_cycles: 5", "max_cycles: 1");
    replace(t, "cylinder_pressure: cylinder_pressure.csv", "cylinder_pressure: " + kSource + "/examples/engine86/cylinder_pressure.csv");
    replace(t, "vtk_every_deg: 10.0", "vtk_every_deg: 90.0");
    replace(t, "mode_shapes: true", "mode_shapes: false");
    if (!pistonFile.empty()) replace(t, "file: ../../out/engine86/piston.h5", "file: " + pistonFile);
    const std::string start = "directory: ";
    const auto at = t.find(start);
    const auto end = t.find('\n', at);
    t.replace(at, end - at, start + (dir / "results").string());
    const fs::path file = dir / name;
    std::ofstream(file) << t;
    return file.string();
}

nlohmann::json checkResults(const fs::path& results) {
    // history.csv: complete lines, one cycle, crank angle from 0 to 720.
    const auto rows = flexehd::cosim::HistoryWriter::read((results / "history.csv").string());
    EXPECT_GT(rows.size(), 1000u);
    EXPECT_NEAR(rows.back().crankDeg, 720.0, 1e-6);
    std::ifstream f(results / "summary.json");
    const nlohmann::json s = nlohmann::json::parse(f);
    EXPECT_EQ(s["status"], "ok");
    // Seed bands: |e| of the order of 0.06 mm (20–100 µm), |β| < 0.5°, slap at firing TDC.
    const double emax = std::max(-s["lateral_min_m"].get<double>(), s["lateral_max_m"].get<double>());
    EXPECT_GT(emax, 20e-6);
    EXPECT_LT(emax, 100e-6);
    EXPECT_LT(s["lateral_min_m"].get<double>(), -10e-6);  // both sides of the bore are visited
    EXPECT_GT(s["lateral_max_m"].get<double>(), 10e-6);
    const double tmax = std::max(-s["tilt_min_rad"].get<double>(), s["tilt_max_rad"].get<double>());
    EXPECT_LT(tmax, 0.5 * 3.14159265 / 180.0);
    EXPECT_GT(s["slap_kinetic_energy_max_crank_deg"].get<double>(), 340.0);
    EXPECT_LT(s["slap_kinetic_energy_max_crank_deg"].get<double>(), 420.0);
    EXPECT_GT(s["friction_power_mean_w"].get<double>(), 0.0);
    // VTK series: a snapshot every 90° of the (only) cycle, listed in film.pvd.
    EXPECT_TRUE(fs::exists(results / "film.pvd"));
    int vts = 0;
    for (const auto& e : fs::directory_iterator(results / "vtk")) vts += e.path().extension() == ".vts";
    EXPECT_EQ(vts, 8);
    return s;
}

}  // namespace

TEST(CliRun, RigidExampleCoarseWithinTheSeedBands) {
    const fs::path dir = fs::temp_directory_path() / ("flexehd_run_hd_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const auto r = runFlexehd("run " + coarseCase("hd.yaml", dir) + " --quiet --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto s = checkResults(dir / "results");
    EXPECT_EQ(nlohmann::json::parse(r.out)["fmep_pa"], s["fmep_pa"]);
    fs::remove_all(dir);
}

TEST(CliRun, FlexiblePistonCoarse) {
    const fs::path dir = fs::temp_directory_path() / ("flexehd_run_ehd_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string body = (dir / "piston.h5").string();
    const auto red = runFlexehd("reduce --mesh " + kSource + "/meshes/piston.geo --size 0.0065 --E 7.5e10 --nu 0.33 "
                                "--rho 2700 --interface pin_bore:rbe2@0,0,0 --modes 10 --static-correction skirt "
                                "--axial-order 2 --circumferential-order 4 --out " + body);
    ASSERT_EQ(red.status, 0) << red.err;
    const auto r = runFlexehd("run " + coarseCase("case.yaml", dir, body) + " --quiet");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto s = checkResults(dir / "results");
    // The skirt receives the film's load. The mapping itself is exact for the bilinear field
    // (test_mapping, 1e-12); what summary.json reports is its difference from the film force
    // the dynamics uses (trapezoidal sum over the grid's control volumes), which is a
    // discretisation difference at the panel edges, O(cell width): measured 2.3 % of the peak
    // film force on this 16 × 48 grid, 0.19 % on the default 48 × 144 grid. Bound: one
    // 7.5° cell's share of a ±40° panel, 7.5 / 80 ≈ 9 %.
    EXPECT_LT(s["load_mapping_conservation_error_max"].get<double>(), 7.5 / 80.0);
    EXPECT_TRUE(fs::exists(dir / "results" / "piston.pvd"));
    // A surface or interface the body does not have: the error names the case file, the case
    // key and the .h5, and lists what the body has.
    const std::string file = coarseCase("case.yaml", dir, body);
    const auto withLines = [&](const std::vector<std::pair<std::string, std::string>>& edits) {
        std::ifstream in(file);
        std::stringstream ss;
        ss << in.rdbuf();
        std::string t = ss.str();
        for (const auto& [from, to] : edits) replace(t, from, to);
        const std::string bad = (dir / "bad.yaml").string();
        std::ofstream(bad) << t;
        return runFlexehd("run " + bad + " --quiet");
    };
    const auto withLine = [&](const std::string& from, const std::string& to) { return withLines({{from, to}}); };
    const auto surface = withLine("surface: skirt", "surface: skrit");
    EXPECT_EQ(surface.status, 1);
    EXPECT_NE(surface.err.find("bad.yaml: bodies.piston.surface: 'skrit' is not a physical group of the reduced body " +
                               body + " (its surface groups: "),
              std::string::npos)
        << surface.err;
    const auto volume = withLine("surface: skirt", "surface: piston");
    EXPECT_NE(volume.err.find("bodies.piston.surface: 'piston' of the reduced body " + body + " is a volume group"),
              std::string::npos)
        << volume.err;
    // A film grid that the body's skirt surface mostly misses (the case's skirt 106 mm long, the
    // mesh's 36 mm: 71 % of the film nodes outside): refused before the run, with the z ranges of
    // both and the question whether the body is the right one.
    const auto longer = withLines({{"skirt_bottom: -0.025", "skirt_bottom: -0.095"},
                                  {"- [-0.0250, 20.0e-6]", "- [-0.0950, 20.0e-6]\n    - [-0.0250, 20.0e-6]"}});
    EXPECT_EQ(longer.status, 1) << longer.err;
    EXPECT_NE(longer.err.find("film nodes of the piston's grid (71 %, more than 25 %) lie outside the surface 'skirt' "
                              "of the reduced body " + body),
              std::string::npos)
        << longer.err;
    EXPECT_NE(longer.err.find("the surface spans z -25.0 to 10.8 mm; is " + body + " the piston's reduced body"),
              std::string::npos)
        << longer.err;
    const auto lands = withLine("surface: skirt", "surface: ring_lands");
    EXPECT_EQ(lands.status, 1);
    EXPECT_NE(lands.err.find("bad.yaml: bodies.piston.surface: the reduced body " + body + " cannot face the film: "
                             "surface 'ring_lands' is not a cylinder about z: node radii from 42.55 to 42.7 mm"),
              std::string::npos)
        << lands.err;
    EXPECT_EQ(lands.err.find("Mapping"), std::string::npos) << lands.err;
    EXPECT_EQ(lands.err.find(".geo"), std::string::npos) << lands.err;
    const auto itf = withLine("interface: pin_bore", "interface: pin_bor");
    EXPECT_NE(itf.err.find("bodies.piston.interface: 'pin_bor' is not an interface of the reduced body " + body +
                           " (its interfaces: pin_bore)"),
              std::string::npos)
        << itf.err;
    fs::remove_all(dir);
}

TEST(CliRun, BadCaseNamesTheKey) {
    const fs::path dir = fs::temp_directory_path() / ("flexehd_run_bad_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::string file = coarseCase("hd.yaml", dir);
    std::ifstream in(file);
    std::stringstream ss;
    ss << in.rdbuf();
    std::string t = ss.str();
    replace(t, "clearance: 50.0e-6", "clearance: -50.0e-6");
    std::ofstream(file) << t;
    const auto r = runFlexehd("run " + file + " --quiet");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("piston.clearance"), std::string::npos) << r.err;
    fs::remove_all(dir);
}

// A grid too large for the machine is refused before it is allocated, with the nodes, the
// memory they need (the documented lower bound: 500 bytes per node on a rigid run) and what is
// available (the 200 GB grid assumes a test machine with less); under an address-space limit
// of 2 GB a grid of 9 million nodes (≥ 4.5 GB) is too. Beyond 32-bit node indices it is
// refused as such.
TEST(CliRun, GridTooLargeForTheMemoryIsRefusedBeforeItIsAllocated) {
    const fs::path dir = fs::temp_directory_path() / ("flexehd_run_huge_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string file = coarseCase("hd.yaml", dir);
    const auto withGrid = [&](const std::string& nz, const std::string& nt) {
        std::ifstream in(file);
        std::stringstream ss;
        ss << in.rdbuf();
        std::string t = ss.str();
        replace(t, "axial_nodes: 16", "axial_nodes: " + nz);
        replace(t, "circumferential_nodes: 48", "circumferential_nodes: " + nt);
        const std::string big = (dir / ("grid_" + nz + ".yaml")).string();
        std::ofstream(big) << t;
        return big;
    };
    const std::string huge = withGrid("20000", "100000");
    const auto r = runFlexehd("run " + huge + " --quiet");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("flexehd: error: " + huge + ": grid: the film grid of 20000 × 100000 = 2000000000 nodes "
                         "is larger than the film solvers can index"),
              std::string::npos)
        << r.err;
    const std::string large = withGrid("4000", "100000");
    const auto l = runFlexehd("run " + large + " --quiet");
    EXPECT_EQ(l.status, 1);
    EXPECT_NE(l.err.find("flexehd: error: " + large + ": grid: the film grid of 4000 × 100000 = 400000000 nodes "
                         "needs at least 200 GB of memory; "),
              std::string::npos)
        << l.err;
    EXPECT_NE(l.err.find(" are available: use a coarser grid"), std::string::npos) << l.err;
    EXPECT_EQ(l.err.find("bad_alloc"), std::string::npos) << l.err;

    // An address-space limit leaves no room for AddressSanitizer's shadow memory.
    if (std::getenv("FLEXEHD_SANITIZE")) GTEST_SKIP() << "address-space limit under AddressSanitizer";
    const std::string big = withGrid("3000", "3000");
    const int limit = flexehd::test::defaultChildTimeout();
    const std::string cmd = flexehd::test::timeLimited("sh -c 'ulimit -v 2000000 && exec " + std::string(FLEXEHD_BINARY) +
                                                           " run " + big + " --quiet'", limit) + " 2>&1";
    FILE* p = popen(cmd.c_str(), "r");
    ASSERT_NE(p, nullptr);
    std::string out;
    std::array<char, 4096> buf;
    while (std::size_t n = fread(buf.data(), 1, buf.size(), p)) out.append(buf.data(), n);
    const int status = WEXITSTATUS(pclose(p));
    flexehd::test::failedByTimeLimit(status, "flexehd run " + big + " (address space 2 GB)", limit);
    EXPECT_EQ(status, 1) << out;
    EXPECT_NE(out.find(": grid: the film grid of 3000 × 3000 = 9000000 nodes needs at least 4.5 GB of memory; 2.0 GB "
                       "are available"),
              std::string::npos)
        << out;
    fs::remove_all(dir);
}

// Periodicity compares a cycle with the one before: after one cycle it is not judged.
TEST(CliRun, OneCycleSaysPeriodicityIsNotChecked) {
    const fs::path dir = fs::temp_directory_path() / ("flexehd_run_once_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string file = coarseCase("hd.yaml", dir);
    // What a killed run into the same directory left is cleaned up, and said so.
    fs::create_directories(dir / "results" / "vtk");
    std::ofstream(dir / "results" / "vtk" / "film_0002.vts.tmp") << "half";
    const auto once = runFlexehd("run " + file + " --cycles 1");
    ASSERT_EQ(once.status, 0) << once.err;
    EXPECT_FALSE(fs::exists(dir / "results" / "vtk" / "film_0002.vts.tmp"));
    EXPECT_NE(once.err.find("removed 1 unfinished .tmp file(s) that an interrupted run left in"), std::string::npos)
        << once.err;
    EXPECT_NE(once.out.find("1 cycle (periodicity not checked: it needs two cycles)"), std::string::npos) << once.out;
    const auto twice = runFlexehd("run " + file + " --cycles 2");
    ASSERT_EQ(twice.status, 0) << twice.err;
    EXPECT_EQ(twice.out.find("periodicity not checked"), std::string::npos) << twice.out;
    EXPECT_NE(twice.out.find("2 cycles ("), std::string::npos) << twice.out;
    // history.csv: the header is the first line (numpy.genfromtxt(names=True) reads it there) and
    // one line per accepted step, time rising strictly also across the cycle boundary.
    std::ifstream in(dir / "results" / "history.csv");
    std::string first;
    std::getline(in, first);
    EXPECT_EQ(first.rfind("cycle,crank_deg,time_s,", 0), 0u) << first;
    const auto rows = flexehd::cosim::HistoryWriter::read((dir / "results" / "history.csv").string());
    ASSERT_GT(rows.size(), 2u);
    EXPECT_EQ(rows.back().cycle, 2);
    for (std::size_t k = 1; k < rows.size(); ++k)
        ASSERT_GT(rows[k].time, rows[k - 1].time) << "row " << k + 1 << " at crank " << rows[k].crankDeg;
    fs::remove_all(dir);
}

// The global -q means what run's --quiet means: no progress output.
TEST(CliRun, GlobalQuietSilencesTheProgress) {
    const fs::path dir = fs::temp_directory_path() / ("flexehd_run_q_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string file = coarseCase("hd.yaml", dir);
    const auto loud = runFlexehd("run " + file + " --cycles 1");
    ASSERT_EQ(loud.status, 0) << loud.err;
    EXPECT_NE(loud.err.find("cycle 1"), std::string::npos) << "progress expected without -q: " << loud.err;
    for (const std::string& q : {"-q run " + file, "run " + file + " --quiet"}) {
        const auto quiet = runFlexehd(q + " --cycles 1");
        ASSERT_EQ(quiet.status, 0) << quiet.err;
        // Warnings stay (this coarse grid's: the thinnest film under-resolved); progress goes.
        std::istringstream lines(quiet.err);
        std::string progress;
        for (std::string line; std::getline(lines, line);)
            if (line.find("the thinnest film's region") == std::string::npos) progress += line + "\n";
        EXPECT_EQ(progress, "") << q;
        EXPECT_EQ(quiet.out, "") << q;
    }
    fs::remove_all(dir);
}

// Command-line errors follow the error convention: "flexehd: error: OPTION: expected …, got …",
// exit code 1, ranges as people write them; --help still exits 0.
TEST(CliRun, CommandLineErrorsSayWhatIsExpected) {
    const std::string example = std::string(FLEXEHD_SOURCE_DIR) + "/examples/engine86/hd.yaml";
    const std::pair<std::string, std::string> cases[] = {
        {"run --cycles 0 " + example, "flexehd: error: --cycles: expected a whole number ≥ 1, got '0'"},
        {"run --cycles abc " + example, "flexehd: error: --cycles: expected a whole number ≥ 1, got 'abc'"},
        {"run --cycles 2.5 " + example, "flexehd: error: --cycles: expected a whole number ≥ 1, got '2.5'"},
        {"modes --mesh x.geo --E 2e11 --nu 0.6 --rho 7850", "flexehd: error: --nu: expected a number from -0.999 to 0.499, got '0.6'"},
        {"run --no-such-option " + example, "flexehd: error: "},
    };
    for (const auto& [args, message] : cases) {
        const auto r = runFlexehd(args);
        EXPECT_EQ(r.status, 1) << args << "\n" << r.err;
        EXPECT_EQ(r.err.rfind(message, 0), 0u) << args << "\n" << r.err;
        EXPECT_EQ(r.err.find("17976931348623157"), std::string::npos) << r.err;
    }
    const auto help = runFlexehd("run --help");
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.out.find("--cycles"), std::string::npos);
}
