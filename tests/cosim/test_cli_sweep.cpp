// `flexehd sweep`: study files (designs, errors), and small studies of the coarse rigid example
// (16 × 48 grid, one cycle): one process and two MPI ranks give the same study.csv, a killed
// study resumes with only the missing variant, a failing variant is recorded with its error.
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/study/BodyCache.hpp"
#include "cosim/study/StudyFile.hpp"
#include "cosim/study/VariantCase.hpp"
#include "CliRunner.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <thread>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <utility>

namespace fs = std::filesystem;
using flexehd::test::CommandResult;
using flexehd::test::runFlexehd;
using testing::AllOf;
using testing::HasSubstr;
using testing::Not;

namespace {

const std::string kSource = FLEXEHD_SOURCE_DIR;

struct TempDir {
    fs::path path;
    explicit TempDir(const std::string& name)
        : path(fs::temp_directory_path() / ("flexehd_sweep_" + name + "_" + std::to_string(::getpid()))) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
};

/// A study of the rigid example engine, coarse: `body` gives design, parameters, etc.
std::string writeStudy(const fs::path& dir, const std::string& body, const std::string& name = "study.yaml") {
    const fs::path file = dir / name;
    std::ofstream(file) << "name: test study\n"
                        << "base_case: " << kSource << "/examples/engine86/hd.yaml\n"
                        << "directory: results\n"
                        << "set:\n"
                        << "  grid.axial_nodes: 16\n"
                        << "  grid.circumferential_nodes: 48\n"
                        << "  time.max_cycles: 1\n"
                        << "  output.vtk_every_deg: 0\n"
                        << "  output.mode_shapes: false\n"
                        << body;
    return file.string();
}

// The message readStudyFile throws for the study (written as writeStudy does), or "no error".
std::string studyError(const fs::path& dir, const std::string& body, const std::string& name = "study.yaml") {
    try {
        flexehd::cosim::readStudyFile(writeStudy(dir, body, name));
    } catch (const std::exception& e) {
        return e.what();
    }
    return "no error";
}

std::string readText(const fs::path& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

/// study.csv without its run_time_s column (the one column that differs between runs).
std::vector<std::string> csvWithoutTimes(const fs::path& p) {
    std::vector<std::string> lines;
    std::istringstream in(readText(p));
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    for (std::stringstream h(line); std::getline(h, line, ',');) header.push_back(line);
    const auto col = std::find(header.begin(), header.end(), "run_time_s") - header.begin();
    std::istringstream again(readText(p));
    while (std::getline(again, line)) {
        std::vector<std::string> f;
        for (std::stringstream s(line); std::getline(s, line, ',');) f.push_back(line);
        if (col < long(f.size())) f.erase(f.begin() + col);
        std::string joined;
        for (const auto& x : f) joined += x + ",";
        lines.push_back(joined);
    }
    return lines;
}

// mpirun -n RANKS flexehd ARGS, stopped after `timeoutSeconds` with its ranks (a test failure then).
CommandResult runMpi(int ranks, const std::string& args, int timeoutSeconds = flexehd::test::defaultChildTimeout()) {
    // Open MPI refuses root unless told; the container runs tests as root.
    const std::string cmd = std::string("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ") +
                            flexehd::test::timeLimited(std::string(FLEXEHD_MPIEXEC) + " -n " + std::to_string(ranks) +
                                                           " --oversubscribe " + FLEXEHD_BINARY + " " + args,
                                                       timeoutSeconds);
    const auto err = fs::temp_directory_path() / ("flexehd_mpi_err_" + std::to_string(::getpid()));
    CommandResult r;
    FILE* p = popen((cmd + " 2>" + err.string()).c_str(), "r");
    std::array<char, 4096> buf;
    while (std::size_t n = fread(buf.data(), 1, buf.size(), p)) r.out.append(buf.data(), n);
    r.status = WEXITSTATUS(pclose(p));
    r.err = readText(err);
    fs::remove(err);
    flexehd::test::failedByTimeLimit(r.status, "mpirun -n " + std::to_string(ranks) + " flexehd " + args, timeoutSeconds);
    return r;
}

nlohmann::json studyJson(const fs::path& dir) { return nlohmann::json::parse(readText(dir / "study.json")); }

}  // namespace

// ---- study files ---------------------------------------------------------------------------

TEST(StudyFile, FullFactorialListsAndRanges) {
    TempDir t("factorial");
    const auto s = flexehd::cosim::readStudyFile(writeStudy(t.path,
        "parameters:\n"
        "  engine.pin_offset: [-0.5e-3, 0.0]\n"
        "  piston.clearance: {start: 30e-6, stop: 70e-6, count: 3}\n"));
    ASSERT_EQ(s.variants.size(), 6u);
    EXPECT_EQ(s.parameters, (std::vector<std::string>{"engine.pin_offset", "piston.clearance"}));
    EXPECT_EQ(s.variants[0].values, (std::vector<std::string>{"-0.5e-3", "3e-05"}));
    EXPECT_EQ(s.variants[2].values, (std::vector<std::string>{"-0.5e-3", "7e-05"}));  // the last key varies fastest
    EXPECT_EQ(s.variants[4].values, (std::vector<std::string>{"0.0", "5e-05"}));
    EXPECT_EQ(s.variants[5].id, "v0005");
    EXPECT_EQ(s.directory, (t.path / "results").string());
    EXPECT_EQ(s.outputs, flexehd::cosim::defaultStudyOutputs());
    // The variant's case: the value set, the paths absolute, the fixed keys applied.
    const std::string c = flexehd::cosim::variantCaseText(s, s.variants[4]);
    EXPECT_THAT(c, HasSubstr("clearance: 5e-05"));
    EXPECT_THAT(c, HasSubstr("axial_nodes: 16"));
    EXPECT_THAT(c, HasSubstr("cylinder_pressure: " + kSource + "/examples/engine86/cylinder_pressure.csv"));
}

// The contacts' figures are outputs a study can collect: the rings', the assembly's FMEP, the
// oil-control band's drain; a misspelt figure is refused naming the valid ones.
TEST(StudyFile, ContactFiguresAreOutputs) {
    TempDir t("contact_outputs");
    const auto s = flexehd::cosim::readStudyFile(writeStudy(
        t.path, "parameters:\n  engine.pin_offset: [0.0]\noutputs: [fmep_pa, fmep_total_pa, rings.top.fmep_pa, "
                "rings.oil_control.min_film_m, oil_control_ring.drain_mean_m3_per_s]\n"));
    EXPECT_EQ(s.outputs.size(), 5u);
    EXPECT_THAT(studyError(t.path, "parameters:\n  engine.pin_offset: [0.0]\noutputs: [rings.top.fmep]\n"),
                AllOf(HasSubstr("'rings.top.fmep' is not a summary.json key"), HasSubstr("fmep_total_pa"),
                      HasSubstr("boundary_friction_power_mean_w")));
    EXPECT_THAT(studyError(t.path, "parameters:\n  engine.pin_offset: [0.0]\noutputs: [rings..fmep_pa]\n"),
                HasSubstr("is not a summary.json key"));
}

// A ring-pack file named relative to the study is found from the variant's case, written elsewhere.
TEST(StudyFile, ARingPackFileIsFoundFromTheVariantsCase) {
    TempDir t("rings");
    fs::copy_file(kSource + "/examples/engine86/rings.yaml", t.path / "pack.yaml");
    const auto s = flexehd::cosim::readStudyFile(
        writeStudy(t.path, "  rings: pack.yaml\nparameters:\n  engine.pin_offset: [0.0]\n"));
    ASSERT_EQ(s.variants.size(), 1u);
    const std::string text = flexehd::cosim::variantCaseText(s, s.variants[0]);
    EXPECT_THAT(text, HasSubstr("rings: " + (t.path / "pack.yaml").string()));
    fs::create_directories(t.path / "elsewhere");
    const fs::path file = t.path / "elsewhere" / "variant.yaml";
    std::ofstream(file) << text;
    flexehd::cosim::CaseFileOptions noBodyFiles;
    noBodyFiles.checkBodyFiles = false;
    EXPECT_EQ(flexehd::cosim::readCaseFile(file.string(), noBodyFiles).rings.size(), 3u);
}

// Every study the examples ship names case-file keys only, and every variant's case reads
// (values in their ranges; the bodies' files are not looked for). A variant on the liner's oil
// layer runs at that layer's step tolerance (a starved skirt's cycles repeat only then,
// docs/coupling.md §1): no base case or study sets the flooded film's value for it.
TEST(StudyFile, ShippedExampleStudiesGiveValidCases) {
    TempDir t("examples");
    int studies = 0;
    for (const auto& entry : fs::directory_iterator(kSource + "/examples/engine86")) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("study_", 0) != 0 || entry.path().extension() != ".yaml") continue;
        ++studies;
        const auto s = flexehd::cosim::readStudyFile(entry.path().string(), (t.path / name).string());
        ASSERT_FALSE(s.variants.empty()) << name;
        EXPECT_NO_THROW(flexehd::cosim::checkCaseKeys(s)) << name;
        flexehd::cosim::CaseFileOptions noBodyFiles;
        noBodyFiles.checkBodyFiles = false;
        for (const auto& v : s.variants) {
            const fs::path file = t.path / (name + "." + v.id + ".yaml");
            std::ofstream(file) << flexehd::cosim::variantCaseText(s, v);
            try {
                const flexehd::cosim::EngineCase c = flexehd::cosim::readCaseFile(file.string(), noBodyFiles);
                if (c.lubricant.supply.model == flexehd::cosim::OilSupplyModel::LinerLayer) {
                    EXPECT_EQ(c.time.lateralTolerance, flexehd::cosim::TimeSpec::kStarvedLateralTolerance)
                        << name << " " << v.id;
                    EXPECT_EQ(c.time.tiltTolerance, flexehd::cosim::TimeSpec::kStarvedTiltTolerance) << name << " " << v.id;
                }
            } catch (const std::exception& e) {
                ADD_FAILURE() << name << " " << v.id << ": " << e.what();
            }
        }
    }
    EXPECT_GE(studies, 3);
}

// A non-periodic variant's spread over its cycles is a study output like any summary.json key.
TEST(StudyFile, CycleToCycleFiguresAreOutputs) {
    TempDir t("spread");
    const auto s = flexehd::cosim::readStudyFile(writeStudy(t.path,
        "parameters:\n"
        "  engine.speed_rpm: [1000, 2000]\n"
        "outputs: [friction_power_mean_w, cycle_to_cycle.friction_power_mean_w.std, cycle_to_cycle.min_film_m.min]\n"));
    EXPECT_EQ(s.outputs.size(), 3u);
    EXPECT_THAT(studyError(t.path,
                           "parameters:\n  engine.speed_rpm: [1000]\noutputs: [cycle_to_cycle.friction_power_mean_w.median]\n",
                           "bad.yaml"),
                HasSubstr("'cycle_to_cycle.friction_power_mean_w.median' is not a summary.json key"));
}

TEST(StudyFile, LatinHypercubeHitsEveryStratumOnce) {
    TempDir t("lhs");
    const std::string body = "design: latin_hypercube\nsamples: 8\nseed: 42\n"
                             "parameters:\n"
                             "  piston.clearance: {min: 20e-6, max: 60e-6}\n"
                             "  lubricant.viscosity: {min: 0.005, max: 0.013}\n";
    const auto s = flexehd::cosim::readStudyFile(writeStudy(t.path, body));
    ASSERT_EQ(s.variants.size(), 8u);
    for (std::size_t p = 0; p < 2; ++p) {
        const double lo = p == 0 ? 20e-6 : 0.005, hi = p == 0 ? 60e-6 : 0.013;
        std::set<int> strata;
        for (const auto& v : s.variants) strata.insert(int((std::stod(v.values[p]) - lo) / (hi - lo) * 8));
        EXPECT_EQ(strata.size(), 8u) << s.parameters[p];
    }
    const auto again = flexehd::cosim::readStudyFile(writeStudy(t.path, body, "again.yaml"));
    EXPECT_EQ(again.variants[3].values, s.variants[3].values);  // the seed fixes the sample
}

TEST(StudyFile, TableAndBodyRecipesShareCachedBodies) {
    TempDir t("table");
    const auto s = flexehd::cosim::readStudyFile(writeStudy(t.path,
        "design: table\n"
        "variants:\n"
        "  - {piston.clearance: 40e-6, reduce.piston.modes: 10}\n"
        "  - {piston.clearance: 60e-6, reduce.piston.modes: 10}\n"
        "  - {piston.clearance: 60e-6, reduce.piston.modes: 12}\n"
        "reduce:\n"
        "  piston: {mesh: " + kSource + "/meshes/piston.geo, size: 0.0065, E: 7.5e10, nu: 0.33, rho: 2700,\n"
        "           interface: [\"pin_bore:rbe2@0,0,0\"], static_correction: skirt}\n"));
    ASSERT_EQ(s.variants.size(), 3u);
    const auto b0 = flexehd::cosim::variantBodies(s, s.variants[0]);
    const auto b1 = flexehd::cosim::variantBodies(s, s.variants[1]);
    const auto b2 = flexehd::cosim::variantBodies(s, s.variants[2]);
    ASSERT_EQ(b0.size(), 1u);
    EXPECT_EQ(b0[0].file, b1[0].file);  // same recipe: built once
    EXPECT_NE(b0[0].file, b2[0].file);
    EXPECT_THAT(b0[0].args, testing::Contains("pin_bore:rbe2@0,0,0"));
    const std::string c = flexehd::cosim::variantCaseText(s, s.variants[0], {{"piston", b0[0].file}});
    EXPECT_THAT(c, HasSubstr("file: " + b0[0].file));  // the rigid piston of the base case became this body
}

TEST(StudyFile, BadInputIsAClearError) {
    TempDir t("bad");
    auto error = [&](const std::string& body) { return studyError(t.path, body); };
    EXPECT_THAT(error("parameters:\n  engine.pin_ofset: [0.0, 1e-3]\n"),
                AllOf(HasSubstr("parameters.engine.pin_ofset: not a case-file key"), HasSubstr("did you mean 'pin_offset'")));
    EXPECT_THAT(error("parameters:\n  engine.pin_offset: [0.0]\nsamplez: 3\n"), HasSubstr("samplez (line"));
    EXPECT_THAT(error("parameters:\n  engine.pin_offset: [0.0]\noutputs: [friction_power]\n"),
                HasSubstr("'friction_power' is not a summary.json key"));
    EXPECT_THAT(error("design: latin_hypercube\nparameters:\n  engine.pin_offset: {min: 0, max: 1e-3}\n"),
                HasSubstr("needs samples"));
    EXPECT_THAT(error("parameters:\n  engine.bore.x: [1]\n"), HasSubstr("engine.bore is '0.086' in the base case"));
    EXPECT_THAT(error("parameters:\n  reduce.piston.size: [0.006]\n"), HasSubstr("no reduced-body recipe"));
    // Counted before the variants are made: a range of 1e9 values, two of 1e5 each (1e10 variants)
    // and 1e9 samples are refused at once, naming the key and the count (expanded, each would
    // take tens of GB).
    EXPECT_THAT(error("parameters:\n  engine.speed_rpm: {start: 1000, stop: 7000, count: 1000000000}\n"),
                AllOf(HasSubstr("parameters.engine.speed_rpm.count"), HasSubstr("a range of 1000000000 values"),
                      HasSubstr("at most 1000000 variants")));
    EXPECT_THAT(error("parameters:\n  engine.speed_rpm: {start: 1000, stop: 7000, count: 100000}\n"
                      "  engine.pin_offset: {start: 0, stop: 1e-3, count: 100000}\n"),
                AllOf(HasSubstr("1e+10 variants (100000 engine.speed_rpm x 100000 engine.pin_offset)"),
                      HasSubstr("at most 1000000 variants")));
    EXPECT_THAT(error("design: latin_hypercube\nsamples: 1000000000\nparameters:\n"
                      "  engine.pin_offset: {min: 0, max: 1e-3}\n"),
                AllOf(HasSubstr("samples"), HasSubstr("1000000000 samples: a study runs at most 1000000 variants")));
    // And through the command line: message and exit code 1.
    const auto r = runFlexehd("sweep " + writeStudy(t.path, "parameters:\n  piston.clearence: [5e-5]\n") + " --quiet");
    EXPECT_EQ(r.status, 1);
    EXPECT_THAT(r.err, HasSubstr("flexehd: error: "));
    EXPECT_THAT(r.err, HasSubstr("parameters.piston.clearence: not a case-file key"));
}

// ---- studies that run ------------------------------------------------------------------------

TEST(CliSweep, OneProcessAndTwoMpiRanksGiveTheSameStudy) {
    TempDir t("mpi");
    const std::string study = writeStudy(t.path, "parameters:\n  engine.pin_offset: [-0.8e-3, 0.0, 0.8e-3]\n");
    const auto one = runFlexehd("sweep " + study + " --out " + (t.path / "one").string() + " --quiet --json");
    ASSERT_EQ(one.status, 0) << one.err;
    const auto two = runMpi(2, "sweep " + study + " --out " + (t.path / "two").string() + " --quiet --json");
    ASSERT_EQ(two.status, 0) << two.err << two.out;
    const auto j1 = nlohmann::json::parse(one.out), j2 = nlohmann::json::parse(two.out);
    EXPECT_EQ(j1["ranks"], 1);
    EXPECT_EQ(j2["ranks"], 2);
    EXPECT_EQ(j1["ok"], 3);
    EXPECT_EQ(j2["ok"], 3);
    const auto a = csvWithoutTimes(t.path / "one" / "study.csv"), b = csvWithoutTimes(t.path / "two" / "study.csv");
    ASSERT_EQ(a.size(), 4u);  // header + 3 variants
    EXPECT_EQ(a, b);
    // Both ranks ran variants; the pin offset moves the secondary motion.
    std::set<int> ranks;
    const auto twoJson = studyJson(t.path / "two");
    for (const auto& v : twoJson["variants"]) ranks.insert(v["rank"].get<int>());
    EXPECT_EQ(ranks.size(), 2u);
    const auto v = studyJson(t.path / "one")["variants"];
    EXPECT_NE(v[0]["outputs"]["lateral_max_m"], v[2]["outputs"]["lateral_max_m"]);
    EXPECT_GT(v[1]["outputs"]["friction_power_mean_w"].get<double>(), 0.0);
}

TEST(CliSweep, ResumesWithOnlyTheMissingVariantAndRecordsAFailingOne) {
    TempDir t("resume");
    // v0001 has a negative clearance: it fails, the others complete.
    const std::string study = writeStudy(t.path, "design: table\nvariants:\n"
                                                 "  - {piston.clearance: 40e-6}\n"
                                                 "  - {piston.clearance: -5e-6}\n"
                                                 "  - {piston.clearance: 60e-6}\n");
    const fs::path dir = t.path / "results";
    const auto first = runFlexehd("sweep " + study + " --quiet --json");
    ASSERT_EQ(first.status, 2) << first.err;  // the study ran to its end, a variant failed
    auto j = nlohmann::json::parse(first.out);
    EXPECT_EQ(j["ok"], 2);
    EXPECT_EQ(j["failed"], 1);
    auto s = studyJson(dir);
    EXPECT_EQ(s["variants"][1]["status"], "failed");
    EXPECT_THAT(s["variants"][1]["message"].get<std::string>(), HasSubstr("piston.clearance"));
    EXPECT_EQ(s["variants"][2]["status"], "ok");
    EXPECT_THAT(readText(dir / "study.csv"), HasSubstr("1,v0001,-5e-6,failed,"));

    // An interrupted study: v0002's results are gone (and its row with them).
    const auto kept = fs::last_write_time(dir / "variants/v0000/summary.json");
    fs::remove_all(dir / "variants/v0002");
    const auto again = runFlexehd("sweep " + study + " --json");  // progress lines on stderr
    ASSERT_EQ(again.status, 2) << again.err;
    j = nlohmann::json::parse(again.out);
    EXPECT_EQ(j["resumed"], 1);  // v0000
    EXPECT_EQ(j["ran"], 2);      // v0002, and v0001 that failed
    EXPECT_EQ(j["ok"], 2);
    EXPECT_EQ(fs::last_write_time(dir / "variants/v0000/summary.json"), kept);
    EXPECT_THAT(again.err, HasSubstr("v0002"));
    EXPECT_THAT(again.err, Not(HasSubstr("] v0000")));
    s = studyJson(dir);
    EXPECT_TRUE(s["variants"][0]["resumed"].get<bool>());
    EXPECT_EQ(s["variants"][2]["status"], "ok");
    EXPECT_EQ(s["counts"]["pending"], 0);
}

TEST(CliSweep, AVariantOverItsTimeLimitIsStoppedAndRecorded) {
    TempDir t("timeout");
    const std::string study = writeStudy(t.path, "parameters:\n  engine.pin_offset: [0.0]\nrun: {timeout_s: 0.2}\n");
    const auto r = runFlexehd("sweep " + study + " --quiet --json");
    ASSERT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["failed"], 1);
    const auto s = studyJson(t.path / "results");
    EXPECT_EQ(s["variants"][0]["status"], "failed");
    EXPECT_THAT(s["variants"][0]["message"].get<std::string>(), HasSubstr("timed out after 0.2 s (the run)"));
}

TEST(CliSweep, VariantsWithTheSameBodyRecipeShareOneBuild) {
    TempDir t("bodies");
    const std::string study = writeStudy(t.path,
        "design: table\nvariants:\n"
        "  - {piston.clearance: 40e-6, reduce.piston.modes: 6}\n"
        "  - {piston.clearance: 60e-6, reduce.piston.modes: 6}\n"
        "reduce:\n"
        "  piston: {mesh: " + kSource + "/meshes/piston.geo, size: 0.0065, E: 7.5e10, nu: 0.33, rho: 2700,\n"
        "           interface: [\"pin_bore:rbe2@0,0,0\"], static_correction: skirt, axial_order: 2,\n"
        "           circumferential_order: 4}\n");
    const auto r = runFlexehd("sweep " + study + " --quiet --json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["ok"], 2) << readText(t.path / "results/study.csv");
    int bodies = 0;
    for (const auto& e : fs::directory_iterator(t.path / "results/cache")) bodies += e.path().extension() == ".h5";
    EXPECT_EQ(bodies, 1);
    // The first variant built it (its log has the reduction), the second only ran.
    EXPECT_THAT(readText(t.path / "results/variants/v0000/run.log"), HasSubstr("modes"));
    EXPECT_THAT(readText(t.path / "results/variants/v0001/run.log"), Not(HasSubstr("reducing")));
    const auto summary = nlohmann::json::parse(readText(t.path / "results/variants/v0001/summary.json"));
    EXPECT_EQ(summary["bodies"]["piston"], "flexible");
}

namespace {

/// Parent pid and state of process `pid` from /proc (state 0 when it is gone).
std::pair<long, char> processStatus(long pid) {
    std::ifstream f("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!std::getline(f, line)) return {0, 0};
    const auto close = line.rfind(')');  // the command name may hold spaces
    std::istringstream rest(line.substr(close + 2));
    char state = 0;
    long ppid = 0;
    rest >> state >> ppid;
    return {ppid, state};
}

long childOf(long parent) {
    for (const auto& e : fs::directory_iterator("/proc")) {
        const std::string name = e.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        if (processStatus(std::stol(name)).first == parent) return std::stol(name);
    }
    return 0;
}

}  // namespace

// kill -9 of the sweep cannot stop its running variant itself: the variant notices that its
// parent is gone and ends too.
TEST(CliSweep, AVariantEndsWhenTheSweepIsKilled) {
    TempDir t("orphan");
    std::string study = writeStudy(t.path, "parameters:\n  time.periodicity_tolerance: [1.0e-30]\n");
    {  // 200 cycles instead of the set's 1 (a key is in set or in parameters, not both)
        std::ifstream in(study);
        std::string text((std::istreambuf_iterator<char>(in)), {});
        text.replace(text.find("time.max_cycles: 1\n"), 19, "time.max_cycles: 200\n");
        std::ofstream(study) << text;
    }
    FILE* p = popen((std::string(FLEXEHD_BINARY) + " sweep " + study + " --quiet >/dev/null 2>&1 & echo $!").c_str(), "r");
    ASSERT_NE(p, nullptr);
    long sweep = 0;
    ASSERT_EQ(fscanf(p, "%ld", &sweep), 1);
    pclose(p);
    long child = 0;
    for (int i = 0; i < 1000 && !child; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        child = childOf(sweep);
    }
    if (!child) ::kill(sweep, SIGKILL);  // its 200 cycles would outlast the test
    ASSERT_NE(child, 0) << "the sweep started no variant";
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the variant is running
    ::kill(sweep, SIGKILL);
    bool ended = false;
    for (int i = 0; i < 500 && !ended; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        const char state = processStatus(child).second;
        ended = state == 0 || state == 'Z';
    }
    if (!ended) ::kill(child, SIGKILL);
    EXPECT_TRUE(ended) << "variant " << child << " still runs 5 s after its sweep was killed";
}
