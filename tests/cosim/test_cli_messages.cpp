// The messages `flexehd` gives on bad input, as a table of probes: the files a probe writes into
// its scratch folder, the command line, the exit code, a fragment the message must hold and one it
// must not (the raw text of a library, binary bytes, numbers printed as 0.000000, nan or inf).
// A new probe is a new row of kProbes.
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "CliRunner.hpp"
#include "MinimalCaseFile.hpp"
#include "../TestScratch.hpp"

namespace {

using flexehd::test::kMinimalCase;
using flexehd::test::kMinimalPressureTable;

struct File {
    std::string name;     ///< in the probe's scratch folder
    std::string content;  ///< bytes as written
};

struct Probe {
    const char* name;          ///< the test's name
    std::vector<File> files;   ///< written before the command runs
    std::string args;          ///< after `flexehd`; {dir} stands for the scratch folder
    int exitCode;
    std::string expected;      ///< a fragment of stderr
    std::string forbidden;     ///< must not be in stderr or stdout
};

std::string minimalCase() { return kMinimalCase; }

// The minimal case with `from` replaced by `to`.
std::string caseWith(const std::string& from, const std::string& to) {
    std::string c = kMinimalCase;
    c.replace(c.find(from), from.size(), to);
    return c;
}

// The minimal case with every "\n" replaced by `eol`.
std::string caseWithLineEnds(const std::string& text, const std::string& eol) {
    std::string out;
    for (char ch : text) out += ch == '\n' ? eol : std::string(1, ch);
    return out;
}

const File kPressure{"p.csv", kMinimalPressureTable};
const File kCase{"case.yaml", minimalCase()};

// The first bytes of a PNG image: what a binary file in place of a text table looks like.
const std::string kPngBytes = std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\x01\0\0\0\x01\0\x08\x06\0\0\0", 29) +
                              "\x5c\x72\xa8\x66\n\0\0\0\x04sBIT" + std::string(40, '\x01');

const std::string kSource = FLEXEHD_SOURCE_DIR;
const std::string kBeamMesh = " --mesh " + kSource + "/tests/fem/data/beam.geo --E 2.1e11 --nu 0.3 --rho 7850";
const std::string kStudy = "base_case: case.yaml\nparameters:\n  engine.speed_rpm: [1000, 2000]\n";

const std::vector<Probe> kProbes = {
    // a. an option given twice
    {"OptionGivenTwice", {kCase, kPressure}, "run {dir}/case.yaml --out {dir}/a --out {dir}/b", 1,
     "option --out given twice", "At Most 1"},
    // b. an output folder that cannot be made
    {"OutputFolderUnderAFile", {kCase, kPressure, {"afile", "x"}}, "run {dir}/case.yaml --out {dir}/afile/x", 1,
     "cannot create the output folder", "filesystem error"},
    {"OutputFolderUnderAFileSaysWhy", {kCase, kPressure, {"afile", "x"}}, "run {dir}/case.yaml --out {dir}/afile/x",
     1, "a parent is a file", "cannot create directories"},
    {"OutputFolderUnderProc", {kCase, kPressure}, "run {dir}/case.yaml --out /proc/flexehd_probe/x", 1,
     "cannot create the output folder /proc/flexehd_probe/x", "filesystem error"},
    // c. commands
    {"UnknownCommand", {}, "frobnicate", 1,
     "unknown command 'frobnicate'; commands are: modes, reduce, inspect, export-modes, bearing, run, thermal, acoustics, sweep",
     "A subcommand is required"},
    {"NoCommand", {}, "", 1, "no command given; commands are: modes,", "A subcommand is required"},
    // d. the case file's YAML
    {"CaseFileWithCrOnlyLineEnds",
     {{"case.yaml", caseWithLineEnds(caseWith("skirt_top", "skirt_topp"), "\r")}, kPressure},
     "run {dir}/case.yaml", 1, "piston.skirt_topp (line 11): unknown key", "YAML syntax error"},
    {"CaseFileWithNulByte", {{"case.yaml", caseWith("  stroke", std::string("  str\0oke", 9))}, kPressure},
     "run {dir}/case.yaml", 1, "the case file contains a NUL byte at line 3 (a binary file?)", "escape character"},
    {"CaseFileWithTwoDocuments", {{"case.yaml", minimalCase() + "---\nname: second\n"}, kPressure},
     "run {dir}/case.yaml", 1, "the case file holds 2 YAML documents; flexehd reads one", "cycle 1"},
    // e. a binary cylinder pressure file
    {"BinaryPressureFile", {{"case.yaml", caseWith("p.csv", "p.png")}, {"p.png", kPngBytes}}, "run {dir}/case.yaml",
     1, "is not a text table: line 2 holds the byte 0x1A", "IHDR"},
    {"BinaryPressureFileNoRawBytes", {{"case.yaml", caseWith("p.csv", "p.png")}, {"p.png", kPngBytes}},
     "run {dir}/case.yaml", 1, "p.png", "\x89PNG"},
    // f. study files
    {"StudyBaseCaseIsTheStudyItself",
     {kCase, kPressure, {"study.yaml", "base_case: study.yaml\nparameters:\n  engine.speed_rpm: [1000, 2000]\n"}},
     "sweep --dry-run {dir}/study.yaml", 1, "base_case points at the study file itself", "unknown key"},
    {"StudyKeyInSetAndParameters",
     {kCase, kPressure,
      {"study.yaml", "base_case: case.yaml\nset:\n  engine.speed_rpm: 1500\nparameters:\n  engine.speed_rpm: [1000, "
                     "2000]\n"}},
     "sweep --dry-run {dir}/study.yaml", 1, "engine.speed_rpm is given both in set and in parameters", "v0001"},
    // g. the bearing's numbers
    {"BearingNonFiniteResult", {}, "bearing --eccentricity 0.5 --length 1e-300", 1, "not finite", "nan"},
    {"BearingNonFiniteResultNoInf", {}, "bearing --eccentricity 0.5 --length 1e-300", 1, "--length", "inf  -"},
    {"BearingUnconvergedNumbers", {}, "bearing --eccentricity 0.5 --speed 1e300", 1, "tolerance 1e-08",
     "0.000000"},
    // h. hints that point the right way
    {"BearingToleranceBelowDoublePrecision", {}, "bearing --eccentricity 0.5 --tolerance 1e-30", 1,
     "--tolerance 1e-30 is below what double precision can reach", "0.000000"},
    // physical inputs beyond their plausible range (docs/case-file.md): refused before the run
    {"SpeedBeyondAnyEngine", {{"case.yaml", caseWith("speed_rpm: 1000", "speed_rpm: 1.0e9")}, kPressure},
     "run {dir}/case.yaml", 1, "engine.speed_rpm", "cycle 1"},
    {"SpeedBeyondAnyEngineSaysTheRange", {{"case.yaml", caseWith("speed_rpm: 1000", "speed_rpm: 1.0e9")}, kPressure},
     "run {dir}/case.yaml", 1, "outside the range of piston engines, 10 to 30 000 rev/min", "status: ok"},
    {"PressureTableInThousandsOfPa", {kCase, {"p.csv", "crank_angle_deg,pressure_pa\n0,1e8\n360,4e9\n720,1e8\n"}},
     "run {dir}/case.yaml", 1, "p.csv:2: 1e+08 Pa is above 50 MPa", "cycle 1"},
    {"PressureTableWithOneAbsurdRow",
     {kCase, {"p.csv", "crank_angle_deg,pressure_pa\n0,1e5\n180,1e300\n360,4e6\n720,1e5\n"}}, "run {dir}/case.yaml",
     1, "p.csv:3: 1e+300 Pa is above 50 MPa", "cycle 1"},
    {"ReplenishmentDeeperThanTheSkirtReaches",
     {{"case.yaml", minimalCase() + "lubricant:\n  cavitation: mass_conserving\n  supply:\n    model: liner_layer\n"
                                    "    thickness: 3.0e-6\n    replenish_below_depth: 100\n"},
      kPressure},
     "run {dir}/case.yaml", 1, "100 m is deeper than the skirt's lower edge ever reaches (0.1445 m below the deck",
     "cycle 1"},
    {"ClearanceBelowTheRoughness",
     {{"case.yaml", caseWith("  skirt_bottom: -0.025\n", "  skirt_bottom: -0.025\n  clearance: 1.0e-9\n")},
      kPressure},
     "run {dir}/case.yaml", 1, "piston.clearance", "cycle 1"},
    {"ClearanceBelowTheRoughnessSaysWhy",
     {{"case.yaml", caseWith("  skirt_bottom: -0.025\n", "  skirt_bottom: -0.025\n  clearance: 1.0e-9\n")},
      kPressure},
     "run {dir}/case.yaml", 1, "is below 1 um, less than the surfaces' roughness", "composite_modulus"},    // the study file's YAML, read as the case file's is
    {"StudyFileWithCrOnlyLineEnds",
     {kCase, kPressure, {"study.yaml", caseWithLineEnds(kStudy + "samplez: 3\n", "\r")}},
     "sweep --dry-run {dir}/study.yaml", 1, "samplez (line 4): unknown key", "YAML syntax error"},
    {"StudyFileWithNulByte",
     {kCase, kPressure, {"study.yaml", "base_case: case.yaml\nparameters:\n  engine.sp" + std::string(1, '\0') +
                                           "eed_rpm: [1000, 2000]\n"}},
     "sweep --dry-run {dir}/study.yaml", 1, "the study file contains a NUL byte at line 3 (a binary file?)",
     "escape character"},
    {"StudyFileWithTwoDocuments", {kCase, kPressure, {"study.yaml", kStudy + "---\nname: second\n"}},
     "sweep --dry-run {dir}/study.yaml", 1, "the study file holds 2 YAML documents; flexehd reads one", "v0001"},
    // output paths under a file, refused before the work with the reason in words
    {"ThermalOutputFolderUnderAFile", {{"afile", "x"}},
     "thermal " + kSource + "/examples/engine86/thermal.yaml --out {dir}/afile/x", 1,
     "cannot create the output folder", "filesystem error"},
    {"ThermalOutputFolderUnderAFileSaysWhy", {{"afile", "x"}},
     "thermal " + kSource + "/examples/engine86/thermal.yaml --out {dir}/afile/x", 1, "a parent is a file",
     "thermoelastic solve"},
    {"ReduceOutputFileUnderAFile", {{"afile", "x"}},
     "reduce" + kBeamMesh + " --interface clamped:rbe2 --modes 2 --out {dir}/afile/x.h5", 1,
     "cannot write the output file", "Not a directory"},
    {"ReduceOutputFileUnderAFileSaysWhy", {{"afile", "x"}},
     "reduce" + kBeamMesh + " --interface clamped:rbe2 --modes 2 --out {dir}/afile/x.h5", 1, "a parent is a file",
     "reading mesh"},
    {"ReduceOutputFileIsAFolder", {}, "reduce" + kBeamMesh + " --interface clamped:rbe2 --modes 2 --out {dir}", 1,
     "it is a folder, not a file", "Is a directory"},
    {"ModesOutputFolderUnderAFile", {{"afile", "x"}}, "modes" + kBeamMesh + " --count 2 --out {dir}/afile/m", 1,
     "cannot create the output folder", "filesystem error"},
    // inputs refused today, kept refused
    {"CaseNameInLatin1", {{"case.yaml", minimalCase() + "name: M\xfcller\n"}, kPressure}, "run {dir}/case.yaml", 1,
     "name (line 14): expected UTF-8 text", "M\xfc"},
    {"BearingZeroLength", {}, "bearing --eccentricity 0.5 --length 0", 1, "--length must be positive", "nan"},
    {"AcousticsWithoutARecord", {{"summary.json", "{}"}}, "acoustics {dir}", 1,
     "/acoustics.h5: no such file", "HDF5-DIAG"},
    {"AcousticsOfAFileThatIsNoRecord", {{"acoustics.h5", "not hdf5"}}, "acoustics {dir}", 1,
     "cannot open it as an HDF5 file", "HDF5-DIAG"},
    {"StudyRangeOfABillionValues",
     {kCase, kPressure,
      {"study.yaml", "base_case: case.yaml\nparameters:\n  engine.speed_rpm: {start: 1000, stop: 7000, count: "
                     "1000000000}\n"}},
     "sweep --dry-run {dir}/study.yaml", 1, "a study runs at most 1000000 variants", "v0001"},
    {"MaxStepOfAMicroDegree",
     {{"case.yaml", minimalCase() + "time:\n  max_step_deg: 1.0e-6\n  min_step_deg: 1.0e-6\n"}, kPressure},
     "run {dir}/case.yaml", 1, "time.max_step_deg", "cycle 1"},
    {"ReduceMeshBeyondTheMemory", {},
     "reduce --mesh " + kSource + "/meshes/piston.geo --size 1e-6 --E 7.5e10 --nu 0.33 --rho 2700 --interface "
     "pin_bore:rbe2@0,0,0 --modes 4 --out {dir}/x.h5", 1, "would make about", "bad_alloc"},
};

// gtest prints a failing parameter by this instead of its bytes.
void PrintTo(const Probe& p, std::ostream* os) { *os << "flexehd " << p.args; }

class CliMessages : public testing::TestWithParam<Probe> {};

TEST_P(CliMessages, SaysWhatWasExpected) {
    const Probe& p = GetParam();
    const std::filesystem::path dir = flexehd::test::scratchDir();
    for (const File& f : p.files) std::ofstream(dir / f.name, std::ios::binary) << f.content;
    std::string args = p.args;
    for (std::size_t at; (at = args.find("{dir}")) != std::string::npos;) args.replace(at, 5, dir.string());
    const flexehd::test::CommandResult r = flexehd::test::runFlexehd(args);
    EXPECT_EQ(r.status, p.exitCode) << r.err;
    EXPECT_NE(r.err.find(p.expected), std::string::npos) << "expected '" << p.expected << "' in: " << r.err;
    EXPECT_EQ(r.err.find(p.forbidden), std::string::npos) << "'" << p.forbidden << "' in: " << r.err;
    EXPECT_EQ(r.out.find(p.forbidden), std::string::npos) << "'" << p.forbidden << "' in stdout: " << r.out;
}

INSTANTIATE_TEST_SUITE_P(Probes, CliMessages, testing::ValuesIn(kProbes),
                         [](const testing::TestParamInfo<Probe>& i) { return std::string(i.param.name); });

}  // namespace
