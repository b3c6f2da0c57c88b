// The case file (cosim/casefile/CaseFile) and the cylinder-pressure function (cosim/engine/CylinderPressure):
// the shipped example reads and holds the documented values; every kind of bad input is an
// error naming the file and the key; periodic piecewise-linear interpolation against hand
// values; the example's piston mass properties against an integration over the piston mesh.
#include <gmock/gmock.h>
#include "TestFiles.hpp"
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "cosim/casefile/CaseFile.hpp"
#include "cosim/run/StarvedStepTolerance.hpp"
#include "cosim/engine/CylinderPressure.hpp"
#include "fem/MeshReader.hpp"
#include "fem/Quadrature.hpp"
#include "fem/ShapeFunctions.hpp"

using namespace flexehd;
using cosim::BodyModel;
using cosim::CaseFileOptions;
using cosim::CylinderPressure;
using cosim::CouplingSpec;
using cosim::EngineCase;
using cosim::PressureSample;
using cosim::PressureTableError;
using cosim::readCaseFile;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string source(const std::string& rel) {
    return std::string(FLEXEHD_SOURCE_DIR) + "/" + rel;
}

using flexehd::test::errorOf;
using flexehd::test::scratchDir;
using flexehd::test::writeFile;

CaseFileOptions noBodyFiles() {
    CaseFileOptions o;
    o.checkBodyFiles = false;
    return o;
}

// ---- a small valid case, mutated by the error tests -----------------------------------------

const char* kPressureCsv =
    "# test table\n"
    "crank_angle_deg,pressure_pa\n"
    "0,1.0e5\n"
    "180,0.9e5\n"
    "360,4.0e6\n"
    "540,2.0e5\n"
    "720,1.0e5\n";

const char* kValidCase = R"(name: small
engine:
  bore: 0.086
  stroke: 0.086
  rod_length: 0.1435
  speed_rpm: 1000
piston:
  mass: 0.3
  pin_mass: 0.13
  inertia: 2.4e-4
  cg_z: 0.014
  skirt_top: 0.0108
  skirt_bottom: -0.025
  clearance: 5e-05
  profile:
    - [-0.025, 20e-6]
    - [-0.010, 0.0]
    - [0.0108, 30e-6]
cylinder_pressure: p.csv
)";

using Edits = std::vector<std::pair<std::string, std::string>>;

/// Writes kValidCase with each `from` replaced by its `to` (each must be found) to DIR/case.yaml,
/// and the pressure table to DIR/p.csv; returns the case path.
std::string caseWith(const fs::path& dir, const Edits& edits, const std::string& csv = kPressureCsv) {
    std::string text = kValidCase;
    for (const auto& [from, to] : edits) {
        const auto pos = text.find(from);
        if (pos == std::string::npos) throw std::logic_error("test case text lacks: " + from);
        text.replace(pos, from.size(), to);
    }
    writeFile(dir / "case.yaml", text);
    writeFile(dir / "p.csv", csv);
    return (dir / "case.yaml").string();
}

std::string caseWith(const fs::path& dir, const std::string& from = "", const std::string& to = "",
                     const std::string& csv = kPressureCsv) {
    return caseWith(dir, from.empty() ? Edits{} : Edits{{from, to}}, csv);
}

std::string caseError(const fs::path& dir, const Edits& edits, const std::string& csv = kPressureCsv,
                      CaseFileOptions options = {}) {
    const std::string path = caseWith(dir, edits, csv);
    return errorOf([&] { readCaseFile(path, options); });
}

std::string caseError(const fs::path& dir, const std::string& from, const std::string& to,
                      const std::string& csv = kPressureCsv, CaseFileOptions options = {}) {
    return caseError(dir, from.empty() ? Edits{} : Edits{{from, to}}, csv, options);
}

// ---- mass properties of a TET10 mesh ---------------------------------------------------------

struct MassProperties {
    double mass = 0.0;   ///< kg
    Eigen::Vector3d cg;  ///< m
    double iyy = 0.0;    ///< kg m^2 about the y-parallel axis through the CG
};

MassProperties integrate(const fem::Mesh& mesh, double rho) {
    using Shape = fem::Shape<fem::ElementType::Tet10>;
    EXPECT_EQ(mesh.volume.type, fem::ElementType::Tet10);
    const auto& rule = fem::tetrahedronRule(5);
    double m = 0.0;
    Eigen::Vector3d first = Eigen::Vector3d::Zero();
    double sxx = 0.0, szz = 0.0;
    Eigen::Matrix<double, 3, 10> X;
    for (fem::Index e = 0; e < mesh.volume.size(); ++e) {
        for (int a = 0; a < 10; ++a) X.col(a) = mesh.nodes.col(mesh.volume.nodes(a, e));
        for (const auto& q : rule) {
            const Eigen::Matrix3d J = X * Shape::dN(q.xi);
            const Eigen::Vector3d x = X * Shape::N(q.xi);
            const double w = rho * q.weight * J.determinant();
            m += w;
            first += w * x;
            sxx += w * x.x() * x.x();
            szz += w * x.z() * x.z();
        }
    }
    MassProperties p;
    p.mass = m;
    p.cg = first / m;
    p.iyy = sxx + szz - m * (p.cg.x() * p.cg.x() + p.cg.z() * p.cg.z());
    return p;
}

}  // namespace

// ============================== the shipped example ==========================================

TEST(CaseFileExample, ReadsWithTheDocumentedValues) {
    const std::string path = source("examples/engine86/case.yaml");
    const EngineCase c = readCaseFile(path, noBodyFiles());
    EXPECT_EQ(c.path, fs::path(path).lexically_normal().string());
    EXPECT_THAT(c.name, HasSubstr("engine86"));
    EXPECT_DOUBLE_EQ(c.engine.bore, 0.086);
    EXPECT_DOUBLE_EQ(c.engine.stroke, 0.086);
    EXPECT_DOUBLE_EQ(c.engine.rodLength, 0.1435);
    EXPECT_DOUBLE_EQ(c.engine.pinOffset, 0.0);
    EXPECT_DOUBLE_EQ(c.engine.speedRpm, 1000.0);
    EXPECT_DOUBLE_EQ(c.engine.crankcasePressure, 1e5);
    EXPECT_DOUBLE_EQ(c.engine.pinTdcDepth, 0.0335);
    EXPECT_DOUBLE_EQ(c.piston.clearance, 50e-6);
    EXPECT_DOUBLE_EQ(c.piston.skirtTop, 0.0108);
    EXPECT_DOUBLE_EQ(c.piston.skirtBottom, -0.025);
    // Panel half-width: asin(Y_e / R_sk) of meshes/piston.geo, in rad.
    EXPECT_NEAR(c.piston.skirtHalfAngle, std::asin(27.5 / 42.95), 1e-4);
    ASSERT_GE(c.piston.profile.size(), 2u);
    EXPECT_DOUBLE_EQ(c.piston.profile.front().z, c.piston.skirtBottom);
    EXPECT_DOUBLE_EQ(c.piston.profile.back().z, c.piston.skirtTop);
    double minDrop = 1.0;
    for (const auto& pt : c.piston.profile) minDrop = std::min(minDrop, pt.drop);
    EXPECT_DOUBLE_EQ(minDrop, 0.0);
    EXPECT_GT(c.piston.profile.front().drop, 10e-6);  // tens of um at the edges
    EXPECT_GT(c.piston.profile.back().drop, 10e-6);
    EXPECT_LT(c.piston.profile.back().drop, 100e-6);
    // E* from Al 75 GPa / 0.33 and cast iron 110 GPa / 0.26, Hertz convention.
    EXPECT_NEAR(c.contact.compositeModulus, 1.0 / ((1 - 0.33 * 0.33) / 75e9 + (1 - 0.26 * 0.26) / 110e9), 1.0);
    EXPECT_NEAR(c.contact.compositeModulus, 49.12e9, 0.01e9);
    EXPECT_NEAR(c.contact.asperityDensity * c.contact.beta * c.contact.sigma, 0.04, 1e-4);
    EXPECT_NEAR(c.contact.sigma / c.contact.beta, 1e-3, 1e-9);
    EXPECT_EQ(c.pistonBody.model, BodyModel::Flexible);
    EXPECT_EQ(c.pistonBody.file, fs::path(source("out/engine86/piston.h5")).lexically_normal().string());
    EXPECT_EQ(c.pistonBody.surface, "skirt");
    EXPECT_EQ(c.pistonBody.interface, "pin_bore");
    EXPECT_EQ(c.linerBody.model, BodyModel::Rigid);
    EXPECT_EQ(c.coupling.acceleration, cosim::CouplingAcceleration::IqnIls);
    EXPECT_TRUE(c.coupling.keepJacobian);
    EXPECT_EQ(c.coupling.response, cosim::ElasticResponse::QuasiStatic);
    EXPECT_NEAR(c.time.tiltTolerance, 5e-6, 1e-9);
    EXPECT_EQ(c.output.directory, fs::path(source("out/engine86/ehd")).lexically_normal().string());
    EXPECT_EQ(c.cylinderPressureFile,
              fs::path(source("examples/engine86/cylinder_pressure.csv")).lexically_normal().string());

    // The pressure trace: 0.5 deg resolution, peak 3-5 MPa at 370-375 deg, gas exchange near 1 bar.
    ASSERT_EQ(c.cylinderPressure.size(), 1441u);
    const CylinderPressure p(c.cylinderPressure);
    EXPECT_GT(p.peak(), 3e6);
    EXPECT_LT(p.peak(), 5e6);
    EXPECT_GE(p.peakAngleDeg(), 370.0);
    EXPECT_LE(p.peakAngleDeg(), 375.0);
    EXPECT_NEAR(p(90.0), 0.7e5, 1.0);    // intake stroke at the manifold pressure
    EXPECT_NEAR(p(630.0), 1.05e5, 1.0);  // exhaust stroke at the back-pressure
    EXPECT_GT(p(360.0), p(0.0) * 10.0);  // compression
}

TEST(CaseFileExample, VariantsDifferOnlyInBodiesOutputAndThermalState) {
    const EngineCase ehd = readCaseFile(source("examples/engine86/case.yaml"), noBodyFiles());
    const EngineCase hd = readCaseFile(source("examples/engine86/hd.yaml"), noBodyFiles());
    const EngineCase both = readCaseFile(source("examples/engine86/ehd_liner.yaml"), noBodyFiles());
    const EngineCase hot = readCaseFile(source("examples/engine86/thermal_hd.yaml"), noBodyFiles());
    const EngineCase dynamic = readCaseFile(source("examples/engine86/ehd_dynamic.yaml"), noBodyFiles());
    const EngineCase rigidRate = readCaseFile(source("examples/engine86/ehd_rigid_rate.yaml"), noBodyFiles());
    const EngineCase flooded = readCaseFile(source("examples/engine86/mass_conserving.yaml"), noBodyFiles());
    const EngineCase starved = readCaseFile(source("examples/engine86/starved.yaml"), noBodyFiles());
    const EngineCase starvedEhd = readCaseFile(source("examples/engine86/starved_ehd.yaml"), noBodyFiles());
    const EngineCase rings = readCaseFile(source("examples/engine86/hd_rings.yaml"), noBodyFiles());
    // The HD run with the ring pack: hd.yaml but for its rings and output.
    EXPECT_EQ(rings.rings.size(), 3u);
    EXPECT_TRUE(hd.rings.empty());
    EXPECT_EQ(rings.piston.profile.size(), hd.piston.profile.size());
    EXPECT_EQ(rings.contact.compositeModulus, hd.contact.compositeModulus);
    EXPECT_EQ(rings.lubricant.viscosity, hd.lubricant.viscosity);
    EXPECT_EQ(rings.cylinderPressureFile, hd.cylinderPressureFile);
    EXPECT_EQ(rings.time.maxCycles, hd.time.maxCycles);
    EXPECT_EQ(rings.grid.axialNodes, hd.grid.axialNodes);
    const EngineCase ehdRings = readCaseFile(source("examples/engine86/ehd_rings.yaml"), noBodyFiles());
    EXPECT_EQ(ehdRings.rings.size(), 3u);
    EXPECT_EQ(ehdRings.pistonBody.file, ehd.pistonBody.file);
    EXPECT_EQ(ehdRings.pistonBody.model, BodyModel::Flexible);
    EXPECT_EQ(ehdRings.grid.axialNodes, ehd.grid.axialNodes);
    EXPECT_EQ(ehdRings.piston.profile.size(), ehd.piston.profile.size());
    // The EHD run on the starved layer: case.yaml's bodies, starved.yaml's film and supply.
    EXPECT_EQ(starvedEhd.pistonBody.file, ehd.pistonBody.file);
    EXPECT_EQ(starvedEhd.pistonBody.model, BodyModel::Flexible);
    EXPECT_EQ(starvedEhd.linerBody.model, BodyModel::Rigid);
    EXPECT_EQ(starvedEhd.lubricant.cavitation, starved.lubricant.cavitation);
    EXPECT_EQ(starvedEhd.lubricant.supply.model, starved.lubricant.supply.model);
    ASSERT_EQ(starvedEhd.lubricant.supply.layer.size(), 1u);
    EXPECT_EQ(starvedEhd.lubricant.supply.layer[0].thickness, starved.lubricant.supply.layer[0].thickness);
    ASSERT_TRUE(starvedEhd.lubricant.supply.oilControlRing && starved.lubricant.supply.oilControlRing);
    EXPECT_EQ(starvedEhd.lubricant.supply.oilControlRing->bottom, starved.lubricant.supply.oilControlRing->bottom);
    EXPECT_EQ(starvedEhd.lubricant.supply.oilControlRing->top, starved.lubricant.supply.oilControlRing->top);
    EXPECT_EQ(starvedEhd.lubricant.supply.oilControlRing->thickness, starved.lubricant.supply.oilControlRing->thickness);
    EXPECT_EQ(starvedEhd.coupling.maxIterations, CouplingSpec::kFlexiblePasses);
    // The oil-supply pair: hd.yaml with the mass-conserving film, flooded and on a 3 µm liner layer.
    EXPECT_EQ(hd.lubricant.cavitation, cosim::CavitationModel::Reynolds);
    for (const EngineCase* v : {&flooded, &starved}) {
        EXPECT_EQ(v->lubricant.cavitation, cosim::CavitationModel::MassConserving);
        EXPECT_EQ(v->pistonBody.model, BodyModel::Rigid);
        EXPECT_EQ(v->linerBody.model, BodyModel::Rigid);
    }
    EXPECT_EQ(flooded.lubricant.supply.model, cosim::OilSupplyModel::Flooded);
    EXPECT_EQ(starved.lubricant.supply.model, cosim::OilSupplyModel::LinerLayer);
    ASSERT_EQ(starved.lubricant.supply.layer.size(), 1u);
    EXPECT_EQ(starved.lubricant.supply.layer[0].thickness, 3.0e-6);
    EXPECT_EQ(dynamic.coupling.response, cosim::ElasticResponse::Dynamic);
    EXPECT_FALSE(rigidRate.coupling.elasticSqueeze);
    EXPECT_TRUE(ehd.coupling.elasticSqueeze && dynamic.coupling.elasticSqueeze);  // the default with newton
    EXPECT_EQ(rigidRate.pistonBody.model, BodyModel::Flexible);
    EXPECT_EQ(dynamic.pistonBody.model, BodyModel::Flexible);
    EXPECT_EQ(hd.pistonBody.model, BodyModel::Rigid);
    EXPECT_EQ(hot.pistonBody.model, BodyModel::Rigid);
    EXPECT_EQ(hot.linerBody.model, BodyModel::Rigid);
    // The thermal variant: cold clearance 75 µm (docs/thermal.md §7) and the thermal file.
    EXPECT_EQ(hot.piston.clearance, 75.0e-6);
    EXPECT_EQ(hot.thermal.file, fs::path(source("out/engine86/thermal/thermal.h5")).lexically_normal().string());
    EXPECT_TRUE(hd.thermal.file.empty() && ehd.thermal.file.empty() && both.thermal.file.empty());
    EXPECT_EQ(hd.linerBody.model, BodyModel::Rigid);
    EXPECT_EQ(both.pistonBody.model, BodyModel::Flexible);
    EXPECT_EQ(both.linerBody.model, BodyModel::Flexible);
    EXPECT_EQ(both.linerBody.surface, "bore");
    EXPECT_EQ(both.linerBody.interface, "top_seat");
    EXPECT_THAT(both.linerBody.interfaces, ::testing::ElementsAre("top_seat", "bottom_seat"));
    EXPECT_EQ(both.linerBody.file, fs::path(source("out/engine86/liner.h5")).lexically_normal().string());
    for (const EngineCase* v : {&hd, &both, &hot, &dynamic, &rigidRate, &flooded, &starved, &starvedEhd}) {
        EXPECT_NE(v->output.directory, ehd.output.directory);
        // Everything else equal: compare the parameter structs field by field through memcmp-free
        // checks of the values that drive the physics.
        EXPECT_EQ(v->engine.bore, ehd.engine.bore);
        EXPECT_EQ(v->engine.stroke, ehd.engine.stroke);
        EXPECT_EQ(v->engine.rodLength, ehd.engine.rodLength);
        EXPECT_EQ(v->engine.pinOffset, ehd.engine.pinOffset);
        EXPECT_EQ(v->engine.speedRpm, ehd.engine.speedRpm);
        EXPECT_EQ(v->engine.crankcasePressure, ehd.engine.crankcasePressure);
        EXPECT_EQ(v->engine.pinTdcDepth, ehd.engine.pinTdcDepth);
        EXPECT_EQ(v->piston.mass, ehd.piston.mass);
        EXPECT_EQ(v->piston.pinMass, ehd.piston.pinMass);
        EXPECT_EQ(v->piston.inertia, ehd.piston.inertia);
        EXPECT_EQ(v->piston.cgX, ehd.piston.cgX);
        EXPECT_EQ(v->piston.cgZ, ehd.piston.cgZ);
        EXPECT_EQ(v->piston.skirtTop, ehd.piston.skirtTop);
        EXPECT_EQ(v->piston.skirtBottom, ehd.piston.skirtBottom);
        if (v != &hot) {
            EXPECT_EQ(v->piston.clearance, ehd.piston.clearance);
        }
        EXPECT_EQ(v->piston.skirtHalfAngle, ehd.piston.skirtHalfAngle);
        EXPECT_EQ(v->piston.ovality, ehd.piston.ovality);
        ASSERT_EQ(v->piston.profile.size(), ehd.piston.profile.size());
        for (std::size_t i = 0; i < ehd.piston.profile.size(); ++i) {
            EXPECT_EQ(v->piston.profile[i].z, ehd.piston.profile[i].z);
            EXPECT_EQ(v->piston.profile[i].drop, ehd.piston.profile[i].drop);
        }
        EXPECT_EQ(v->lubricant.viscosity, ehd.lubricant.viscosity);
        EXPECT_EQ(v->lubricant.density, ehd.lubricant.density);
        EXPECT_EQ(v->lubricant.barusAlpha, ehd.lubricant.barusAlpha);
        EXPECT_EQ(v->lubricant.cavitationPressure, ehd.lubricant.cavitationPressure);
        EXPECT_EQ(v->contact.sigma, ehd.contact.sigma);
        EXPECT_EQ(v->contact.beta, ehd.contact.beta);
        EXPECT_EQ(v->contact.asperityDensity, ehd.contact.asperityDensity);
        EXPECT_EQ(v->contact.compositeModulus, ehd.contact.compositeModulus);
        EXPECT_EQ(v->contact.boundaryFriction, ehd.contact.boundaryFriction);
        EXPECT_EQ(v->cylinderPressureFile, ehd.cylinderPressureFile);
        EXPECT_EQ(v->grid.axialNodes, ehd.grid.axialNodes);
        EXPECT_EQ(v->grid.circumferentialNodes, ehd.grid.circumferentialNodes);
        EXPECT_EQ(v->time.startDeg, ehd.time.startDeg);
        EXPECT_EQ(v->time.maxStepDeg, ehd.time.maxStepDeg);
        EXPECT_EQ(v->time.minStepDeg, ehd.time.minStepDeg);
        if (v == &flooded) {  // the defaults, for studies that switch it to a starved supply: the
                              // same lateral value, 5e-6 rad exactly against the others' 2.865e-4 deg
            EXPECT_EQ(v->time.lateralTolerance, ehd.time.lateralTolerance);
            EXPECT_EQ(v->time.tiltTolerance, cosim::TimeSpec{}.tiltTolerance);
            EXPECT_NEAR(v->time.tiltTolerance, ehd.time.tiltTolerance, 1e-4 * ehd.time.tiltTolerance);
        } else if (v != &starved && v != &starvedEhd) {  // a starved skirt's slaps need the tighter step error (docs/coupling.md §1)
            EXPECT_EQ(v->time.lateralTolerance, ehd.time.lateralTolerance);
            EXPECT_EQ(v->time.tiltTolerance, ehd.time.tiltTolerance);
        } else {  // the liner layer's defaults
            EXPECT_EQ(v->time.lateralTolerance, cosim::TimeSpec::kStarvedLateralTolerance);
            EXPECT_EQ(v->time.tiltTolerance, cosim::TimeSpec::kStarvedTiltTolerance);
        }
        if (v != &starved && v != &starvedEhd) {  // the starved layer settles over more cycles (docs/case-file.md)
            EXPECT_EQ(v->time.maxCycles, ehd.time.maxCycles);
        }
        EXPECT_EQ(v->time.periodicityTolerance, ehd.time.periodicityTolerance);
        EXPECT_EQ(v->coupling.tolerance, ehd.coupling.tolerance);
        // Every example takes the passes' default: more with a flexible body (docs/coupling.md §1,
        // "Passes per step").
        EXPECT_EQ(v->coupling.maxIterations,
                  v->hasFlexibleBody() ? CouplingSpec::kFlexiblePasses : CouplingSpec{}.maxIterations);
        EXPECT_EQ(v->coupling.acceleration, ehd.coupling.acceleration);
        if (v != &dynamic) {
            EXPECT_EQ(v->coupling.response, ehd.coupling.response);
        }
        EXPECT_EQ(v->output.vtkEveryDeg, ehd.output.vtkEveryDeg);
        EXPECT_EQ(v->output.modeShapes, ehd.output.modeShapes);
    }
}

TEST(CaseFileExample, BodyFilesAreCheckedByDefault) {
    // A copy of the example whose bodies point into an empty directory.
    const fs::path dir = scratchDir();
    fs::copy_file(source("examples/engine86/case.yaml"), dir / "case.yaml");
    fs::copy_file(source("examples/engine86/cylinder_pressure.csv"), dir / "cylinder_pressure.csv");
    const std::string path = (dir / "case.yaml").string();
    EXPECT_THAT(errorOf([&] { readCaseFile(path); }),
                AllOf(StartsWith(path + ": bodies.piston.file (line "), HasSubstr("piston.h5 does not exist")));
    EXPECT_EQ(errorOf([&] { readCaseFile(path, noBodyFiles()); }), "");
}

// The piston's mass, CG and rotary inertia in the example are the integrals over the shipped
// mesh at its default size (0.004 m, aluminium 2700 kg/m^3). Independent estimates: the same
// integral on the coarse mesh (0.0065 m), and Gmsh/OpenCASCADE's exact-geometry values quoted in
// docs/meshes.md (0.3159 kg, z_cg = 13.91 mm, I_yy = 2.360e-4 kg m^2).
TEST(CaseFileExample, PistonMassPropertiesMatchTheMesh) {
    const EngineCase c = readCaseFile(source("examples/engine86/case.yaml"), noBodyFiles());
    fem::MeshOptions options;
    options.size = 0.0065;
    const fem::Mesh mesh = fem::readMesh(source("meshes/piston.geo"), options);
    const MassProperties mp = integrate(mesh, 2700.0);
    EXPECT_NEAR(c.piston.mass, mp.mass, 0.003 * mp.mass);
    EXPECT_NEAR(c.piston.cgZ, mp.cg.z(), 0.1e-3);
    EXPECT_NEAR(c.piston.cgX, mp.cg.x(), 0.05e-3);
    EXPECT_NEAR(mp.cg.y(), 0.0, 0.05e-3);
    EXPECT_NEAR(c.piston.inertia, mp.iyy, 0.01 * mp.iyy);
    // OpenCASCADE's exact-geometry values (docs/meshes.md).
    EXPECT_NEAR(c.piston.mass, 0.3159, 0.002);
    EXPECT_NEAR(c.piston.cgZ, 13.91e-3, 0.05e-3);
    EXPECT_NEAR(c.piston.inertia, 2.360e-4, 0.01 * 2.360e-4);
    // Hand check: a 86 mm piston of 0.32 kg is GN/D^3 = 0.50 g/cm^3 (typical 0.4-0.5 for SI pistons).
    EXPECT_NEAR(c.piston.mass / std::pow(8.6, 3) * 1000.0, 0.50, 0.02);
    // Steel pin 21 mm OD, 12 mm ID, 74 mm long.
    EXPECT_NEAR(c.piston.pinMass, 7850.0 * kPi / 4 * (0.021 * 0.021 - 0.012 * 0.012) * 0.074, 0.001);
}

// The values written into examples/engine86/*.yaml; run with --gtest_also_run_disabled_tests.
TEST(CaseFileExample, DISABLED_PrintPistonMassPropertiesDefaultMesh) {
    const fem::Mesh mesh = fem::readMesh(source("meshes/piston.geo"));  // default size 0.004
    const MassProperties mp = integrate(mesh, 2700.0);
    std::cout.precision(6);
    std::cout << "piston.geo, default size, " << mesh.volume.size() << " TET10, rho 2700:\n  mass " << mp.mass
              << " kg\n  cg (" << mp.cg.x() << ", " << mp.cg.y() << ", " << mp.cg.z() << ") m\n  Iyy about the CG "
              << mp.iyy << " kg m^2\n";
}

// ============================== errors ======================================================

TEST(CaseFileErrors, ValidSmallCaseReadsWithDefaults) {
    const fs::path dir = scratchDir();
    const EngineCase c = readCaseFile(caseWith(dir));
    EXPECT_EQ(c.name, "small");
    EXPECT_DOUBLE_EQ(c.engine.pinOffset, 0.0);
    EXPECT_DOUBLE_EQ(c.piston.cgX, 0.0);
    EXPECT_DOUBLE_EQ(c.piston.skirtHalfAngle, kPi / 2);
    EXPECT_EQ(c.pistonBody.model, BodyModel::Rigid);
    EXPECT_EQ(c.linerBody.model, BodyModel::Rigid);
    EXPECT_EQ(c.output.directory, (dir / "results").lexically_normal().string());
    const cosim::EngineCase defaults;
    EXPECT_EQ(c.lubricant.viscosity, defaults.lubricant.viscosity);
    EXPECT_EQ(c.contact.compositeModulus, defaults.contact.compositeModulus);
    EXPECT_EQ(c.grid.axialNodes, defaults.grid.axialNodes);
    EXPECT_EQ(c.time.maxStepDeg, defaults.time.maxStepDeg);
    EXPECT_EQ(c.time.tiltTolerance, defaults.time.tiltTolerance);
    EXPECT_EQ(c.coupling.maxIterations, defaults.coupling.maxIterations);
    EXPECT_EQ(c.coupling.method, cosim::CouplingMethod::Newton);
    EXPECT_EQ(c.contact.coatingThickness, defaults.contact.coatingThickness);
    ASSERT_EQ(c.cylinderPressure.size(), 5u);
    EXPECT_EQ(c.cylinderPressure[2].crankDeg, 360.0);
    EXPECT_EQ(c.cylinderPressure[2].pressure, 4.0e6);
}

// Spreadsheet programs and some editors start UTF-8 files with a byte-order mark: the case file
// and the pressure table are read as without it.
TEST(CaseFileErrors, ByteOrderMarksAreAccepted) {
    const fs::path dir = scratchDir();
    const std::string path = caseWith(dir, Edits{}, "\xEF\xBB\xBF" "0,1e5\n180,2e5\n360,4e6\n540,2e5\n720,1e5\n");
    std::ifstream in(path);
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    std::ofstream(path) << "\xEF\xBB\xBF" << text;
    const EngineCase c = readCaseFile(path);
    EXPECT_EQ(c.name, "small");
    ASSERT_EQ(c.cylinderPressure.size(), 5u);
    EXPECT_EQ(c.cylinderPressure[0].crankDeg, 0.0);
}

TEST(CaseFileErrors, NegativeValueNamesFileKeyAndLine) {
    const fs::path dir = scratchDir();
    const std::string file = (dir / "case.yaml").string();
    EXPECT_EQ(caseError(dir, "clearance: 5e-05", "clearance: -5e-05"),
              file + ": piston.clearance (line 14): expected a positive length in m, got -5e-05");
    EXPECT_THAT(caseError(dir, "mass: 0.3", "mass: 0"),
                AllOf(StartsWith(file + ": piston.mass (line 8): "), HasSubstr("positive mass"), HasSubstr("got 0")));
    EXPECT_THAT(caseError(dir, "speed_rpm: 1000", "speed_rpm: -1000"),
                AllOf(StartsWith(file + ": engine.speed_rpm"), HasSubstr("got -1000")));
    EXPECT_THAT(caseError(dir, "cylinder_pressure: p.csv", "cylinder_pressure: p.csv\nlubricant:\n  viscosity: -0.01"),
                AllOf(StartsWith(file + ": lubricant.viscosity"), HasSubstr("positive dynamic viscosity in Pa s")));
}

TEST(CaseFileErrors, UnknownKeySuggestsTheClosest) {
    const fs::path dir = scratchDir();
    const std::string file = (dir / "case.yaml").string();
    EXPECT_THAT(caseError(dir, "clearance: 5e-05", "clearence: 5e-05"),
                AllOf(StartsWith(file + ": piston.clearence (line 14): unknown key"),
                      HasSubstr("did you mean 'clearance'?"), HasSubstr("valid keys here: mass, pin_mass")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\nlubricants: {}"),
                AllOf(StartsWith(file + ": lubricants"), HasSubstr("did you mean 'lubricant'?")));
    EXPECT_THAT(caseError(dir, "speed_rpm: 1000", "speed: 1000"),
                AllOf(StartsWith(file + ": engine.speed"), HasSubstr("did you mean 'speed_rpm'?")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ntime: {max_step: 0.5}"),
                AllOf(StartsWith(file + ": time.max_step"), HasSubstr("did you mean 'max_step_deg'?")));
    // Nothing close: no suggestion, but the list.
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ngrid: {resolution: 3}"),
                AllOf(StartsWith(file + ": grid.resolution"), Not(HasSubstr("did you mean")),
                      HasSubstr("axial_nodes, circumferential_nodes")));
    EXPECT_THAT(caseError(dir, "bore: 0.086", "bore: 0.086\n  bore: 0.087"),
                AllOf(StartsWith(file + ": engine.bore"), HasSubstr("given twice")));
}

TEST(CaseFileErrors, WrongTypes) {
    const fs::path dir = scratchDir();
    const std::string file = (dir / "case.yaml").string();
    EXPECT_THAT(
        caseError(dir, "bore: 0.086", "bore: [0.086]"),
        AllOf(StartsWith(file + ": engine.bore (line 3): "), HasSubstr("expected a positive length in m, got a list")));
    EXPECT_THAT(caseError(dir, "bore: 0.086", "bore: 86mm"),
                AllOf(StartsWith(file + ": engine.bore"), HasSubstr("got '86mm'")));
    EXPECT_THAT(caseError(dir, "bore: 0.086", "bore:"),
                AllOf(StartsWith(file + ": engine.bore"), HasSubstr("got nothing")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ngrid: {axial_nodes: 40.5}"),
                AllOf(StartsWith(file + ": grid.axial_nodes"),
                      HasSubstr("expected a whole number of nodes from 3 to 100000, got '40.5'")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ncoupling: {max_iterations: 2147483648}"),
                AllOf(StartsWith(file + ": coupling.max_iterations"),
                      HasSubstr("expected a whole number of iterations from 1 to 10000, got 2147483648")));
    EXPECT_THAT(caseError(dir, "bore: 0.086", "bore: []"),
                AllOf(StartsWith(file + ": engine.bore"), HasSubstr("got an empty list")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\noutput: {mode_shapes: maybe}"),
                AllOf(StartsWith(file + ": output.mode_shapes"), HasSubstr("true or false")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ncoupling: {elastic_squeeze: 1e-3}"),
                AllOf(StartsWith(file + ": coupling.elastic_squeeze"), HasSubstr("true or false")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ncoupling: {keep_jacobian: 0.5}"),
                AllOf(StartsWith(file + ": coupling.keep_jacobian"), HasSubstr("true or false")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ncoupling: {acceleration: iqn_ils}"),
                AllOf(StartsWith(file + ": coupling.acceleration"), HasSubstr("one of iqn-ils, aitken"),
                      HasSubstr("did you mean 'iqn-ils'?")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\nbodies: {response: static}"),
                AllOf(StartsWith(file + ": bodies.response"), HasSubstr("quasi_static, dynamic")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\nbodies: {piston: flexible}"),
                AllOf(StartsWith(file + ": bodies.piston"), HasSubstr("'rigid' or a mapping")));
    EXPECT_THAT(caseError(dir, "    - [-0.010, 0.0]\n", "    - [-0.010]\n"),
                AllOf(StartsWith(file + ": piston.profile[1] (line 17)"), HasSubstr("pair [z, drop]")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\nlubricant: 3"),
                AllOf(StartsWith(file + ": lubricant (line 2)"), HasSubstr("expected a mapping")));
    EXPECT_THAT(caseError(dir, "name: small", "name: [small"),
                AllOf(StartsWith(file + ":"), HasSubstr("YAML syntax error")));
}

TEST(CaseFileErrors, MissingRequiredKeys) {
    const fs::path dir = scratchDir();
    const std::string file = (dir / "case.yaml").string();
    EXPECT_THAT(caseError(dir, "  bore: 0.086\n", ""),
                AllOf(StartsWith(file + ": engine.bore"), HasSubstr("required key missing")));
    EXPECT_THAT(caseError(dir, "  inertia: 2.4e-4\n", ""),
                AllOf(StartsWith(file + ": piston.inertia"), HasSubstr("required key missing")));
    EXPECT_THAT(caseError(dir, "cylinder_pressure: p.csv\n", ""),
                AllOf(StartsWith(file + ": cylinder_pressure"), HasSubstr("required key missing")));
    // A flexible liner needs pin_tdc_depth (it places the piston on the liner mesh).
    EXPECT_THAT(
        caseError(dir, "name: small", "name: small\nbodies: {liner: {file: l.h5}}", kPressureCsv, noBodyFiles()),
        AllOf(StartsWith(file + ": engine.pin_tdc_depth"), HasSubstr("flexible liner")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\nbodies: {piston: {file: p.h5, interface: []}}",
                          kPressureCsv, noBodyFiles()),
                AllOf(StartsWith(file + ": bodies.piston.interface (line 2): "),
                      HasSubstr("expected an interface name or a list of them, got an empty list")));
}

TEST(CaseFile, PistonLoadsAreReadAndCheckedKeyByKey) {
    const fs::path dir = scratchDir();
    const std::string file = (dir / "case.yaml").string();
    const auto withBodies = [&](const std::string& bodies) {
        return caseWith(dir, "name: small", "name: small\nbodies: " + bodies);
    };
    const CaseFileOptions noFiles = noBodyFiles();
    const EngineCase c = readCaseFile(withBodies("{piston: {file: p.h5, loads: [inertia, gas_pressure]}}"), noFiles);
    EXPECT_TRUE(c.pistonBody.loads.gasPressure);
    EXPECT_TRUE(c.pistonBody.loads.inertia);
    EXPECT_EQ(c.pistonBody.loads.gasSurface, "crown");
    const EngineCase d =
        readCaseFile(withBodies("{piston: {file: p.h5, loads: [gas_pressure], gas_surface: top}}"), noFiles);
    EXPECT_TRUE(d.pistonBody.loads.gasPressure);
    EXPECT_FALSE(d.pistonBody.loads.inertia);
    EXPECT_EQ(d.pistonBody.loads.gasSurface, "top");
    const auto error = [&](const std::string& bodies) {
        return caseError(dir, "name: small", "name: small\nbodies: " + bodies, kPressureCsv, noBodyFiles());
    };
    EXPECT_THAT(error("{piston: {file: p.h5, loads: [gravity]}}"),
                AllOf(StartsWith(file + ": bodies.piston.loads[0]"), HasSubstr("expected gas_pressure, inertia or ring_pack, got 'gravity'")));
    EXPECT_THAT(error("{piston: {file: p.h5, loads: [inertia, inertia]}}"),
                AllOf(StartsWith(file + ": bodies.piston.loads[1]"), HasSubstr("listed twice")));
    EXPECT_THAT(error("{piston: {file: p.h5, loads: inertia}}"),
                AllOf(StartsWith(file + ": bodies.piston.loads"), HasSubstr("expected a list of gas_pressure, inertia, ring_pack")));
    EXPECT_THAT(error("{piston: {file: p.h5, loads: [inertia], gas_surface: crown}}"),
                AllOf(StartsWith(file + ": bodies.piston.gas_surface"), HasSubstr("does not list")));
    EXPECT_THAT(error("{liner: {file: l.h5, loads: [inertia]}}"),
                AllOf(StartsWith(file + ": bodies.liner.loads"), HasSubstr("loads act on the piston only")));
}

TEST(CaseFileErrors, OutOfRangeAndInconsistentValues) {
    const fs::path dir = scratchDir();
    const std::string file = (dir / "case.yaml").string();
    EXPECT_THAT(caseError(dir, "rod_length: 0.1435", "rod_length: 0.04"),
                AllOf(StartsWith(file + ": engine.rod_length"), HasSubstr("stroke/2 + |pin_offset|")));
    EXPECT_THAT(caseError(dir, "rod_length: 0.1435", "rod_length: 0.044\n  pin_offset: 0.002"),
                AllOf(StartsWith(file + ": engine.rod_length"), HasSubstr("0.045")));
    EXPECT_THAT(caseError(dir, "skirt_bottom: -0.025", "skirt_bottom: 0.02"),
                AllOf(StartsWith(file + ": piston.skirt_bottom"), HasSubstr("skirt_bottom < skirt_top")));
    EXPECT_THAT(caseError(dir, "    - [-0.010, 0.0]\n", "    - [-0.030, 0.0]\n"),
                AllOf(StartsWith(file + ": piston.profile[1]"), HasSubstr("strictly ascending")));
    EXPECT_THAT(caseError(dir, "    - [-0.025, 20e-6]\n", "    - [-0.020, 20e-6]\n"),
                AllOf(StartsWith(file + ": piston.profile"), HasSubstr("must cover the skirt")));
    EXPECT_THAT(caseError(dir, "    - [-0.010, 0.0]\n", "    - [-0.010, -60e-6]\n"),
                AllOf(StartsWith(file + ": piston.profile[1]"), HasSubstr("touch the bore")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\noutput: {vtk_every_deg: 1.0e-9}"),
                AllOf(StartsWith(file + ": output.vtk_every_deg"), HasSubstr("0 (no VTK) or 0.01 to 720 deg")));
    EXPECT_THAT(caseError(dir, "clearance: 5e-05", "clearance: 5e-05\n  skirt_half_angle_deg: 200"),
                AllOf(StartsWith(file + ": piston.skirt_half_angle_deg"), HasSubstr("0 < angle <= 180")));
    EXPECT_THAT(caseError(dir, "clearance: 5e-05", "clearance: 5e-05\n  skirt_half_angle_deg: 0"),
                AllOf(StartsWith(file + ": piston.skirt_half_angle_deg"), HasSubstr("positive angle in deg")));
    EXPECT_THAT(caseError(dir, "clearance: 5e-05", "clearance: 0.05"),
                AllOf(StartsWith(file + ": piston.clearance"), HasSubstr("check the units")));
    EXPECT_THAT(
        caseError(dir, "name: small", "name: small\ntime: {max_step_deg: 0.01, min_step_deg: 0.1}"),
        AllOf(StartsWith(file + ": time.max_step_deg"), HasSubstr("max_step_deg (0.01) >= min_step_deg (0.1)")));
    EXPECT_THAT(
        caseError(dir, {{"cylinder_pressure: p.csv", "cylinder_pressure: p.csv\ngrid: {circumferential_nodes: 16}"},
                        {"clearance: 5e-05", "clearance: 5e-05\n  skirt_half_angle_deg: 20"}}),
        AllOf(StartsWith(file + ": grid.circumferential_nodes"), HasSubstr("skirt panel")));
    EXPECT_THAT(
        caseError(dir, "name: small", "name: small\ncontact: {composite_modulus: 4e10, piston_youngs_modulus: 7.5e10}"),
        AllOf(StartsWith(file + ": contact.composite_modulus"), HasSubstr("not both")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ncontact: {piston_youngs_modulus: 7.5e10}"),
                AllOf(StartsWith(file + ": contact.piston_poisson_ratio"), HasSubstr("required key missing")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ncontact: {hard_contact_stiffness: 1e14, coating_thickness: 1e-5}"),
                AllOf(StartsWith(file + ": contact.hard_contact_stiffness"), HasSubstr("not both")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ncontact: {coating_thickness: 0.015}"),
                AllOf(StartsWith(file + ": contact.coating_thickness"), HasSubstr("check the units")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ncontact: {coating_poisson_ratio: 0.5}"),
                AllOf(StartsWith(file + ": contact.coating_poisson_ratio"), HasSubstr("(-1, 0.5)")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ncontact: {restitution: 1.2}"),
                AllOf(StartsWith(file + ": contact.restitution"), HasSubstr("(0, 1]")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ncontact: {restitution: 0}"),
                StartsWith(file + ": contact.restitution"));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ncoupling: {method: monolithic}"),
                AllOf(StartsWith(file + ": coupling.method"), HasSubstr("newton, partitioned")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ncoupling: {method: partitioned, elastic_squeeze: true}"),
                AllOf(StartsWith(file + ": coupling.elastic_squeeze"), HasSubstr("coupling.method: newton")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\nlubricant: {cavitation_pressure: 2e5}"),
                AllOf(StartsWith(file + ": lubricant.cavitation_pressure")));
    EXPECT_THAT(caseError(dir, "name: small",
                          "name: small\nlubricant: {cavitation: mass_conserving}\nbodies: {piston: {file: p.h5}}\n"
                          "coupling: {method: partitioned}",
                          kPressureCsv, noBodyFiles()),
                AllOf(StartsWith(file + ": coupling.method"), HasSubstr("coupling.method: newton")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ncontact: {liner_wear_coefficient: 1e-6}"),
                AllOf(StartsWith(file + ": contact.liner_wear_coefficient"), HasSubstr("check the units")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\ncontact: {piston_wear_coefficient: -1e-16}"),
                AllOf(StartsWith(file + ": contact.piston_wear_coefficient")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\nlubricant: {cavitation: elrod}"),
                AllOf(StartsWith(file + ": lubricant.cavitation"), HasSubstr("reynolds, mass_conserving")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\nlubricant: {cavitation: mass_conserving, barus_alpha: 2e-8}"),
                AllOf(StartsWith(file + ": lubricant.cavitation"), HasSubstr("barus_alpha: 0")));
    EXPECT_THAT(caseError(dir, "name: small", "name: small\nlubricant: {supply: {model: liner_layer, thickness: 3e-6}}"),
                AllOf(StartsWith(file + ": lubricant.supply.model"), HasSubstr("mass_conserving")));
    EXPECT_THAT(caseError(dir, "name: small",
                          "name: small\nlubricant: {cavitation: mass_conserving, supply: {model: liner_layer}}"),
                AllOf(StartsWith(file + ": lubricant.supply"), HasSubstr("either thickness")));
    EXPECT_THAT(caseError(dir, "name: small",
                          "name: small\nlubricant: {cavitation: mass_conserving, supply: {model: liner_layer, "
                          "thickness: 3e-3}}"),
                AllOf(StartsWith(file + ": lubricant.supply.thickness"), HasSubstr("check the units")));
    EXPECT_THAT(caseError(dir, "name: small",
                          "name: small\nlubricant: {cavitation: mass_conserving, supply: {model: liner_layer, "
                          "thickness_table: [[0.05, 3e-6], [0.01, 2e-6]]}}"),
                AllOf(StartsWith(file + ": lubricant.supply.thickness_table[1]"), HasSubstr("ascending")));
    EXPECT_THAT(caseError(dir, "name: small",
                          "name: small\nlubricant: {cavitation: mass_conserving, supply: {thickness: 3e-6}}"),
                AllOf(StartsWith(file + ": lubricant.supply.thickness"), HasSubstr("liner_layer")));
    EXPECT_THAT(caseError(dir, "speed_rpm: 1000", "speed_rpm: 1000\n  pin_tdc_depth: 0.005"),
                AllOf(StartsWith(file + ": engine.pin_tdc_depth"), HasSubstr("above the deck")));
}

// A flexible body, on the mass-conserving film (flooded or on the liner's oil layer) or the
// Reynolds film, gets more passes per step by default (docs/coupling.md §1, "Passes per step",
// and §6); a rigid one keeps the general default, and the key given wins.
TEST(CaseFile, FlexibleBodiesGetMorePassesByDefault) {
    const fs::path dir = scratchDir();
    const std::string starved =
        "name: small\nlubricant: {cavitation: mass_conserving, supply: {model: liner_layer, thickness: 3e-6}}\n";
    const std::string flexible = "bodies: {piston: {file: p.h5}}\n";
    auto passes = [&](const std::string& text) {
        return readCaseFile(caseWith(dir, "name: small", text), noBodyFiles()).coupling.maxIterations;
    };
    EXPECT_EQ(passes(starved + flexible), CouplingSpec::kFlexiblePasses);
    EXPECT_EQ(passes(starved + flexible + "coupling: {max_iterations: 40}"), 40);
    EXPECT_EQ(passes(starved), CouplingSpec{}.maxIterations);
    EXPECT_EQ(passes("name: small\nlubricant: {cavitation: mass_conserving}\n" + flexible),
              CouplingSpec::kFlexiblePasses);
    EXPECT_EQ(passes("name: small\n" + flexible), CouplingSpec::kFlexiblePasses);
    EXPECT_EQ(passes("name: small\n"), CouplingSpec{}.maxIterations);
    EXPECT_GT(CouplingSpec::kFlexiblePasses, CouplingSpec{}.maxIterations);
}

// On the liner's oil layer the step error tolerances default to a tenth of the general ones (a
// starved skirt's cycles repeat only then: docs/coupling.md §1); a flooded film keeps the general
// defaults, and the keys given win.
TEST(CaseFile, AStarvedSkirtGetsATighterStepToleranceByDefault) {
    const fs::path dir = scratchDir();
    const std::string starved =
        "name: small\nlubricant: {cavitation: mass_conserving, supply: {model: liner_layer, thickness: 3e-6}}\n";
    auto time = [&](const std::string& text) { return readCaseFile(caseWith(dir, "name: small", text)).time; };
    const cosim::TimeSpec general{};
    EXPECT_EQ(time(starved).lateralTolerance, cosim::TimeSpec::kStarvedLateralTolerance);
    EXPECT_EQ(time(starved).tiltTolerance, cosim::TimeSpec::kStarvedTiltTolerance);
    EXPECT_NEAR(cosim::TimeSpec::kStarvedLateralTolerance, 0.1 * general.lateralTolerance, 1e-20);
    EXPECT_NEAR(cosim::TimeSpec::kStarvedTiltTolerance, 0.1 * general.tiltTolerance, 1e-20);
    const cosim::TimeSpec given = time(starved + "time: {lateral_tolerance: 0.1e-6, tilt_tolerance_deg: 1.0e-4}");
    EXPECT_EQ(given.lateralTolerance, 0.1e-6);
    EXPECT_NEAR(given.tiltTolerance, 1.0e-4 * std::numbers::pi / 180.0, 1e-18);
    const cosim::TimeSpec flooded = time("name: small\nlubricant: {cavitation: mass_conserving}\n");
    EXPECT_EQ(flooded.lateralTolerance, general.lateralTolerance);
    EXPECT_EQ(flooded.tiltTolerance, general.tiltTolerance);
    EXPECT_EQ(time("name: small").lateralTolerance, general.lateralTolerance);
}

// A starved case given the flooded film's tolerances (copied from hd.yaml) is warned, naming the
// keys and the defaults; at the defaults, tighter, or flooded, it is not.
TEST(CaseFile, LooseStepToleranceOnALinerLayerIsWarned) {
    const fs::path dir = scratchDir();
    const std::string starved =
        "name: small\nlubricant: {cavitation: mass_conserving, supply: {model: liner_layer, thickness: 3e-6}}\n";
    auto warning = [&](const std::string& text) {
        return cosim::looseStarvedStepTolerance(readCaseFile(caseWith(dir, "name: small", text)));
    };
    const auto loose = warning(starved + "time: {lateral_tolerance: 0.2e-6, tilt_tolerance_deg: 2.865e-4}");
    ASSERT_TRUE(loose.has_value());
    EXPECT_THAT(*loose, AllOf(HasSubstr("time.lateral_tolerance 2e-07 m (liner layer default 2e-08 m)"),
                              HasSubstr("time.tilt_tolerance_deg 0.0002865 (default 2.865e-05)"),
                              HasSubstr("remove the key")));
    const auto tiltOnly = warning(starved + "time: {tilt_tolerance_deg: 1.0e-4}");
    ASSERT_TRUE(tiltOnly.has_value());
    EXPECT_THAT(*tiltOnly, Not(HasSubstr("lateral")));
    EXPECT_FALSE(warning(starved).has_value());
    EXPECT_FALSE(warning(starved + "time: {lateral_tolerance: 0.01e-6}").has_value());
    EXPECT_FALSE(warning("name: small\nlubricant: {cavitation: mass_conserving}\n"
                         "time: {lateral_tolerance: 0.2e-6}").has_value());
}

TEST(CaseFile, TheKeptJacobianCanBeTurnedOff) {
    const fs::path dir = scratchDir();
    auto keep = [&](const std::string& text) {
        return readCaseFile(caseWith(dir, "name: small", text), noBodyFiles()).coupling.keepJacobian;
    };
    EXPECT_TRUE(keep("name: small"));
    EXPECT_FALSE(keep("name: small\ncoupling: {keep_jacobian: false}"));
}

TEST(CaseFile, OilControlRingIsReadAndPlacedOnThePiston) {
    const fs::path dir = scratchDir();
    const std::string file = (dir / "case.yaml").string();
    const std::string supply = "name: small\nlubricant: {cavitation: mass_conserving, supply: {model: liner_layer, "
                               "thickness: 3e-6, oil_control_ring: ";
    auto withRing = [&](const std::string& ring) { return supply + ring + "}}"; };
    const EngineCase c =
        readCaseFile(caseWith(dir, "name: small", withRing("{bottom: 0.0138, top: 0.0163, thickness: 1e-6}")));
    ASSERT_TRUE(c.lubricant.supply.oilControlRing.has_value());
    EXPECT_EQ(c.lubricant.supply.oilControlRing->bottom, 0.0138);
    EXPECT_EQ(c.lubricant.supply.oilControlRing->top, 0.0163);
    EXPECT_EQ(c.lubricant.supply.oilControlRing->thickness, 1e-6);
    EXPECT_FALSE(readCaseFile(caseWith(dir, "name: small", "name: small")).lubricant.supply.oilControlRing.has_value());

    const std::string ring = file + ": lubricant.supply.oil_control_ring";
    EXPECT_THAT(caseError(dir, "name: small", withRing("{bottom: 0.0138, thickness: 1e-6}")),
                StartsWith(ring + ".top"));
    EXPECT_THAT(caseError(dir, "name: small", withRing("{bottom: 0.0163, top: 0.0138, thickness: 1e-6}")),
                AllOf(StartsWith(ring + ".top"), HasSubstr("above its lower edge")));
    EXPECT_THAT(caseError(dir, "name: small", withRing("{bottom: 0.0138, top: 0.0163, thickness: 2e-3}")),
                AllOf(StartsWith(ring + ".thickness"), HasSubstr("check the units")));
    EXPECT_THAT(caseError(dir, "name: small", withRing("{bottom: 0.0138, top: 0.0163, thickness: -1e-6}")),
                StartsWith(ring + ".thickness"));
    EXPECT_THAT(caseError(dir, "name: small", withRing("{bottom: 0.005, top: 0.0163, thickness: 1e-6}")),
                AllOf(StartsWith(ring + ".bottom"), HasSubstr("piston.skirt_top = 0.0108")));
    EXPECT_THAT(caseError(dir, "name: small", withRing("{bottom: 0.0138, top: 0.04, thickness: 1e-6}")),
                AllOf(StartsWith(ring + ".top"), HasSubstr("above the deck")));
    EXPECT_THAT(caseError(dir, "name: small", withRing("{bottom: 0.0138, top: 0.0163, thick: 1e-6}")),
                AllOf(StartsWith(ring + ".thick"), HasSubstr("did you mean 'thickness'")));
    EXPECT_THAT(caseError(dir, "name: small",
                          "name: small\nlubricant: {supply: {oil_control_ring: {bottom: 0.0138, top: 0.0163, "
                          "thickness: 1e-6}}}"),
                AllOf(StartsWith(file + ": lubricant.supply.oil_control_ring"), HasSubstr("liner_layer")));
}

TEST(CaseFileErrors, MissingAndUnreadableFiles) {
    const fs::path dir = scratchDir();
    const std::string file = (dir / "case.yaml").string();
    EXPECT_THAT(
        errorOf([&] { readCaseFile((dir / "nope.yaml").string()); }),
        AllOf(StartsWith((dir / "nope.yaml").string() + ": cannot read the case file"), HasSubstr("no such file")));
    EXPECT_THAT(caseError(dir, "cylinder_pressure: p.csv", "cylinder_pressure: missing.csv"),
                AllOf(StartsWith(file + ": cylinder_pressure (line 19): "), HasSubstr((dir / "missing.csv").string()),
                      HasSubstr("no such file")));
    // Reduced-body files: missing, a directory, not HDF5; relative to the case file.
    EXPECT_THAT(caseError(dir, "name: small", "name: small\nbodies: {piston: {file: piston.h5}}"),
                AllOf(StartsWith(file + ": bodies.piston.file"), HasSubstr((dir / "piston.h5").string()),
                      HasSubstr("does not exist")));
    fs::create_directories(dir / "adir");
    EXPECT_THAT(caseError(dir, "name: small", "name: small\nbodies: {piston: {file: adir}}"),
                AllOf(StartsWith(file + ": bodies.piston.file"), HasSubstr("is a directory")));
    writeFile(dir / "text.h5", "not hdf5 at all");
    EXPECT_THAT(caseError(dir, "name: small", "name: small\nbodies: {liner: {file: text.h5}}"),
                AllOf(StartsWith(file + ": bodies.liner.file"), HasSubstr("not an HDF5 file")));
    // A file with the HDF5 signature passes the check (its content is the simulation's business).
    writeFile(dir / "sig.h5", std::string("\x89HDF\r\n\x1a\n", 8) + std::string(100, '\0'));
    const EngineCase c = readCaseFile(caseWith(dir, "name: small", "name: small\nbodies: {piston: {file: sig.h5}}"));
    EXPECT_EQ(c.pistonBody.file, (dir / "sig.h5").string());
    EXPECT_EQ(c.pistonBody.surface, "skirt");
    EXPECT_EQ(c.pistonBody.interface, "pin_bore");
    // output.directory naming an existing file.
    writeFile(dir / "afile", "x");
    EXPECT_THAT(caseError(dir, "name: small", "name: small\noutput: {directory: afile}"),
                AllOf(StartsWith(file + ": output.directory"), HasSubstr("not a directory")));
}

TEST(CaseFileErrors, BadPressureTables) {
    const fs::path dir = scratchDir();
    const std::string file = (dir / "case.yaml").string();
    const std::string csv = (dir / "p.csv").string();
    auto bad = [&](const std::string& table) { return caseError(dir, "", "", table); };
    const std::string prefix = file + ": cylinder_pressure (line 19): " + csv;
    EXPECT_THAT(bad("0,1e5\n360,4e6\n300,2e6\n720,1e5\n"),
                AllOf(StartsWith(prefix + ":3: "), HasSubstr("strictly ascending")));
    EXPECT_THAT(bad("# c\n0,1e5\n360,-4e6\n720,1e5\n"), AllOf(StartsWith(prefix + ":3: "), HasSubstr("positive")));
    EXPECT_THAT(bad("0,1e5\n100,4e6\n200,2e5\n"), AllOf(StartsWith(prefix + ":3: "), HasSubstr("does not cover")));
    EXPECT_THAT(bad("10,1e5\n360,4e6\n720,1e5\n"), AllOf(StartsWith(prefix + ":1: "), HasSubstr("start at 0 deg")));
    EXPECT_THAT(bad("0,1e5\n360,4e6\n730,1e5\n"), AllOf(StartsWith(prefix + ":3: "), HasSubstr("beyond the 720")));
    EXPECT_THAT(bad("0,1e5\n360,4e6\n720,2e5\n"), AllOf(StartsWith(prefix + ":3: "), HasSubstr("must repeat")));
    EXPECT_THAT(bad("angle,p\n0,1e5\n360,4e6,7\n720,1e5\n"),
                AllOf(StartsWith(prefix + ":3: "), HasSubstr("two numbers")));
    EXPECT_THAT(bad("angle,p\n0,1e5\nfoo,bar\n720,1e5\n"),
                AllOf(StartsWith(prefix + ":3: "), HasSubstr("two numbers")));
    EXPECT_THAT(bad("# only comments\n"), AllOf(StartsWith(prefix + ": "), HasSubstr("at least 2 samples")));
    EXPECT_THAT(bad("0,1\n360,40\n720,1\n"), AllOf(StartsWith(prefix + ": "), HasSubstr("in Pa")));
    // Accepted: a header, blanks, semicolons, and an open end within the widest spacing.
    EXPECT_EQ(bad("crank;p\n\n0;1e5\n360;4e6\n540;2e5\n"), "");
    EXPECT_EQ(bad("0 1e5\n360 4e6\n"), "");
}

// ============================== CylinderPressure ============================================

TEST(CylinderPressure, InterpolatesLinearlyAndPeriodically) {
    const CylinderPressure p(
        {{0.0, 1.0e5}, {180.0, 0.8e5}, {360.0, 5.0e6}, {370.0, 6.0e6}, {540.0, 3.0e5}, {720.0, 1.0e5}});
    EXPECT_DOUBLE_EQ(p(0.0), 1.0e5);
    EXPECT_DOUBLE_EQ(p(90.0), 0.9e5);   // halfway 1.0e5 -> 0.8e5
    EXPECT_DOUBLE_EQ(p(365.0), 5.5e6);  // halfway 5e6 -> 6e6
    EXPECT_DOUBLE_EQ(p(362.5), 5.25e6);
    EXPECT_DOUBLE_EQ(p(630.0), 2.0e5);  // halfway 3e5 -> 1e5
    EXPECT_DOUBLE_EQ(p(720.0), 1.0e5);
    EXPECT_DOUBLE_EQ(p(720.0 + 365.0), 5.5e6);  // periodic
    EXPECT_DOUBLE_EQ(p(-355.0), 5.5e6);         // -355 = 365 - 720
    EXPECT_DOUBLE_EQ(p(3 * 720.0 + 90.0), 0.9e5);
    EXPECT_DOUBLE_EQ(p.peak(), 6.0e6);
    EXPECT_DOUBLE_EQ(p.peakAngleDeg(), 370.0);
    EXPECT_EQ(p.samples().size(), 6u);
}

TEST(CylinderPressure, OpenEndWrapsToTheFirstSample) {
    // Uniform 90 deg table ending at 630: 630 -> 720 runs to the 0 deg value.
    const CylinderPressure p(
        {{0.0, 1e5}, {90.0, 2e5}, {180.0, 3e5}, {270.0, 4e5}, {360.0, 9e5}, {450.0, 5e5}, {540.0, 3e5}, {630.0, 2e5}});
    EXPECT_DOUBLE_EQ(p(675.0), 1.5e5);
    EXPECT_DOUBLE_EQ(p(-45.0), 1.5e5);
    EXPECT_DOUBLE_EQ(p(719.999999), 1e5 + (2e5 - 1e5) * (0.000001 / 90.0));
    EXPECT_DOUBLE_EQ(p.peak(), 9e5);
    EXPECT_DOUBLE_EQ(p.peakAngleDeg(), 360.0);
}

TEST(CylinderPressure, RejectsBadTables) {
    auto sampleOf = [](std::vector<PressureSample> s) -> std::size_t {
        try {
            CylinderPressure p(std::move(s));
        } catch (const PressureTableError& e) {
            return e.sample();
        }
        return 12345;
    };
    EXPECT_EQ(sampleOf({{0.0, 1e5}}), PressureTableError::npos);
    EXPECT_EQ(sampleOf({{5.0, 1e5}, {720.0, 1e5}}), 0u);
    EXPECT_EQ(sampleOf({{0.0, 1e5}, {0.0, 2e5}, {720.0, 1e5}}), 1u);
    EXPECT_EQ(sampleOf({{0.0, 1e5}, {360.0, 0.0}, {720.0, 1e5}}), 1u);
    EXPECT_EQ(sampleOf({{0.0, 1e5}, {360.0, std::nan("")}, {720.0, 1e5}}), 1u);
    EXPECT_EQ(sampleOf({{0.0, 1e5}, {360.0, 2e5}, {720.0, 1.1e5}}), 2u);
    EXPECT_EQ(sampleOf({{0.0, 1e5}, {100.0, 2e5}, {200.0, 1.1e5}}), 2u);  // gap 520 > 100
    EXPECT_EQ(sampleOf({{0.0, 1e5}, {360.0, 2e5}, {721.0, 1e5}}), 2u);
    EXPECT_EQ(sampleOf({{0.0, 1e5}, {360.0, 2e5}, {720.0, 1e5}}), 12345u);
}
