// The case keys of the clearance terms: `liner.bore_distortion` and `thermal`, their defaults
// and errors.
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
#include "MinimalCaseFile.hpp"

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


namespace {

std::string writeCase(const fs::path& dir, const std::string& extra, bool pinDepth = true) {
    std::string text = flexehd::test::kMinimalCase;
    if (!pinDepth) text.erase(text.find("  pin_tdc_depth: 0.0335\n"), 24);
    writeFile(dir / "case.yaml", text + extra);
    writeFile(dir / "p.csv", flexehd::test::kMinimalPressureTable);
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
