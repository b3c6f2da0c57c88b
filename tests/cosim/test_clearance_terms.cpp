// Film side of the clearance terms: the liner's bore distortion (Fourier orders, nodal FE result) and the
// thermal displacements of piston and liner (thermal.h5) in the film thickness (seed eq. 2),
// cosim/ClearanceTerms, BoreDistortion, ThermalDisplacementFile, LinerFieldTable, the case keys
// `liner.bore_distortion` and `thermal`, and their placement by the run (PistonSimulation).
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

#include "cosim/BoreDistortion.hpp"
#include "cosim/CaseFile.hpp"
#include "cosim/ClearanceTerms.hpp"
#include "cosim/PistonSimulation.hpp"
#include "cosim/SkirtFilm.hpp"
#include "cosim/ThermalDisplacementFile.hpp"

using namespace flexehd;
using namespace flexehd::cosim;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

namespace fs = std::filesystem;

namespace {

constexpr double kPi = std::numbers::pi;

using flexehd::test::errorOf;
using flexehd::test::scratchDir;
using flexehd::test::writeFile;

/// The example engine's geometry on a coarse grid; the skirt panels ±40° about ±x (Void between).
EngineCase smallCase() {
    EngineCase c;
    c.engine.bore = 0.086;
    c.engine.stroke = 0.086;
    c.engine.rodLength = 0.1435;
    c.engine.speedRpm = 1000.0;
    c.engine.pinTdcDepth = 0.0335;
    c.piston.mass = 0.3159;
    c.piston.pinMass = 0.1355;
    c.piston.inertia = 2.36e-4;
    c.piston.cgZ = 0.0139;
    c.piston.skirtTop = 0.0108;
    c.piston.skirtBottom = -0.025;
    c.piston.clearance = 50e-6;
    c.piston.skirtHalfAngle = 40.0 * kPi / 180.0;
    c.piston.profile = {{-0.025, 20e-6}, {-0.01, 0.0}, {0.0108, 30e-6}};
    c.grid.axialNodes = 9;
    c.grid.circumferentialNodes = 36;
    c.cylinderPressure = {{0.0, 1.0e5}, {360.0, 1.5e5}, {720.0, 1.0e5}};
    c.lubricant.viscosity = 0.0086;
    c.lubricant.density = 820.0;
    c.output.vtkEveryDeg = 0.0;
    c.time.maxCycles = 1;
    return c;
}

/// Liner offsets of the example crank-slider between TDC and BDC, by hand: the pin height above
/// the crank axis is r cos φ + √(l² − r² sin² φ) (no pin offset), and the liner-frame z of the
/// pin is −pin_tdc_depth − (s_TDC − s(φ)) (EngineSpec::pinTdcDepth).
double handOffset(const EngineCase& c, double crankDeg) {
    const double r = 0.5 * c.engine.stroke, l = c.engine.rodLength, phi = crankDeg * kPi / 180.0;
    const double s = r * std::cos(phi) + std::sqrt(l * l - r * r * std::sin(phi) * std::sin(phi));
    return -c.engine.pinTdcDepth - ((r + l) - s);
}

// ---- a thermal.h5 written with the HDF5 C API ----------------------------------------------

struct Group {
    std::string name;  // "piston" or "liner"
    std::vector<double> axial, theta;
    std::function<double(double, double)> u;  // u_r(z, θ)
    bool writeTheta = true;
    std::size_t rowsWritten = 0;  // 0: axial.size()
};

void attribute(hid_t file, const char* name, const std::string& value) {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(file, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
    const char* p = value.c_str();
    H5Awrite(a, type, &p);
    H5Aclose(a);
    H5Sclose(space);
    H5Tclose(type);
}

void attribute(hid_t file, const char* name, int value) {
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t a = H5Acreate2(file, name, H5T_STD_I32LE, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_INT, &value);
    H5Aclose(a);
    H5Sclose(space);
}

void dataset(hid_t group, const char* name, const std::vector<double>& v, std::vector<hsize_t> dims) {
    const hid_t space = H5Screate_simple(int(dims.size()), dims.data(), nullptr);
    const hid_t d = H5Dcreate2(group, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    H5Dclose(d);
    H5Sclose(space);
}

void writeThermal(const fs::path& path, const std::vector<Group>& groups, const std::string& format = kThermalFormat,
                  int version = kThermalFormatVersion) {
    const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    attribute(file, "format", format);
    attribute(file, "format_version", version);
    for (const Group& g : groups) {
        const hid_t grp = H5Gcreate2(file, ("/" + g.name).c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        dataset(grp, "axial", g.axial, {g.axial.size()});
        if (g.writeTheta) dataset(grp, "theta", g.theta, {g.theta.size()});
        const std::size_t rows = g.rowsWritten ? g.rowsWritten : g.axial.size();
        std::vector<double> u;
        for (std::size_t i = 0; i < rows; ++i)
            for (double th : g.theta) u.push_back(g.u(g.axial[std::min(i, g.axial.size() - 1)], th));
        dataset(grp, "radial_displacement", u, {rows, g.theta.size()});
        H5Gclose(grp);
    }
    H5Fclose(file);
}

std::vector<double> uniformTheta(int n) {
    std::vector<double> t;
    for (int j = 0; j < n; ++j) t.push_back(2.0 * kPi * j / n);
    return t;
}

std::vector<double> linspace(double a, double b, int n) {
    std::vector<double> v;
    for (int i = 0; i < n; ++i) v.push_back(a + (b - a) * i / (n - 1));
    return v;
}

/// Liner offsets the run visits (as PistonSimulation computes them, 0.25° sampling).
std::pair<double, double> sweep(const EngineCase& c) {
    double lo = handOffset(c, 0.0), hi = lo;
    for (int k = 1; k <= 1440; ++k) {
        lo = std::min(lo, handOffset(c, 0.25 * k));
        hi = std::max(hi, handOffset(c, 0.25 * k));
    }
    return {lo, hi};
}

/// h_rigid at (e, β) with the clearance terms at the offset, minus h_rigid without them.
Eigen::VectorXd change(const EngineCase& c, const SkirtFilm& film, double offset) {
    const auto [lo, hi] = sweep(c);
    const ClearanceTerms terms(c, film.grid(), lo, hi);
    Eigen::VectorXd h0, h1;
    film.rigidThickness(3e-6, 2e-4, h0);
    h1 = h0;
    terms.add(offset, h1);
    return h1 - h0;
}

}  // namespace

// ============================== bore distortion ==============================================

TEST(BoreDistortion, PureOrder2ReappearsAsAnOrder2FilmChange) {
    EngineCase c = smallCase();
    const double A = 8e-6, phi = 0.3;
    c.liner.boreDistortion.format = BoreDistortionFormat::Fourier;
    // Two measured positions far apart: the grid sits between them (interpolated in z).
    c.liner.boreDistortion.fourier = {{-0.150, 2, A, phi}, {-0.005, 2, A, phi}};
    const SkirtFilm film(c.engine, c.piston, c.grid);
    const lube::FilmGrid& g = film.grid();
    for (double crank : {0.0, 77.0, 180.0}) {
        const Eigen::VectorXd dh = change(c, film, handOffset(c, crank));
        double worst = 0.0;
        int film_ = 0;
        for (int k = 0; k < g.size(); ++k) {
            const double th = g.theta(g.thetaIndex(k));
            const double expected = g.kind(k) == lube::NodeKind::Void ? 0.0 : A * std::cos(2.0 * (th - phi));
            worst = std::max(worst, std::abs(dh[k] - expected));
            film_ += g.kind(k) != lube::NodeKind::Void;
        }
        EXPECT_LE(worst, 1e-20) << "crank " << crank;  // round-off of 8e-6: 1e-21
        EXPECT_GT(film_, 0);
    }
}

TEST(BoreDistortion, AmplitudeAndPhaseAreInterpolatedAsAFieldLinearInZ) {
    EngineCase c = smallCase();
    // Order 2 growing from 2 to 10 um between z = -0.10 and -0.04 m, order 0 and 4 at one end only,
    // the phase turning (the field, not the phase, is interpolated).
    c.liner.boreDistortion.format = BoreDistortionFormat::Fourier;
    c.liner.boreDistortion.fourier = {
        {-0.10, 2, 2e-6, 0.0}, {-0.10, 0, 1e-6, 0.0}, {-0.04, 2, 10e-6, 0.5}, {-0.04, 4, 3e-6, 1.0}};
    sortFourierTerms(c.liner.boreDistortion.fourier);
    const SkirtFilm film(c.engine, c.piston, c.grid);
    const lube::FilmGrid& g = film.grid();
    const double offset = handOffset(c, 100.0);
    const Eigen::VectorXd dh = change(c, film, offset);
    double worst = 0.0;
    for (int k = 0; k < g.size(); ++k) {
        if (g.kind(k) == lube::NodeKind::Void) continue;
        const double z = g.z(g.axialIndex(k)) + offset, th = g.theta(g.thetaIndex(k));
        const double t = std::clamp((z + 0.10) / 0.06, 0.0, 1.0);
        const double expected = (1 - t) * (2e-6 * std::cos(2 * th) + 1e-6) +
                                t * (10e-6 * std::cos(2 * (th - 0.5)) + 3e-6 * std::cos(4 * (th - 1.0)));
        worst = std::max(worst, std::abs(dh[k] - expected));
        EXPECT_NEAR(fourierDistortion(c.liner.boreDistortion.fourier, z, th), expected, 1e-19);
    }
    EXPECT_LE(worst, 1e-19);
}

TEST(BoreDistortion, FourierCsvWithDepthAndDegrees) {
    const fs::path dir = scratchDir();
    writeFile(dir / "d.csv",
              "# bore distortion, measured cold after assembly\n"
              "depth, order, amplitude, phase_deg\n"
              "0.020, 2, 6e-6, 45\n"
              "0.020, 3, 2e-6, 10\n"
              "0.120, 2, 3e-6, 45\n");
    const auto terms = readFourierTable((dir / "d.csv").string(), 0.086);
    ASSERT_EQ(terms.size(), 3u);
    EXPECT_DOUBLE_EQ(terms[0].z, -0.120);  // sorted by z
    EXPECT_DOUBLE_EQ(terms[1].z, -0.020);
    EXPECT_EQ(terms[2].order, 3);
    EXPECT_NEAR(terms[1].phase, kPi / 4, 1e-15);
    EXPECT_NEAR(fourierDistortion(terms, -0.070, kPi / 4),
                4.5e-6 + 0.5 * 2e-6 * std::cos(3 * (kPi / 4 - 10 * kPi / 180)), 1e-20);

    writeFile(dir / "bad.csv", "z, order, amplitude, phase\n-0.02, 2, 6e-6, 0\n-0.02, 2.5, 1e-6, 0\n");
    EXPECT_THAT(errorOf([&] { readFourierTable((dir / "bad.csv").string(), 0.086); }),
                AllOf(HasSubstr("bad.csv:3:"), HasSubstr("integer order")));
    writeFile(dir / "twice.csv", "z, order, amplitude, phase\n-0.02, 2, 6e-6, 0\n-0.02, 2, 1e-6, 0\n");
    EXPECT_THAT(errorOf([&] { readFourierTable((dir / "twice.csv").string(), 0.086); }),
                AllOf(HasSubstr("twice.csv:3:"), HasSubstr("given twice (first on line 2)")));
    writeFile(dir / "units.csv", "z, order, amplitude, phase\n-0.02, 2, 6, 0\n");
    EXPECT_THAT(errorOf([&] { readFourierTable((dir / "units.csv").string(), 0.086); }),
                AllOf(HasSubstr("units.csv:2:"), HasSubstr("check the units")));
    writeFile(dir / "noheader.csv", "-0.02, 2, 6e-6, 0\n");
    EXPECT_THAT(errorOf([&] { readFourierTable((dir / "noheader.csv").string(), 0.086); }),
                AllOf(HasSubstr("noheader.csv:1:"), HasSubstr("header")));
    writeFile(dir / "nophase.csv", "z, order, amplitude\n-0.02, 2, 6e-6\n");
    EXPECT_THAT(errorOf([&] { readFourierTable((dir / "nophase.csv").string(), 0.086); }),
                AllOf(HasSubstr("nophase.csv:1:"), HasSubstr("phase or phase_deg")));
}

TEST(BoreDistortion, NodalFeResultIsFittedOnTheBore) {
    const fs::path dir = scratchDir();
    EngineCase c = smallCase();
    const double R = 0.5 * c.engine.bore;
    // A liner-like node cloud: bore nodes (r = R) and wall nodes (r = R + 3 mm, other values, to be
    // ignored), as u_x, u_y, u_z. u_r on the bore: quadratic in z plus an order-2 term.
    const auto f = [](double z) { return 3e-6 + 2e-5 * z + 1e-3 * z * z; };
    const auto g2 = [](double th) { return 4e-6 * std::cos(2 * th); };
    std::string csv = "node,x,y,z,ux,uy,uz\n";
    int id = 0;
    for (int i = 0; i <= 100; ++i) {
        const double z = -0.160 + 0.160 * i / 100;
        for (int j = 0; j < 90; ++j) {
            const double th = 2 * kPi * (j + 0.5 * (i % 2)) / 90;
            for (double r : {R, R + 0.003}) {
                const double ur = r == R ? f(z) + g2(th) : 1e-4;
                csv += fmt::format("{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", ++id, r * std::cos(th),
                                   r * std::sin(th), z, ur * std::cos(th), ur * std::sin(th), 1e-6);
            }
        }
    }
    writeFile(dir / "fe.csv", csv);
    const auto nodes = readBoreNodes((dir / "fe.csv").string(), c.engine.bore);
    EXPECT_EQ(nodes.size(), 101u * 90u);
    c.liner.boreDistortion.format = BoreDistortionFormat::Nodal;
    c.liner.boreDistortion.nodes = nodes;
    const SkirtFilm film(c.engine, c.piston, c.grid);
    const lube::FilmGrid& g = film.grid();
    const double offset = handOffset(c, 123.0);
    const Eigen::VectorXd dh = change(c, film, offset);
    double worstZ = 0.0, worst = 0.0;
    for (int k = 0; k < g.size(); ++k) {
        if (g.kind(k) == lube::NodeKind::Void) continue;
        const double z = g.z(g.axialIndex(k)) + offset, th = g.theta(g.thetaIndex(k));
        worst = std::max(worst, std::abs(dh[k] - f(z) - g2(th)));
        (void)worstZ;
    }
    // Order 2 on 90 nodes per turn: the quadratic fit's error ∝ (Δθ)³; the z part is exact but
    // the rows are linear in z at ≤ 0.5 mm: 1e-3 · (0.5e-3)² / 8 = 3e-11 m.
    EXPECT_LE(worst, 0.005 * 4e-6);

    // Field quadratic in z only: the fit is exact on the table's rows; between them the rows are
    // interpolated linearly in z (spacing h = 0.5 mm here): error ≤ f'' h² / 8 = 6.25e-11 m.
    std::string csv2 = "x,y,z,ur\n";
    for (int i = 0; i <= 80; ++i)
        for (int j = 0; j < 60; ++j) {
            const double z = -0.160 + 0.160 * i / 80, th = 2 * kPi * j / 60;
            csv2 += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g}\n", R * std::cos(th), R * std::sin(th), z, f(z));
        }
    writeFile(dir / "fe2.csv", csv2);
    c.liner.boreDistortion.nodes = readBoreNodes((dir / "fe2.csv").string(), c.engine.bore);
    const Eigen::VectorXd dh2 = change(c, film, offset);
    {
        const auto [lo, hi] = sweep(c);
        const ClearanceTerms terms(c, g, lo, hi);
        ASSERT_TRUE(terms.distortion().has_value());
        const LinerFieldTable& table = *terms.distortion();
        EXPECT_LE(table.rows()[1] - table.rows()[0], 0.5e-3 + 1e-12);
        double fit = 0.0;
        for (std::size_t k = 0; k < table.rows().size(); ++k)
            for (int j = 0; j < g.nTheta(); ++j)
                fit = std::max(fit, std::abs(table.values()(Eigen::Index(k), j) - f(table.rows()[k])));
        EXPECT_LE(fit, 1e-18);
    }
    worst = 0.0;
    for (int k = 0; k < g.size(); ++k)
        if (g.kind(k) != lube::NodeKind::Void)
            worst = std::max(worst, std::abs(dh2[k] - f(g.z(g.axialIndex(k)) + offset)));
    EXPECT_LE(worst, 6.25e-11);

    // Errors: coordinates in mm; a cloud that does not cover the sweep.
    writeFile(dir / "mm.csv", "x,y,z,ur\n43,0,-10,1e-6\n");
    EXPECT_THAT(errorOf([&] { readBoreNodes((dir / "mm.csv").string(), c.engine.bore); }),
                AllOf(HasSubstr("mm.csv"), HasSubstr("innermost nodes lie at r = 43 m")));
    std::string shortCsv = "x,y,z,ur\n";
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j < 30; ++j)
            shortCsv += fmt::format("{:.17g},{:.17g},{:.17g},1e-6\n", R * std::cos(2 * kPi * j / 30),
                                    R * std::sin(2 * kPi * j / 30), -0.05 + 0.005 * i);
    writeFile(dir / "short.csv", shortCsv);
    c.liner.boreDistortion.nodes = readBoreNodes((dir / "short.csv").string(), c.engine.bore);
    c.liner.boreDistortion.file = (dir / "short.csv").string();
    EXPECT_THAT(errorOf([&] { change(c, film, offset); }),
                AllOf(HasSubstr("short.csv"), HasSubstr("cover liner-frame z = -0.05 … 0 m"), HasSubstr("sweeps")));
}

// The same FE result as a .vtu file (written by VTK's own writer, as an external FE code's
// export would be, with the nodes as points and no cells needed) gives the same bore nodes as the
// CSV: u as a 3-component array (float64, and float32 under another name), or u_r as 1 component.
TEST(BoreDistortion, NodalFeResultFromVtuEqualsTheCsv) {
    const fs::path dir = scratchDir();
    const double bore = 0.086, R = 0.5 * bore;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();  // (the second test below keeps VTK's default float32 points)
    vtkNew<vtkDoubleArray> u, ur;
    vtkNew<vtkFloatArray> u32;
    u->SetName("displacement");
    u->SetNumberOfComponents(3);
    u32->SetName("U_assembly");
    u32->SetNumberOfComponents(3);
    ur->SetName("ur");
    std::string csv = "x,y,z,ux,uy,uz\n";
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j < 36; ++j)
            for (double r : {R, R + 0.003}) {
                const double z = -0.160 + 0.004 * i, th = 2 * kPi * j / 36;
                const double radial = r == R ? 3e-6 + 4e-6 * std::cos(2 * th) + 1e-4 * z : 1e-4;
                const double x = r * std::cos(th), y = r * std::sin(th);
                points->InsertNextPoint(x, y, z);
                u->InsertNextTuple3(radial * std::cos(th), radial * std::sin(th), 1e-6);
                u32->InsertNextTuple3(radial * std::cos(th), radial * std::sin(th), 1e-6);
                ur->InsertNextValue(radial);
                csv += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", x, y, z,
                                   radial * std::cos(th), radial * std::sin(th), 1e-6);
            }
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(points);
    grid->GetPointData()->AddArray(u);
    grid->GetPointData()->AddArray(u32);
    grid->GetPointData()->AddArray(ur);
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetFileName((dir / "fe.vtu").string().c_str());
    writer->SetInputData(grid);
    ASSERT_EQ(writer->Write(), 1);
    writeFile(dir / "fe.csv", csv);

    const auto fromCsv = readBoreNodes((dir / "fe.csv").string(), bore);
    ASSERT_EQ(fromCsv.size(), 41u * 36u);
    for (const std::string field : {"displacement", "U_assembly", "ur"}) {
        const auto fromVtu = readBoreNodes((dir / "fe.vtu").string(), bore, field);
        ASSERT_EQ(fromVtu.size(), fromCsv.size()) << field;
        const double tol = field == "U_assembly" ? 1e-6 * 1e-5 : 1e-18;  // float32: 7 digits of ≤ 1e-5 m
        for (std::size_t k = 0; k < fromCsv.size(); ++k) {
            EXPECT_EQ(fromVtu[k].x, fromCsv[k].x);
            EXPECT_EQ(fromVtu[k].z, fromCsv[k].z);
            EXPECT_NEAR(fromVtu[k].ur, fromCsv[k].ur, tol) << field << " node " << k;
        }
    }

    // Errors name the file and what it holds.
    EXPECT_THAT(errorOf([&] { readBoreNodes((dir / "fe.vtu").string(), bore, "u"); }),
                AllOf(HasSubstr("fe.vtu: no point-data array 'u'"),
                      HasSubstr("the file has 'displacement', 'U_assembly', 'ur'")));
    writeFile(dir / "fake.vtu", "x,y,z,ur\n0.043,0,0,1e-6\n");
    EXPECT_THAT(errorOf([&] { readBoreNodes((dir / "fake.vtu").string(), bore); }),
                HasSubstr("fake.vtu: not a VTK XML unstructured grid"));
    {  // a .vtu cut short after its header
        std::ifstream in(dir / "fe.vtu", std::ios::binary);
        std::string head(400, '\0');
        in.read(head.data(), std::streamsize(head.size()));
        writeFile(dir / "cut.vtu", head);
    }
    EXPECT_THAT(errorOf([&] { readBoreNodes((dir / "cut.vtu").string(), bore); }),
                HasSubstr("cut.vtu: cannot read the points of the .vtu file"));
    EXPECT_THAT(errorOf([&] { readBoreNodes((dir / "missing.vtu").string(), bore); }),
                HasSubstr("missing.vtu: no such file"));
}

// ============================== thermal.h5 ===================================================

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
        const lube::FilmGrid& g = sim.film().grid();
        Eigen::VectorXd h;
        sim.film().rigidThickness(sn.lateral, sn.tilt, h);
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

// ============================== case file ====================================================

namespace {
const char* kCase = R"(engine:
  bore: 0.086
  stroke: 0.086
  rod_length: 0.1435
  speed_rpm: 1000
  pin_tdc_depth: 0.0335
piston:
  mass: 0.3
  pin_mass: 0.13
  inertia: 2.4e-4
  skirt_top: 0.0108
  skirt_bottom: -0.025
cylinder_pressure: p.csv
)";

std::string writeCase(const fs::path& dir, const std::string& extra, bool pinDepth = true) {
    std::string text = kCase;
    if (!pinDepth) text.erase(text.find("  pin_tdc_depth: 0.0335\n"), 24);
    writeFile(dir / "case.yaml", text + extra);
    writeFile(dir / "p.csv", "0,1e5\n360,4e6\n720,1e5\n");
    return (dir / "case.yaml").string();
}
}  // namespace

TEST(CaseFileThermal, KeysAreReadAndDefaultsAreOff) {
    const fs::path dir = scratchDir();
    const EngineCase none = readCaseFile(writeCase(dir, ""));
    EXPECT_EQ(none.liner.boreDistortion.format, BoreDistortionFormat::None);
    EXPECT_TRUE(none.thermal.file.empty());
    EXPECT_FALSE(ClearanceTerms::wanted(none));

    writeThermal(dir / "thermal.h5",
                 {{"piston", {-0.03, 0.02}, uniformTheta(12), [](double, double) { return 1e-5; }}});
    writeFile(dir / "d.csv", "z,order,amplitude,phase\n-0.05,2,5e-6,0.1\n");
    const EngineCase a = readCaseFile(writeCase(dir,
                                                "thermal:\n  file: thermal.h5\nliner:\n  bore_distortion:\n"
                                                "    format: fourier\n    file: d.csv\n"));
    EXPECT_EQ(a.thermal.file, (dir / "thermal.h5").string());
    ASSERT_EQ(a.liner.boreDistortion.format, BoreDistortionFormat::Fourier);
    EXPECT_EQ(a.liner.boreDistortion.file, (dir / "d.csv").string());
    ASSERT_EQ(a.liner.boreDistortion.fourier.size(), 1u);
    EXPECT_DOUBLE_EQ(a.liner.boreDistortion.fourier[0].phase, 0.1);

    const EngineCase b = readCaseFile(writeCase(dir,
                                                "liner:\n  bore_distortion:\n    format: fourier\n    orders:\n"
                                                "      - {depth: 0.02, order: 2, amplitude: 6e-6, phase_deg: 90}\n"
                                                "      - {z: -0.12, order: 4, amplitude: 1e-6, phase: 0}\n"));
    ASSERT_EQ(b.liner.boreDistortion.fourier.size(), 2u);
    EXPECT_DOUBLE_EQ(b.liner.boreDistortion.fourier[0].z, -0.12);
    EXPECT_DOUBLE_EQ(b.liner.boreDistortion.fourier[1].z, -0.02);
    EXPECT_NEAR(b.liner.boreDistortion.fourier[1].phase, kPi / 2, 1e-15);

    std::string fe = "node,x,y,z,ur\n";
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j < 12; ++j)
            fe += fmt::format("{},{:.17g},{:.17g},{:g},2e-6\n", 12 * i + j, 0.043 * std::cos(kPi * j / 6),
                              0.043 * std::sin(kPi * j / 6), -0.04 * i);
    writeFile(dir / "fe.csv", fe);
    const EngineCase n = readCaseFile(writeCase(dir, "liner:\n  bore_distortion: {format: nodal, file: fe.csv}\n"));
    EXPECT_EQ(n.liner.boreDistortion.format, BoreDistortionFormat::Nodal);
    EXPECT_EQ(n.liner.boreDistortion.nodes.size(), 60u);
    EXPECT_DOUBLE_EQ(n.liner.boreDistortion.nodes[7].ur, 2e-6);
}

TEST(CaseFileThermal, BadInputNamesTheKey) {
    const fs::path dir = scratchDir();
    const auto err = [&](const std::string& extra, bool pinDepth = true, CaseFileOptions o = {}) {
        const std::string path = writeCase(dir, extra, pinDepth);
        return errorOf([&] { readCaseFile(path, o); });
    };
    const std::string file = (dir / "case.yaml").string();
    EXPECT_THAT(err("liner:\n  bore_distorsion: {format: fourier}\n"),
                AllOf(StartsWith(file + ": liner.bore_distorsion (line 15): unknown key"),
                      HasSubstr("did you mean 'bore_distortion'?")));
    EXPECT_THAT(err("thermal:\n  files: thermal.h5\n"),
                AllOf(StartsWith(file + ": thermal.files"), HasSubstr("did you mean 'file'?")));
    EXPECT_THAT(err("thermal:\n  file: nothere.h5\n"),
                AllOf(StartsWith(file + ": thermal.file (line 15): thermal-displacement file"),
                      HasSubstr("nothere.h5: no such file (make it with `flexehd thermal`)")));
    EXPECT_EQ(err("thermal:\n  file: nothere.h5\n", true, CaseFileOptions{.checkBodyFiles = false}), "");
    writeThermal(dir / "wrong.h5", {{"piston", {-0.03, 0.02}, uniformTheta(12), [](double, double) { return 0.0; }}},
                 "something-else");
    EXPECT_THAT(err("thermal:\n  file: wrong.h5\n"),
                AllOf(StartsWith(file + ": thermal.file"), HasSubstr("'format' is \"something-else\"")));
    EXPECT_THAT(err("thermal:\n  file: wrong.h5\n", false, CaseFileOptions{.checkBodyFiles = false}),
                AllOf(StartsWith(file + ": engine.pin_tdc_depth"),
                      HasSubstr("required with liner.bore_distortion or thermal")));
    EXPECT_THAT(err("liner:\n  bore_distortion:\n    format: fouriar\n    file: d.csv\n"),
                AllOf(StartsWith(file + ": liner.bore_distortion.format"), HasSubstr("did you mean 'fourier'?")));
    EXPECT_THAT(err("liner:\n  bore_distortion:\n    file: d.csv\n"),
                AllOf(StartsWith(file + ": liner.bore_distortion.format"), HasSubstr("required key missing")));
    EXPECT_THAT(err("liner:\n  bore_distortion:\n    format: fourier\n    file: missing.csv\n"),
                AllOf(StartsWith(file + ": liner.bore_distortion.file (line 17): "),
                      HasSubstr("missing.csv: no such file or not readable")));
    writeFile(dir / "bad.csv", "z,order,amplitude,phase\n-0.05,2,5e-6,0.1\n-0.05,x,1e-6,0\n");
    EXPECT_THAT(err("liner:\n  bore_distortion:\n    format: fourier\n    file: bad.csv\n"),
                AllOf(StartsWith(file + ": liner.bore_distortion.file"), HasSubstr("bad.csv:3: expected a number")));
    EXPECT_THAT(err("liner:\n  bore_distortion:\n    format: fourier\n    orders:\n"
                    "      - {z: -0.02, order: 2, amplitude: 6e-6, phase_deg: 90}\n"
                    "      - {z: -0.02, order: 2, amplitude: 1e-6, phase_deg: 0}\n"),
                AllOf(StartsWith(file + ": liner.bore_distortion.orders[1] (line 19): "),
                      HasSubstr("given twice (first at liner.bore_distortion.orders[0])")));
    EXPECT_THAT(
        err("liner:\n  bore_distortion:\n    format: fourier\n    orders:\n"
            "      - {z: -0.02, order: 2, amplitude: 6e-6, phase: 1, phase_deg: 90}\n"),
        AllOf(StartsWith(file + ": liner.bore_distortion.orders[0].phase_deg"), HasSubstr("exactly one of phase")));
    EXPECT_THAT(
        err("liner:\n  bore_distortion:\n    format: fourier\n    orders:\n"
            "      - {z: -0.02, order: 2, amplitude: 6e-6, phase: 1, ordre: 3}\n"),
        AllOf(StartsWith(file + ": liner.bore_distortion.orders[0].ordre"), HasSubstr("did you mean 'order'?")));
    EXPECT_THAT(err("liner:\n  bore_distortion:\n    format: nodal\n    orders: []\n"),
                AllOf(StartsWith(file + ": liner.bore_distortion.orders"), HasSubstr("format: fourier")));
    EXPECT_THAT(err("liner:\n  bore_distortion: {format: fourier}\n", false),
                AllOf(StartsWith(file + ": liner.bore_distortion.file"), HasSubstr("required key missing")));
}

// liner.bore_distortion {format: nodal, file: X.vtu, field: NAME}: the array is named by `field`
// (default `displacement`); `field` with a CSV or a Fourier table is refused.
TEST(CaseFileThermal, NodalVtuFieldKey) {
    const fs::path dir = scratchDir();
    vtkNew<vtkPoints> points;
    vtkNew<vtkDoubleArray> ur;
    ur->SetName("u_radial");
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j < 12; ++j) {
            points->InsertNextPoint(0.043 * std::cos(kPi * j / 6), 0.043 * std::sin(kPi * j / 6), -0.04 * i);
            ur->InsertNextValue(2e-6);
        }
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(points);
    grid->GetPointData()->AddArray(ur);
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetFileName((dir / "fe.vtu").string().c_str());
    writer->SetInputData(grid);
    ASSERT_EQ(writer->Write(), 1);
    const EngineCase n =
        readCaseFile(writeCase(dir, "liner:\n  bore_distortion: {format: nodal, file: fe.vtu, field: u_radial}\n"));
    EXPECT_EQ(n.liner.boreDistortion.format, BoreDistortionFormat::Nodal);
    ASSERT_EQ(n.liner.boreDistortion.nodes.size(), 60u);
    EXPECT_DOUBLE_EQ(n.liner.boreDistortion.nodes[7].ur, 2e-6);

    const std::string file = (dir / "case.yaml").string();
    EXPECT_THAT(errorOf([&] {
                    readCaseFile(writeCase(dir, "liner:\n  bore_distortion: {format: nodal, file: fe.vtu}\n"));
                }),
                AllOf(StartsWith(file + ": liner.bore_distortion.file"),
                      HasSubstr("no point-data array 'displacement' (the file has 'u_radial')")));
    writeFile(dir / "fe.csv", "x,y,z,ur\n0.043,0,0,1e-6\n");
    EXPECT_THAT(errorOf([&] {
                    readCaseFile(writeCase(dir, "liner:\n  bore_distortion: {format: nodal, file: fe.csv, field: u}\n"));
                }),
                AllOf(StartsWith(file + ": liner.bore_distortion.field"), HasSubstr("this table is a CSV")));
}
