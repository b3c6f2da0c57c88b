// Thermal analysis at the co-simulation level: the surface table of a freely expanding
// sleeve (mean over θ of u_r = α ΔT R), the liner temperature interpolation (exact for data
// linear in z and r), and `flexehd thermal` end to end on the coarse shipped meshes: a
// readable thermal.h5 with the agreed layout, VTU files, clear errors for bad input.
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "CliRunner.hpp"
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/thermal/CylindricalSurfaceSampler.hpp"
#include "cosim/thermal/LinerTemperature.hpp"
#include "cosim/thermal/ThermalFileWriter.hpp"
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "cosim/clearance/ThermalDisplacementFile.hpp"
#include "fem/MeshReader.hpp"
#include "fem/ThermalDeformation.hpp"

namespace fs = std::filesystem;
using namespace flexehd;
using testing::HasSubstr;

namespace {

const std::string kSource = FLEXEHD_SOURCE_DIR;

fs::path scratch() {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    auto dir = fs::temp_directory_path() / ("flexehd_thermal_" + std::string(info->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

}  // namespace

// Free expansion of a sleeve (outer radius 43 mm, inner 40 mm) under uniform ΔT: the mean
// over a uniform θ table of u_r is α ΔT R on either surface (a rigid translation left by the
// support averages out over θ), and the points of a full cylinder are all on the surface.
TEST(SurfaceTable, FreeExpansionOfASleeveGivesAlphaDeltaTR) {
    const fem::Mesh m = fem::readMesh(kSource + "/tests/cosim/data/sleeve.geo", {2, 0.008});
    const double alpha = 1.1e-5, dT = 100.0, Tref = 293.15;
    const Eigen::VectorXd T = Eigen::VectorXd::Constant(m.numNodes(), Tref + dT);
    const auto d = fem::solveThermalDeformation(m, {1.1e11, 0.26, 7200.0}, alpha, T, Tref, {{}, "inner"});
    for (const auto& [group, R] : {std::pair<std::string, double>{"outer", 0.043}, {"inner", 0.040}}) {
        const cosim::SurfaceTable t = cosim::CylindricalSurfaceSampler(m, {group}).sample(d.displacement, 9, 48);
        ASSERT_EQ(t.radial.rows(), 9);
        ASSERT_EQ(t.radial.cols(), 48);
        EXPECT_NEAR(t.axial.front(), -0.030, 1e-9);
        EXPECT_NEAR(t.axial.back(), 0.020, 1e-9);
        EXPECT_NEAR(t.theta[1], 2 * std::numbers::pi / 48, 1e-15);
        EXPECT_EQ(t.onSurface.cast<int>().sum(), 9 * 48);
        for (Eigen::Index i = 0; i < t.radial.rows(); ++i)
            EXPECT_NEAR(t.radial.row(i).mean(), alpha * dT * R, 1e-3 * alpha * dT * R) << group << " row " << i;
    }
}

// A temperature linear in z, T = 400 K + 2000 K/m z, sampled on the sleeve's outer and inner
// cylinders: the profile over z (circumferential mean per row) is that line at every row — the
// surface's shape functions reproduce a linear field exactly — and every point is on the surface.
TEST(SurfaceTable, TemperatureProfileOfAFieldLinearInZIsThatLine) {
    fem::MeshOptions order2;
    order2.order = 2;
    order2.size = 0.008;
    const fem::Mesh m = fem::readMesh(kSource + "/tests/cosim/data/sleeve.geo", order2);
    Eigen::VectorXd T(m.numNodes());
    for (fem::Index n = 0; n < m.numNodes(); ++n) T(n) = 400.0 + 2000.0 * m.nodes(2, n);
    for (const std::string group : {"outer", "inner"}) {
        const cosim::ScalarSurfaceTable t = cosim::CylindricalSurfaceSampler(m, {group}).sampleScalar(T, 11, 24);
        EXPECT_EQ(t.onSurface.cast<int>().sum(), 11 * 24) << group;
        const cosim::AxialProfile p = cosim::axialProfile(t);
        ASSERT_EQ(p.axial.size(), 11u);
        EXPECT_NEAR(p.axial.front(), -0.030, 1e-9);
        EXPECT_NEAR(p.axial.back(), 0.020, 1e-9);
        for (std::size_t i = 0; i < p.axial.size(); ++i)
            EXPECT_NEAR(p.values[i], 400.0 + 2000.0 * p.axial[i], 1e-9) << group << " row " << i;
    }
}

// The mean of a piecewise-linear profile over a range is its integral over the range divided by
// the length: z = 0, 1, 2 m with T = 0, 10, 10 K averages (3.75 + 5) / 1 = 8.75 K over 0.5 … 1.5 m,
// and a linear profile averages to its value at the range's midpoint.
TEST(SurfaceTemperatureProfile, MeanIsTheIntegralOverTheRange) {
    const cosim::SurfaceTemperatureProfile kink{"test", {0.0, 1.0, 2.0}, {0.0, 10.0, 10.0}};
    EXPECT_NEAR(kink.mean(0.5, 1.5), 8.75, 1e-12);
    EXPECT_NEAR(kink.mean(1.2, 1.9), 10.0, 1e-12);
    const cosim::SurfaceTemperatureProfile line{"test", {0.010, 0.015, 0.035}, {330.0, 350.0, 430.0}};  // 290 + 4000 z
    EXPECT_NEAR(line.mean(0.012, 0.030), 290.0 + 4000.0 * 0.021, 1e-9);
    std::string error;
    try {
        (void)line.mean(0.005, 0.020);
    } catch (const std::out_of_range& e) {
        error = e.what();
    }
    EXPECT_THAT(error, HasSubstr("test/z_m covers 0.01 … 0.035 m"));
}

// thermal.h5's ring-belt profile as the writer puts it and the run's reader reads it back; a file
// without it (the liner alone here) reads with the profile absent.
TEST(ThermalFile, RingBeltProfileIsWrittenAndReadBack) {
    const fs::path dir = scratch();
    cosim::SurfaceTable table;
    table.axial = {0.0, 0.01};
    table.theta = {0.0, 2 * std::numbers::pi / 3, 4 * std::numbers::pi / 3};
    table.radial.setConstant(2, 3, 1e-5);
    table.onSurface.setOnes(2, 3);
    cosim::ThermalBodyTable piston, liner;
    piston.table = liner.table = table;
    piston.ringBelt = cosim::AxialProfile{{0.012, 0.020, 0.033}, {410.0, 430.0, 462.5}};
    piston.ringBeltSurface = "ring_lands";
    const std::string h5 = (dir / "thermal.h5").string();
    cosim::writeThermalFile(h5, piston, liner);
    const cosim::ThermalDisplacement t = cosim::readThermalDisplacementFile(h5);
    ASSERT_TRUE(t.pistonRingBelt);
    EXPECT_EQ(t.pistonRingBelt->z, (std::vector<double>{0.012, 0.020, 0.033}));
    EXPECT_EQ(t.pistonRingBelt->temperature, (std::vector<double>{410.0, 430.0, 462.5}));
    EXPECT_EQ(t.pistonRingBelt->where, h5 + ":/piston/ring_belt");

    cosim::writeThermalFile(h5, std::nullopt, liner);
    EXPECT_FALSE(cosim::readThermalDisplacementFile(h5).pistonRingBelt);
    piston.ringBelt->values[1] = -1.0;
    EXPECT_THROW(cosim::writeThermalFile(h5, piston, std::nullopt), std::runtime_error);
}

// Thermocouples at two radii, temperatures linear in z: T(r, z) = a + b z + c r reproduced
// at every node (linear in z between stations, linear in r through the two depths).
TEST(LinerTemperature, ReproducesFieldsLinearInZAndR) {
    const fem::Mesh m = fem::readMesh(kSource + "/tests/cosim/data/sleeve.geo", {1, 0.008});
    auto exact = [](double r, double z) { return 400.0 + 800.0 * z - 5000.0 * (r - 0.041); };
    const std::vector<double> radii{0.041, 0.042};
    std::vector<cosim::ThermocoupleStation> st;
    for (double z : {-0.030, -0.010, 0.020}) st.push_back({z, {exact(0.041, z), exact(0.042, z)}});
    const Eigen::VectorXd T = cosim::linerTemperature(m, radii, st);
    double err = 0.0;
    for (fem::Index n = 0; n < m.numNodes(); ++n)
        err = std::max(err, std::abs(T(n) - exact(m.nodes.col(n).head<2>().norm(), m.nodes(2, n))));
    EXPECT_LT(err, 1e-9);
    // Beyond the last station the temperature stays at the last station's value.
    EXPECT_NEAR(cosim::thermocoupleTemperature(radii, st, 0.041, 0.05), exact(0.041, 0.020), 1e-12);
}

// ---- flexehd thermal ------------------------------------------------------------------------

namespace {

/// A thermal case on the coarse test meshes (docs/meshes.md), grid 16 × 24.
std::string coarseCase(const std::string& extraPiston = "", const std::string& templugs = "") {
    return "name: coarse thermal test\n"
           "reference_temperature: 293.15\n"
           "grid: {axial_nodes: 16, circumferential_nodes: 24}\n"
           "piston:\n"
           "  mesh: " + kSource + "/meshes/piston.geo\n"
           "  mesh_size: 0.0065\n"
           "  material: {youngs_modulus: 7.5e10, poisson_ratio: 0.33, conductivity: 150.0, expansion: 2.1e-5}\n"
           "  convection:\n"
           "    crown: {h: 300.0, fluid_temperature: 900.0}\n"
           "    ring_lands: {h: 150.0, fluid_temperature: 420.0}\n"
           "    ring_grooves: {h: 1500.0, fluid_temperature: 410.0}\n"
           "    skirt: {h: 600.0, fluid_temperature: 390.0}\n"
           "    skirt_taper: {h: 600.0, fluid_temperature: 390.0}\n"
           "    pin_bore: {h: 800.0, fluid_temperature: 380.0}\n"
           "    underside: {h: 500.0, fluid_temperature: 370.0}\n" +
           extraPiston +
           "  calibration:\n"
           "    fit_h: [crown, underside]\n"
           "    templugs:\n" +
           (templugs.empty() ? "      - {name: crown_centre, position: [0.0, 0.0, 0.031], temperature: 520.0}\n"
                               "      - {name: top_land, position: [0.041, 0.0, 0.030], temperature: 490.0}\n"
                               "      - {name: pin_boss, position: [0.0, 0.030, 0.012], temperature: 445.0}\n"
                             : templugs) +
           "liner:\n"
           "  mesh: " + kSource + "/meshes/liner.geo\n"
           "  mesh_size: 0.012\n"
           "  material: {youngs_modulus: 1.1e11, poisson_ratio: 0.26, expansion: 1.1e-5}\n"
           "  thermocouples:\n"
           "    radii: [0.0445, 0.0480]\n"
           "    stations:\n"
           "      - [-0.150, 370.0, 365.0]\n"
           "      - [-0.010, 420.0, 405.0]\n";
}

std::string writeCase(const fs::path& dir, const std::string& text) {
    const auto p = dir / "thermal.yaml";
    std::ofstream(p) << text;
    return p.string();
}

std::string stringAttribute(hid_t obj, const char* name) {
    const hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
    const hid_t t = H5Aget_type(a);
    std::string v;
    if (H5Tis_variable_str(t) > 0) {
        char* p = nullptr;
        const hid_t mem = H5Tcopy(H5T_C_S1);
        H5Tset_size(mem, H5T_VARIABLE);
        H5Tset_cset(mem, H5Tget_cset(t));
        H5Aread(a, mem, &p);
        v = p ? p : "";
        H5free_memory(p);
        H5Tclose(mem);
    }
    H5Tclose(t);
    H5Aclose(a);
    return v;
}

std::vector<hsize_t> dims(hid_t file, const std::string& name) {
    const hid_t d = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    if (d < 0) return {};
    const hid_t s = H5Dget_space(d);
    std::vector<hsize_t> out(std::size_t(H5Sget_simple_extent_ndims(s)));
    H5Sget_simple_extent_dims(s, out.data(), nullptr);
    H5Sclose(s);
    H5Dclose(d);
    return out;
}

}  // namespace

TEST(ThermalCli, WritesThermalFileWithAgreedLayoutAndVtu) {
    const fs::path dir = scratch();
    const std::string casePath = writeCase(dir, coarseCase());
    const auto r = test::runFlexehd("thermal " + casePath + " --out " + (dir / "out").string() + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto doc = nlohmann::json::parse(r.out);
    for (const char* f : {"thermal.h5", "piston.vtu", "liner.vtu", "summary.json"})
        EXPECT_TRUE(fs::is_regular_file(dir / "out" / f)) << f;
    EXPECT_GT(double(doc["piston"]["temperature"]["max_k"]), double(doc["piston"]["temperature"]["min_k"]));
    EXPECT_EQ(doc["piston"]["calibration"]["templugs"].size(), 3u);
    EXPECT_TRUE(bool(doc["piston"]["calibration"]["matched"])) << doc["piston"]["calibration"]["message"];
    EXPECT_LT(double(doc["piston"]["calibration"]["rms_residual_k"]), 5.0);
    EXPECT_GT(double(doc["liner"]["temperature"]["max_k"]), 400.0);

    // The agreed layout, read with the raw HDF5 API.
    const std::string h5 = (dir / "out" / "thermal.h5").string();
    const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    EXPECT_EQ(stringAttribute(file, "format"), "flexehd-thermal");
    {
        int version = 0;
        const hid_t a = H5Aopen(file, "format_version", H5P_DEFAULT);
        H5Aread(a, H5T_NATIVE_INT, &version);
        H5Aclose(a);
        EXPECT_EQ(version, 1);
    }
    for (const std::string g : {"/piston", "/liner"}) {
        const hid_t grp = H5Gopen2(file, g.c_str(), H5P_DEFAULT);
        ASSERT_GE(grp, 0) << g;
        EXPECT_EQ(stringAttribute(grp, "units"), "m");
        H5Gclose(grp);
        for (const auto& [name, unit] : {std::pair{"axial", "m"}, {"theta", "rad"}, {"radial_displacement", "m"}, {"on_surface", "1"}}) {
            const hid_t d = H5Dopen2(file, (g + "/" + name).c_str(), H5P_DEFAULT);
            ASSERT_GE(d, 0) << g << "/" << name;
            EXPECT_EQ(stringAttribute(d, "units"), unit) << g << "/" << name;
            H5Dclose(d);
        }
        EXPECT_EQ(dims(file, g + "/axial"), std::vector<hsize_t>({16}));
        EXPECT_EQ(dims(file, g + "/theta"), std::vector<hsize_t>({24}));
        EXPECT_EQ(dims(file, g + "/radial_displacement"), std::vector<hsize_t>({16, 24}));
    }
    // The ring belt's outer-surface temperature over z, on the piston only: piston.geo's ring_lands
    // span z = 12.3 mm (the band below the oil groove) … 33.0 mm (the crown's edge), 20.7 mm in rows
    // at most 0.1 mm apart (≥ 208).
    const std::vector<hsize_t> rows = dims(file, "/piston/ring_belt/z_m");
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_GE(rows[0], 208u);
    EXPECT_EQ(dims(file, "/piston/ring_belt/temperature_k"), rows);
    for (const auto& [name, unit] : {std::pair{"z_m", "m"}, {"temperature_k", "K"}}) {
        const hid_t d = H5Dopen2(file, ("/piston/ring_belt/" + std::string(name)).c_str(), H5P_DEFAULT);
        ASSERT_GE(d, 0) << name;
        EXPECT_EQ(stringAttribute(d, "units"), unit) << name;
        H5Dclose(d);
    }
    EXPECT_EQ(H5Lexists(file, "/liner/ring_belt", H5P_DEFAULT), 0);
    H5Fclose(file);

    // And through the reader `flexehd run` uses.
    const cosim::ThermalDisplacement t = cosim::readThermalDisplacementFile(h5);
    ASSERT_TRUE(t.piston && t.liner);
    EXPECT_NEAR(t.piston->axial.front(), -0.025, 1e-6);   // skirt bottom, piston frame
    EXPECT_NEAR(t.piston->axial.back(), 0.0123, 1e-6);    // top of the skirt taper
    EXPECT_NEAR(t.liner->axial.front(), -0.160, 1e-6);    // liner frame
    EXPECT_NEAR(t.liner->axial.back(), 0.0, 1e-6);
    ASSERT_TRUE(t.pistonRingBelt);
    EXPECT_NEAR(t.pistonRingBelt->z.front(), 0.0123, 1e-6);
    EXPECT_NEAR(t.pistonRingBelt->z.back(), 0.0330, 1e-6);
    for (double T : t.pistonRingBelt->temperature) {
        EXPECT_GE(T, double(doc["piston"]["temperature"]["min_k"]));
        EXPECT_LE(T, double(doc["piston"]["temperature"]["max_k"]));
    }
    EXPECT_EQ(doc["piston"]["ring_belt"]["temperature_k"].size(), t.pistonRingBelt->temperature.size());
    // Plausibility: hot aluminium skirt grows outward by α (T − T_ref) R within the range of its
    // temperatures; the bore grows outward.
    const double R = 0.04295, a = 2.1e-5, Tref = 293.15;
    const double uMin = a * (double(doc["piston"]["temperature"]["min_k"]) - Tref) * R;
    const double uMax = a * (double(doc["piston"]["temperature"]["max_k"]) - Tref) * R;
    const double uSkirt = t.piston->at(0.0, 0.0);
    EXPECT_GT(uSkirt, 0.5 * uMin);
    EXPECT_LT(uSkirt, 1.5 * uMax);
    EXPECT_GT(t.liner->at(-0.08, 1.0), 0.0);
}

// Every convection boundary at the same fluid temperature, 400 K: the steady piston is at 400 K
// throughout (no heat flows), so the ring belt's profile is 400 K at every z. A ring_belt group
// that the mesh lacks is an error naming the key.
TEST(ThermalCli, OneFluidTemperatureEverywhereGivesAUniformRingBeltProfile) {
    const fs::path dir = scratch();
    const std::string text = "grid: {axial_nodes: 16, circumferential_nodes: 24}\n"
                             "piston:\n"
                             "  mesh: " + kSource + "/meshes/piston.geo\n"
                             "  mesh_size: 0.0065\n"
                             "  material: {youngs_modulus: 7.5e10, poisson_ratio: 0.33, conductivity: 150.0, "
                             "expansion: 2.1e-5}\n"
                             "  ring_belt: [ring_lands]\n"
                             "  convection:\n"
                             "    crown: {h: 300.0, fluid_temperature: 400.0}\n"
                             "    ring_lands: {h: 150.0, fluid_temperature: 400.0}\n"
                             "    skirt: {h: 600.0, fluid_temperature: 400.0}\n"
                             "    underside: {h: 500.0, fluid_temperature: 400.0}\n";
    const auto r = test::runFlexehd("thermal " + writeCase(dir, text) + " --out " + (dir / "out").string());
    ASSERT_EQ(r.status, 0) << r.err;
    const cosim::ThermalDisplacement t = cosim::readThermalDisplacementFile((dir / "out" / "thermal.h5").string());
    ASSERT_TRUE(t.pistonRingBelt);
    EXPECT_FALSE(t.liner);
    for (double T : t.pistonRingBelt->temperature) EXPECT_NEAR(T, 400.0, 1e-6);

    std::string bad = text;
    bad.replace(bad.find("ring_belt: [ring_lands]"), 23, "ring_belt: [ring_land]");
    const auto e = test::runFlexehd("thermal " + writeCase(dir, bad) + " --out " + (dir / "out2").string());
    EXPECT_EQ(e.status, 1);
    EXPECT_THAT(e.err, HasSubstr("piston.ring_belt"));
    EXPECT_THAT(e.err, HasSubstr("ring_land"));
}

TEST(ThermalCli, UnknownKeyNamesTheKey) {
    const fs::path dir = scratch();
    std::string text = coarseCase("  suport: pin_bore\n");
    const auto r = test::runFlexehd("thermal " + writeCase(dir, text) + " --out " + (dir / "out").string());
    EXPECT_EQ(r.status, 1);
    EXPECT_THAT(r.err, HasSubstr("piston.suport"));
    EXPECT_THAT(r.err, HasSubstr("unknown key (did you mean 'support'?)"));
}

TEST(ThermalCli, MissingMeshFileIsNamed) {
    const fs::path dir = scratch();
    std::string text = coarseCase();
    text.replace(text.find("meshes/liner.geo"), 16, "meshes/linr.geo");
    const auto r = test::runFlexehd("thermal " + writeCase(dir, text) + " --out " + (dir / "out").string());
    EXPECT_EQ(r.status, 1);
    EXPECT_THAT(r.err, HasSubstr("liner.mesh"));
    EXPECT_THAT(r.err, HasSubstr("file not found"));
    EXPECT_THAT(test::runFlexehd("thermal " + (dir / "nothing.yaml").string()).err, HasSubstr("not found"));
}

TEST(ThermalCli, OutOfRangeValueAndTemplugOutsideThePiston) {
    const fs::path dir = scratch();
    std::string text = coarseCase();
    text.replace(text.find("expansion: 2.1e-5"), 17, "expansion: -2.1e-5");
    auto r = test::runFlexehd("thermal " + writeCase(dir, text));
    EXPECT_EQ(r.status, 1);
    EXPECT_THAT(r.err, HasSubstr("piston.material.expansion"));

    r = test::runFlexehd("thermal " + writeCase(dir, coarseCase("", "      - {name: crown_centre, position: [0.0, 0.0, 0.031], temperature: 520.0}\n"
                                                                      "      - {name: in_the_air, position: [0.0, 0.0, 0.040], temperature: 500.0}\n")) +
                         " --out " + (dir / "out").string());
    EXPECT_EQ(r.status, 1);
    EXPECT_THAT(r.err, HasSubstr("piston.calibration"));
    EXPECT_THAT(r.err, HasSubstr("'in_the_air'"));
    EXPECT_THAT(r.err, HasSubstr("outside the mesh"));
}

// The shipped thermal example (examples/engine86/thermal.yaml on the coarse test meshes) with the
// cold geometry of examples/engine86/thermal_hd.yaml: the hot running clearance — the film with
// the piston centred — is positive and in the band docs/thermal.md §7 gives for the example
// (10–40 µm at the largest skirt diameter, TDC to BDC), and the thermal closure of the mean film
// lies within the free-expansion bounds α_p ΔT_skirt R − α_l ΔT_bore R_bore built from the
// example's own measured temperatures (skirt templugs 377–408 K, bore-side thermocouples
// 370–418 K): an FE field with a wrong sign, factor or reference temperature falls outside.
TEST(ThermalExample, HotRunningClearanceIsPlausible) {
    const fs::path dir = scratch();
    std::ifstream in(kSource + "/examples/engine86/thermal.yaml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto replace = [&](const std::string& from, const std::string& to) {
        const auto at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    };
    replace("../../meshes/piston.geo", kSource + "/meshes/piston.geo");
    replace("../../meshes/liner.geo", kSource + "/meshes/liner.geo");
    replace("mesh_size: 0.004 ", "mesh_size: 0.0065");  // the coarse test meshes
    replace("mesh_size: 0.005", "mesh_size: 0.012");
    const auto r = test::runFlexehd("thermal " + writeCase(dir, text) + " --out " + (dir / "out").string() + " --json");
    ASSERT_EQ(r.status, 0) << r.err;

    // The example's thermal file (out/engine86/thermal/) is a build product: not checked here.
    cosim::EngineCase hot = cosim::readCaseFile(kSource + "/examples/engine86/thermal_hd.yaml",
                                                cosim::CaseFileOptions{.checkBodyFiles = false});
    hot.thermal.file = (dir / "out" / "thermal.h5").string();
    cosim::EngineCase cold = hot;
    cold.thermal.file.clear();
    const cosim::PistonSimulation hotSim(hot), coldSim(cold);

    const double R = 0.5 * hot.engine.bore, Tref = 293.15, ap = 20.0e-6, al = 11.0e-6;  // thermal.yaml
    const double closureMin = (ap * (377.0 - Tref) - al * (418.0 - Tref)) * R;
    const double closureMax = (ap * (408.0 - Tref) - al * (370.0 - Tref)) * R;
    for (const double deg : {0.0, 90.0, 180.0}) {
        const cosim::ClearanceRange h = hotSim.contact<cosim::SkirtContact>().centredClearance(hotSim.linerOffset(deg)),
                                    c = coldSim.contact<cosim::SkirtContact>().centredClearance(coldSim.linerOffset(deg));
        EXPECT_GE(h.min, 10.0e-6) << deg;
        EXPECT_LE(h.min, 40.0e-6) << deg;
        const double closure = c.mean - h.mean;
        EXPECT_GT(closure, closureMin) << deg;
        EXPECT_LT(closure, closureMax) << deg;
        std::printf("crank %5.1f deg: hot min %.1f mean %.1f max %.1f um, cold mean %.1f um, closure %.1f um "
                    "(free-expansion bounds %.1f ... %.1f)\n",
                    deg, h.min * 1e6, h.mean * 1e6, h.max * 1e6, c.mean * 1e6, closure * 1e6, closureMin * 1e6,
                    closureMax * 1e6);
    }
}
