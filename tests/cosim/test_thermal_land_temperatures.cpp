// The lands' gas temperatures from the thermal file (run/ThermalLandTemperatures): a ring pack
// with `ring_gas: {model: lands}`, a thermal file and no `land_temperatures` takes for each land
// the mean of the file's piston ring-belt profile (/piston/ring_belt) over the land's z range
// (ring i's groove lower flank down to ring i + 1's groove top); given temperatures win; a file
// written without the profile keeps 450 K and the run says so once, as a warning. The files are
// written with the HDF5 C API (ClearanceTestSupport.hpp), not by flexehd's writer.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <hdf5.h>

#include <csignal>
#include <filesystem>
#include <string>
#include <vector>

#include "ClearanceTestSupport.hpp"
#include "TestFiles.hpp"
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/clearance/ThermalDisplacementFile.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "cosim/run/CaseRun.hpp"
#include "cosim/run/ThermalLandTemperatures.hpp"

using namespace flexehd;
using namespace flexehd::cosim;
using namespace flexehd::cosim::test;
using ::testing::AllOf;
using ::testing::HasSubstr;
using flexehd::test::errorOf;
using flexehd::test::scratchDir;

namespace fs = std::filesystem;

namespace {

// The example's pack (examples/engine86/rings.yaml: the lands span z = 21.3 … 25.3 mm between the
// top and the second ring and 16.3 … 19.8 mm between the second and the oil-control ring) with the
// lands' gas, on a coarse grid.
EngineCase packCase(const std::string& thermalFile) {
    EngineCase c = readCaseFile(std::string(FLEXEHD_SOURCE_DIR) + "/examples/engine86/hd_rings.yaml");
    c.grid.axialNodes = 24;
    c.grid.circumferentialNodes = 72;
    c.ringGas.model = RingGasModel::Lands;
    c.ringGas.ringLift = false;
    c.ringGas.landTemperatures.clear();
    c.thermal.file = thermalFile;
    return c;
}

// thermal.h5 with uniform growth tables for piston and liner (covering the example's skirt and its
// sweep) and, when `z` is not empty, /piston/ring_belt with the given rows.
void writeProfileFile(const fs::path& path, const std::vector<double>& z = {}, const std::vector<double>& t = {}) {
    writeThermal(path, {{"piston", {-0.030, 0.0, 0.020}, uniformTheta(24), [](double, double) { return 20e-6; }},
                        {"liner", linspace(-0.170, 0.005, 8), uniformTheta(24), [](double, double) { return 5e-6; }}});
    if (z.empty()) return;
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    const hid_t g = H5Gcreate2(file, "/piston/ring_belt", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    dataset(g, "z_m", z, {z.size()});
    dataset(g, "temperature_k", t, {t.size()});
    H5Gclose(g);
    H5Fclose(file);
}

}  // namespace

// A profile linear in z, T = 300 K + 4000 K/m z: a land's mean is the value at its mid-height,
// 300 + 4000 · 0.0233 = 393.2 K and 300 + 4000 · 0.01805 = 372.2 K.
TEST(ThermalLandTemperatures, ALinearProfileGivesEachLandItsMidHeightValue) {
    const fs::path dir = scratchDir();
    std::vector<double> z = linspace(0.010, 0.035, 11), t;
    for (double v : z) t.push_back(300.0 + 4000.0 * v);
    writeProfileFile(dir / "thermal.h5", z, t);
    const auto lands = thermalLandTemperatures(packCase((dir / "thermal.h5").string()));
    ASSERT_TRUE(lands);
    ASSERT_EQ(lands->temperatures.size(), 2u);
    EXPECT_NEAR(lands->temperatures[0], 393.2, 1e-9);
    EXPECT_NEAR(lands->temperatures[1], 372.2, 1e-9);
    EXPECT_THAT(lands->message, AllOf(HasSubstr("393.2, 372.2 K"), HasSubstr("thermal.h5")));
}

// A step from 380 K to 480 K between z = 22 and 24 mm: the upper land (21.3 … 25.3 mm) averages
// 380 K over 0.7 mm, the ramp's 430 K over 2 mm and 480 K over 1.3 mm, (266 + 860 + 624) / 4 =
// 437.5 K — not its mid-height value (455 K); the lower land (16.3 … 19.8 mm) lies in the flat 380 K.
TEST(ThermalLandTemperatures, EachLandTakesTheProfilesMeanOverItsHeight) {
    const fs::path dir = scratchDir();
    writeProfileFile(dir / "thermal.h5", {0.010, 0.022, 0.024, 0.035}, {380.0, 380.0, 480.0, 480.0});
    const auto lands = thermalLandTemperatures(packCase((dir / "thermal.h5").string()));
    ASSERT_TRUE(lands);
    ASSERT_EQ(lands->temperatures.size(), 2u);
    EXPECT_NEAR(lands->temperatures[0], 437.5, 1e-9);
    EXPECT_NEAR(lands->temperatures[1], 380.0, 1e-9);
}

// Given land temperatures win; without the lands' gas or without a thermal file nothing is set.
TEST(ThermalLandTemperatures, GivenTemperaturesWin) {
    const fs::path dir = scratchDir();
    writeProfileFile(dir / "thermal.h5", {0.010, 0.035}, {400.0, 500.0});
    EngineCase given = packCase((dir / "thermal.h5").string());
    given.ringGas.landTemperatures = {470.0, 440.0};
    EXPECT_FALSE(thermalLandTemperatures(given));
    EngineCase noGas = packCase((dir / "thermal.h5").string());
    noGas.ringGas.model = RingGasModel::None;
    EXPECT_FALSE(thermalLandTemperatures(noGas));
    EXPECT_FALSE(thermalLandTemperatures(packCase("")));
}

// A land beyond the profile's rows: an error naming the case, the land, its rings and the file.
TEST(ThermalLandTemperatures, ALandOutsideTheProfileIsAnError) {
    const fs::path dir = scratchDir();
    writeProfileFile(dir / "thermal.h5", {0.018, 0.035}, {400.0, 500.0});
    const std::string file = (dir / "thermal.h5").string();
    EXPECT_THAT(errorOf([&] { (void)thermalLandTemperatures(packCase(file)); }),
                AllOf(HasSubstr("hd_rings.yaml: ring_gas: land 2"), HasSubstr("'second' and 'oil_control'"),
                      HasSubstr(file + ":/piston/ring_belt/z_m"), HasSubstr("ring_gas.land_temperatures")));
}

// A profile the reader refuses names the file and the dataset.
TEST(ThermalLandTemperatures, ABadProfileNamesTheDataset) {
    const fs::path dir = scratchDir();
    const std::string file = (dir / "thermal.h5").string();
    writeProfileFile(file, {0.010, 0.030, 0.020}, {400.0, 450.0, 500.0});
    EXPECT_THAT(errorOf([&] { (void)readThermalDisplacementFile(file); }),
                AllOf(HasSubstr(file), HasSubstr("/piston/ring_belt/z_m must be strictly increasing")));
    writeProfileFile(file, {0.010, 0.030}, {400.0, 450.0, 500.0});
    EXPECT_THAT(errorOf([&] { (void)readThermalDisplacementFile(file); }),
                HasSubstr("/piston/ring_belt/temperature_k has 3 values"));
    writeProfileFile(file, {0.010, 0.030}, {400.0, -450.0});
    EXPECT_THAT(errorOf([&] { (void)readThermalDisplacementFile(file); }),
                HasSubstr("/piston/ring_belt/temperature_k must be positive"));
}

namespace {

struct LoggedRun {
    std::vector<std::string> info, warn;
    std::string error;
};

// runCase on `c`, stopped before its first step: what it logged.
LoggedRun startRun(EngineCase c, const fs::path& out) {
    c.output.directory = out.string();
    LoggedRun r;
    RunLog log;
    log.info = [&](const std::string& s) { r.info.push_back(s); };
    log.warn = [&](const std::string& s) { r.warn.push_back(s); };
    log.interrupted = [] { return int(SIGTERM); };
    r.error = errorOf([&] { (void)runCase(c, log); });
    return r;
}

int countWith(const std::vector<std::string>& lines, const std::string& part) {
    int n = 0;
    for (const auto& l : lines) n += l.find(part) != std::string::npos;
    return n;
}

}  // namespace

// The run takes the lands' temperatures from the profile and says which on its log.
TEST(ThermalLandTemperatures, TheRunTakesThemFromTheFile) {
    const fs::path dir = scratchDir();
    std::vector<double> z = linspace(0.010, 0.035, 11), t;
    for (double v : z) t.push_back(300.0 + 4000.0 * v);
    writeProfileFile(dir / "thermal.h5", z, t);
    const LoggedRun r = startRun(packCase((dir / "thermal.h5").string()), dir / "out");
    EXPECT_THAT(r.error, HasSubstr("interrupted by signal"));
    EXPECT_EQ(countWith(r.info, "ring_gas: land temperatures 393.2, 372.2 K"), 1);
    EXPECT_EQ(countWith(r.warn, "ring-belt"), 0);
}

// A thermal file written without the profile (the layout of earlier builds) still reads; the run
// keeps 450 K and warns once, naming the file and the key that sets the temperatures.
TEST(ThermalLandTemperatures, AFileWithoutTheProfileKeeps450KWithOneWarning) {
    const fs::path dir = scratchDir();
    const std::string file = (dir / "thermal.h5").string();
    writeProfileFile(file);
    const ThermalDisplacement read = readThermalDisplacementFile(file);
    EXPECT_TRUE(read.piston && read.liner);
    EXPECT_FALSE(read.pistonRingBelt);
    const auto lands = thermalLandTemperatures(packCase(file));
    ASSERT_TRUE(lands);
    EXPECT_TRUE(lands->temperatures.empty());

    const LoggedRun r = startRun(packCase(file), dir / "out");
    EXPECT_THAT(r.error, HasSubstr("interrupted by signal"));
    ASSERT_EQ(countWith(r.warn, "ring-belt temperature profile"), 1);
    EXPECT_EQ(r.warn.size(), 1u);
    EXPECT_THAT(r.warn.front(), AllOf(HasSubstr(file), HasSubstr("450 K"), HasSubstr("ring_gas.land_temperatures")));
    EXPECT_EQ(countWith(r.info, "land temperatures"), 0);
}
