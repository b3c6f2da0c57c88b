// The liner's bore distortion in the film thickness: Fourier orders (constant or a table over
// depth) and a nodal FE result (CSV or VTU) fitted on the bore (BoreDistortion, ClearanceTerms).
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
