// The thermal displacements of piston and liner (thermal.h5: ThermalDisplacementFile) in the film
// thickness, placed by the run at the liner offset, and the file's errors.
#include <gmock/gmock.h>
#include "TestFiles.hpp"
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <hdf5.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "cosim/clearance/BoreDistortion.hpp"
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/clearance/ClearanceTerms.hpp"
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "cosim/engine/SkirtFilm.hpp"
#include "cosim/clearance/ThermalDisplacementFile.hpp"

#include "ClearanceTestSupport.hpp"

using namespace flexehd;
using namespace flexehd::cosim;
using namespace flexehd::cosim::test;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;
using flexehd::test::errorOf;
using flexehd::test::scratchDir;
using flexehd::test::writeFile;

namespace fs = std::filesystem;


TEST(ThermalFile, UniformPistonAndLinerGrowthChangeHExactly) {
    const fs::path dir = scratchDir();
    writeThermal(dir / "thermal.h5",
                 {{"piston", {-0.030, 0.0, 0.020}, uniformTheta(48), [](double, double) { return 20e-6; }},
                  {"liner", linspace(-0.160, 0.0, 17), uniformTheta(36), [](double, double) { return 5e-6; }}});
    EngineCase c = smallCase();
    c.thermal.file = (dir / "thermal.h5").string();
    const SkirtFilm film(c.engine, c.piston, c.grid);
    const lube::FilmGrid& g = film.grid();
    for (double crank : {0.0, 250.0}) {
        const Eigen::VectorXd dh = change(c, film, handOffset(c, crank));
        for (int k = 0; k < g.size(); ++k)
            EXPECT_NEAR(dh[k], g.kind(k) == lube::NodeKind::Void ? 0.0 : -20e-6 + 5e-6, 1e-20) << k;
    }
}

TEST(ThermalFile, ThetaDependentFieldsAreBilinearAndPeriodic) {
    const fs::path dir = scratchDir();
    // Piston: linear in z, order 2 in θ; the file's 72 columns contain the grid's 36 (exact at
    // the nodes). Liner: linear in z plus sin θ on 10 columns (bilinear between them).
    const auto up = [](double z, double th) { return 20e-6 + 1e-4 * z + 3e-6 * std::cos(2 * th); };
    const auto ul = [](double z, double th) { return 5e-6 + 2e-5 * z + 1e-6 * std::sin(th); };
    writeThermal(dir / "thermal.h5", {{"piston", {-0.030, -0.010, 0.020}, uniformTheta(72), up},
                                      {"liner", linspace(-0.170, 0.005, 8), uniformTheta(10), ul}});
    EngineCase c = smallCase();
    c.thermal.file = (dir / "thermal.h5").string();
    const SkirtFilm film(c.engine, c.piston, c.grid);
    const lube::FilmGrid& g = film.grid();
    const double offset = handOffset(c, 45.0);
    const Eigen::VectorXd dh = change(c, film, offset);
    const double step = 2 * kPi / 10;
    double worst = 0.0;
    for (int k = 0; k < g.size(); ++k) {
        if (g.kind(k) == lube::NodeKind::Void) continue;
        const double z = g.z(g.axialIndex(k)), th = g.theta(g.thetaIndex(k));
        // Liner: linear in θ between the file's columns j, j + 1 (periodic).
        const int j = int(std::floor(th / step + 1e-12)) % 10;
        const double t = th / step - j;
        const double zl = z + offset;
        const double liner = (1 - t) * ul(zl, j * step) + t * ul(zl, ((j + 1) % 10) * step);
        worst = std::max(worst, std::abs(dh[k] - (-up(z, th) + liner)));
    }
    EXPECT_LE(worst, 1e-19);

    const ThermalDisplacement file = readThermalDisplacementFile(c.thermal.file);
    ASSERT_TRUE(file.liner.has_value());
    // Periodic: θ just below 2π interpolates between the last column and the first.
    EXPECT_NEAR(file.liner->at(-0.1, 2 * kPi - 0.5 * step), 0.5 * (ul(-0.1, 2 * kPi - step) + ul(-0.1, 0.0)), 1e-20);
    EXPECT_NEAR(file.liner->at(-0.1, -0.5 * step), file.liner->at(-0.1, 2 * kPi - 0.5 * step), 1e-20);
}

TEST(ThermalFile, LinerFieldsMoveWithThePistonInTheRun) {
    const fs::path dir = scratchDir();
    const auto ul = [](double z, double th) { return 5e-6 + 4e-5 * (z + 0.1) + 1e-6 * std::cos(th); };
    writeThermal(dir / "thermal.h5", {{"liner", linspace(-0.170, 0.0, 18), uniformTheta(36), ul}});
    EngineCase c = smallCase();
    c.thermal.file = (dir / "thermal.h5").string();
    c.liner.boreDistortion.format = BoreDistortionFormat::Fourier;
    c.liner.boreDistortion.fourier = {{-0.12, 2, 2e-6, 0.2}, {-0.03, 2, 9e-6, 0.2}};
    c.output.vtkEveryDeg = 1.0;
    // Hand-computed liner offsets at 90° and at BDC (180°): s_TDC − s(180°) = 2 r = stroke.
    for (const auto& [crank, offset] : std::vector<std::pair<double, double>>{
             {90.0, -0.0335 - (0.043 + 0.1435 - std::sqrt(0.1435 * 0.1435 - 0.043 * 0.043))},
             {180.0, -0.0335 - 0.086}}) {
        EXPECT_NEAR(offset, handOffset(c, crank), 1e-15);
        c.time.startDeg = crank - 1.0;
        PistonSimulation sim(c);
        EXPECT_NEAR(sim.linerOffset(crank), offset, 1e-12);
        std::vector<Snapshot> snaps;
        SimulationCallbacks cb;
        cb.onSnapshot = [&](const Snapshot& s) { snaps.push_back(s); };
        sim.run(cb, 1.0);
        ASSERT_FALSE(snaps.empty());
        const Snapshot& sn = snaps.back();
        ASSERT_NEAR(sn.crankDeg, crank, 1e-9);
        const lube::FilmGrid& g = sim.contact<SkirtContact>().film().grid();
        Eigen::VectorXd h;
        sim.contact<SkirtContact>().film().rigidThickness(sn.lateral, sn.tilt, h);
        double worst = 0.0;
        for (int k = 0; k < g.size(); ++k) {
            if (g.kind(k) == lube::NodeKind::Void) continue;
            const double z = g.z(g.axialIndex(k)) + offset, th = g.theta(g.thetaIndex(k));
            const double t = std::clamp((z + 0.12) / 0.09, 0.0, 1.0);
            const double expected = h[k] + ul(z, th) + ((1 - t) * 2e-6 + t * 9e-6) * std::cos(2 * (th - 0.2));
            worst = std::max(worst, std::abs(sn.filmThickness[k] - expected));
        }
        EXPECT_LE(worst, 1e-17) << "crank " << crank;  // the offset to ~1e-16 m times slopes ≤ 1e-4
    }
}

TEST(ThermalFile, BadFilesGiveClearErrors) {
    const fs::path dir = scratchDir();
    const std::vector<double> th = uniformTheta(12);
    const auto u = [](double, double) { return 1e-5; };
    EngineCase c = smallCase();
    const SkirtFilm film(c.engine, c.piston, c.grid);
    const auto error = [&](const fs::path& p) {
        c.thermal.file = p.string();
        return errorOf([&] { change(c, film, -0.05); });
    };
    EXPECT_THAT(error(dir / "missing.h5"), AllOf(HasSubstr("missing.h5"), HasSubstr("no such file")));
    writeFile(dir / "text.h5", "not hdf5");
    EXPECT_THAT(error(dir / "text.h5"), AllOf(HasSubstr("text.h5"), HasSubstr("not an HDF5 file")));
    writeThermal(dir / "format.h5", {{"piston", {-0.03, 0.02}, th, u}}, "flexehd-reduced-body");
    EXPECT_THAT(
        error(dir / "format.h5"),
        AllOf(HasSubstr("format.h5"), HasSubstr("'format' is \"flexehd-reduced-body\", expected \"flexehd-thermal\"")));
    writeThermal(dir / "version.h5", {{"piston", {-0.03, 0.02}, th, u}}, kThermalFormat, 2);
    EXPECT_THAT(error(dir / "version.h5"), AllOf(HasSubstr("version.h5"), HasSubstr("'format_version' is 2")));
    Group noTheta{"liner", {-0.17, 0.0}, th, u};
    noTheta.writeTheta = false;
    writeThermal(dir / "theta.h5", {noTheta});
    EXPECT_THAT(error(dir / "theta.h5"), AllOf(HasSubstr("theta.h5"), HasSubstr("missing dataset /liner/theta")));
    Group rows{"piston", {-0.03, 0.0, 0.02}, th, u};
    rows.rowsWritten = 2;
    writeThermal(dir / "size.h5", {rows});
    EXPECT_THAT(error(dir / "size.h5"),
                AllOf(HasSubstr("size.h5"),
                      HasSubstr("/piston/radial_displacement is 2 x 12, expected n_z x n_theta = 3 x 12")));
    std::vector<double> closed = linspace(0.0, 2 * kPi, 12);  // repeats 2π: not periodic-uniform
    writeThermal(dir / "closed.h5", {{"piston", {-0.03, 0.02}, closed, u}});
    EXPECT_THAT(error(dir / "closed.h5"), AllOf(HasSubstr("closed.h5"), HasSubstr("/piston/theta must be uniform")));
    writeThermal(dir / "short.h5", {{"piston", {-0.02, 0.02}, th, u}});
    EXPECT_THAT(error(dir / "short.h5"),
                AllOf(HasSubstr("short.h5:/piston/axial covers z = -0.02 … 0.02 m"), HasSubstr("skirt film grid")));
    writeThermal(dir / "liner.h5", {{"liner", {-0.10, 0.0}, th, u}});
    EXPECT_THAT(error(dir / "liner.h5"),
                AllOf(HasSubstr("liner.h5:/liner/axial covers z = -0.1 … 0 m"), HasSubstr("sweep over the liner")));
    {
        const hid_t f = H5Fcreate((dir / "empty.h5").c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
        attribute(f, "format", std::string(kThermalFormat));
        attribute(f, "version", 1);  // the root attribute's name in files of earlier builds
        H5Fclose(f);
    }
    EXPECT_THAT(error(dir / "empty.h5"), HasSubstr("neither a /piston nor a /liner group"));
    {
        const hid_t f = H5Fcreate((dir / "noattr.h5").c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
        H5Fclose(f);
    }
    EXPECT_THAT(error(dir / "noattr.h5"), HasSubstr("missing root attribute 'format'"));
}
