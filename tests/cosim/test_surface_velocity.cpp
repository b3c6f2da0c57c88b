// The liner's recorded surface velocity for slap noise (cosim/results/SurfaceVelocityRecorder,
// docs/acoustics.md; case key `acoustics`).
//  - On a sleeve (outer radius 43 mm, 50 mm long) the outer surface's points carry its area
//    2πRH, their normals are radial: a rigid translation along x has the normal velocity n_x,
//    whose mean square over the surface is ∫ cos²θ dA = πRH, and ∫ n dA = 0 round the closed
//    cylinder.
//    The sleeve's three translations are its "modes", each on a spring (400, 600 and 900 Hz,
//    damping ratios 0.3, 0.2, 0.1).
//  - The record is the sleeve's forced response to the run's modal force, linear between the
//    accepted steps, sampled on a fixed grid of the sampling rate: under a force linear in time
//    each mode's velocity is the closed-form ramp response at every sample, whatever the steps;
//    each cycle's grid starts at the cycle's first state; the file holds what the recorder holds.
//  - `flexehd acoustics`' report of a record: the sleeve driven along x by F sin Ωt at the 3rd
//    engine order (on a bin, rectangular window) translates with V = F Ω / |ω² − Ω² + 2iζωΩ|
//    and radiates ½ ρ c V² ∫ cos²θ dA = ½ ρ c V² πRH, all of it in the 1/3-octave band of
//    160 Hz and at order 3; its area-weighted rms normal velocity is V/2.
//  - The case file refuses `acoustics` without a flexible liner, and caps time.max_step_deg at
//    the sampling interval 6 n / f_s degrees.
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/results/LinerVibrationReport.hpp"
#include "cosim/results/SurfaceVelocityRecorder.hpp"
#include "fem/BoundarySurface.hpp"
#include "fem/MeshReader.hpp"
#include "VtkReadBack.hpp"
#include "../TestScratch.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <hdf5.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

using namespace flexehd;
using namespace flexehd::cosim;

namespace {

const std::string kSource = FLEXEHD_SOURCE_DIR;

const Eigen::Vector3d kOmega = 2.0 * std::numbers::pi * Eigen::Vector3d(400.0, 600.0, 900.0);
const Eigen::Vector3d kZeta(0.3, 0.2, 0.1);

// The sleeve with the three translations as its "modes", each on a spring (the normal velocity of
// a translation along x is n_x).
modal::ReducedBody translatingSleeve() {
    fem::MeshOptions order2;
    order2.order = 2;
    order2.size = 0.008;
    modal::ReducedBody b;
    b.mesh = fem::readMesh(kSource + "/tests/cosim/data/sleeve.geo", order2);
    b.meshPath = "sleeve.geo";
    b.shapes = Eigen::MatrixXd::Zero(3 * b.mesh.numNodes(), 3);
    for (fem::Index n = 0; n < b.mesh.numNodes(); ++n)
        for (int k = 0; k < 3; ++k) b.shapes(3 * n + k, k) = 1.0;
    b.massMatrix = Eigen::Matrix3d::Identity();
    b.stiffnessMatrix = kOmega.cwiseAbs2().asDiagonal();
    b.dampingRatios = kZeta;
    b.frequenciesHz = kOmega / (2.0 * std::numbers::pi);
    b.rigidBody.assign(3, 0);
    // Its three modes are all it has: it covers every range (a cut-off above any asked).
    b.settings.cutoffHz = 1e6;
    return b;
}

EngineCase acousticCase(double upToHz) {
    EngineCase c;
    c.engine.speedRpm = 3000.0;
    c.acoustics.enabled = true;
    c.acoustics.surface = "outer";
    c.acoustics.upToHz = upToHz;
    return c;
}

/// x'' + 2ζω x' + ω² x = a t from rest: x'.
double rampVelocity(double w, double zeta, double a, double t) {
    const double wd = w * std::sqrt(1 - zeta * zeta);
    const double c1 = 2 * zeta * a / (w * w * w), c2 = (zeta * w * c1 - a / (w * w)) / wd;
    const double e = std::exp(-zeta * w * t), c = std::cos(wd * t), s = std::sin(wd * t);
    return a / (w * w) + e * (-zeta * w * (c1 * c + c2 * s) + wd * (-c1 * s + c2 * c));
}

std::vector<double> readDoubles(hid_t file, const std::string& name, std::vector<hsize_t>& dims) {
    const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    EXPECT_GE(set, 0) << name;
    const hid_t space = H5Dget_space(set);
    dims.assign(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)), 0);
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    hsize_t n = 1;
    for (hsize_t d : dims) n *= d;
    std::vector<double> v(n);
    H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    H5Sclose(space);
    H5Dclose(set);
    return v;
}

}  // namespace

// A basis of the sleeve's first two modes (as `reduce --modes 2` keeps them) covers 600 Hz, its
// second frequency: a record up to 2000 Hz is refused with the frequency, the file and the
// `reduce --cutoff` that covers it; up to 600 Hz it is taken.
TEST(SurfaceVelocity, ARangeAboveTheLinersNormalModesIsRefused) {
    modal::ReducedBody sleeve = translatingSleeve();
    sleeve.settings.cutoffHz = 0.0;
    sleeve.settings.normalModes = 2;
    EngineCase c = acousticCase(2000.0);
    c.linerBody.file = "/cases/sleeve.h5";
    try {
        SurfaceVelocityRecorder(c, sleeve, {}, 0, "unused.h5");
        ADD_FAILURE() << "a range above the normal modes was accepted";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        for (const char* part : {"acoustics.up_to_hz", "2000 Hz", "/cases/sleeve.h5", "up to 600 Hz", "--modes 2",
                                 "--cutoff 2000", "at most 600 Hz"})
            EXPECT_NE(what.find(part), std::string::npos) << part << " in: " << what;
    }
    EXPECT_NO_THROW(SurfaceVelocityRecorder(acousticCase(600.0), sleeve, {}, 0, "unused.h5"));
}

TEST(SurfaceVelocity, TheSleevesOuterPointsCarryItsAreaAndRadialNormals) {
    const modal::ReducedBody sleeve = translatingSleeve();
    const SurfaceVelocityRecorder r(acousticCase(2000.0), sleeve, {}, 0, "unused.h5");
    const double R = 0.043, H = 0.050, area = 2.0 * std::numbers::pi * R * H;
    const Eigen::VectorXd& A = r.areas();
    const Eigen::MatrixXd& P = r.normalShapes();
    ASSERT_EQ(P.cols(), 3);
    // The flat sub-triangles' chords cut the circle: with 4 mm sub-triangle edges on R = 43 mm
    // their area falls short by about (4/43)²/24 = 0.04 %, and a point's normal turns over its
    // neighbourhood (about 0.1 rad): |Σ a| is 1 − (0.1)²/6 of its area. Within 0.5 %.
    EXPECT_NEAR(A.sum(), area, 5e-3 * area);
    EXPECT_NEAR(A.dot(P.col(0).cwiseAbs2()), 0.5 * area, 5e-3 * area);
    EXPECT_NEAR(A.dot(P.col(1).cwiseAbs2()), 0.5 * area, 5e-3 * area);
    // A flat sub-triangle on the curved surface tilts out of its tangent plane by second order in
    // its size: n_z² of order ((4/43)²)² ≈ 1e-4 at most.
    EXPECT_LT(A.dot(P.col(2).cwiseAbs2()), 1e-4 * area);
    EXPECT_NEAR(A.dot(P.col(0)), 0.0, 1e-9 * area);
    for (Eigen::Index i = 0; i < A.size(); ++i) {
        const Eigen::Vector3d x = r.points().col(i);
        const double radial = (x.x() * r.normals()(0, i) + x.y() * r.normals()(1, i)) / std::hypot(x.x(), x.y());
        ASSERT_GT(radial, 0.99) << "point " << i << " at " << x.transpose(); // outward
    }
    std::printf("sleeve's outer surface: %lld points, %.6g m^2 (2 pi R H = %.6g); sum A n_x^2 = %.6g (pi R H = %.6g)\n",
                static_cast<long long>(A.size()), A.sum(), area, A.dot(P.col(0).cwiseAbs2()), 0.5 * area);
    EXPECT_THROW(
        {
            EngineCase c = acousticCase(2000.0);
            c.acoustics.surface = "jacket";
            SurfaceVelocityRecorder(c, sleeve, {}, 0, "unused.h5");
        },
        std::invalid_argument);
}

TEST(SurfaceVelocity, TheForcedResponseToARampIsSampledExactlyOnTheFixedGrid) {
    const modal::ReducedBody sleeve = translatingSleeve();
    const std::filesystem::path dir = flexehd::test::scratchDir();
    const EngineCase c = acousticCase(1000.0);  // 2560 samples per second
    SurfaceVelocityRecorder r(c, sleeve, {}, 2, (dir / "acoustics.h5").string());
    const double fs = 2560.0, omega = 3000.0 * 6.0;  // deg/s
    const Eigen::Vector3d slope(2.0e5, -3.0e5, 5.0e5);  // N/s per unit modal mass
    auto velocity = [&](double t) {
        Eigen::Vector3d v;
        for (int k = 0; k < 3; ++k) v[k] = rampVelocity(kOmega[k], kZeta[k], slope[k], t);
        return v;
    };
    StepEvaluation evaluation;
    // Irregular steps over 0.05 s (two "cycles" of 0.02 s and 0.03 s), the state's modal force led
    // by two piston modes.
    std::vector<double> times{0.0};
    for (double t = 0.0; t < 0.05;) times.push_back(t += 1e-4 * (1.0 + 2.5 * std::abs(std::sin(97.0 * t))));
    auto feed = [&](double t, int cycle) {
        StepState s;
        s.time = t;
        s.crankDeg = omega * t;
        s.f = Eigen::VectorXd::Zero(5);
        s.f.tail(3) = slope * t;
        r.stepAccepted(AcceptedStep{s, evaluation, cycle, 0.0, 0.0});
    };
    std::size_t k = 0;
    for (; times[k] <= 0.02; ++k) feed(times[k], 1);
    const double cycleStart = times[k - 1];
    r.cycleEnded(CycleEnd{1, 0, false, nullptr});
    for (; k < times.size(); ++k) feed(times[k], 2);
    const std::vector<double>& t = r.sampleTimes();
    const Eigen::MatrixXd v = r.sampleVelocities();
    ASSERT_GT(t.size(), 70u);
    EXPECT_DOUBLE_EQ(t.front(), cycleStart);
    EXPECT_EQ(t.size(), static_cast<std::size_t>(std::floor((times.back() - cycleStart) * fs)) + 1);
    for (std::size_t j = 0; j < t.size(); ++j) {
        EXPECT_NEAR(t[j], cycleStart + static_cast<double>(j) / fs, 1e-12);
        EXPECT_LT((v.row(static_cast<Eigen::Index>(j)).transpose() - velocity(t[j])).norm(), 1e-9 * velocity(t[j]).norm()) << j;
        EXPECT_NEAR(r.sampleAngles()[j], std::fmod(omega * t[j], 720.0), 1e-9);
    }
    // The file of the first cycle: its samples and the surface, with units.
    r.cycleEnded(CycleEnd{2, 2, true, nullptr});
    const hid_t file = H5Fopen((dir / "acoustics.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    std::vector<hsize_t> dims;
    const std::vector<double> fileTimes = readDoubles(file, "/time_s", dims);
    ASSERT_EQ(fileTimes.size(), t.size());
    EXPECT_EQ(fileTimes.back(), t.back());
    const std::vector<double> fileVelocity = readDoubles(file, "/liner/modal_velocity", dims);
    ASSERT_EQ(dims, (std::vector<hsize_t>{t.size(), 3}));
    EXPECT_EQ(fileVelocity[3 * 5 + 1], v(5, 1));  // row-major samples × modes
    readDoubles(file, "/surface/normal_shapes", dims);
    EXPECT_EQ(dims, (std::vector<hsize_t>{static_cast<hsize_t>(r.areas().size()), 3}));
    H5Fclose(file);
    EXPECT_EQ(r.cyclesWritten(), 2);
}

TEST(SurfaceVelocity, TheCaseFileAsksForAFlexibleLinerAndCapsTheStep) {
    const std::filesystem::path dir = flexehd::test::scratchDir();
    std::ifstream in(kSource + "/examples/engine86/ehd_liner.yaml");
    std::stringstream text;
    text << in.rdbuf();
    std::string yaml = text.str();
    for (const std::string csv : {"cylinder_pressure.csv"})
        std::filesystem::copy_file(kSource + "/examples/engine86/" + csv, dir / csv);
    auto read = [&](const std::string& y) {
        std::ofstream(dir / "case.yaml") << y << "acoustics:\n  up_to_hz: 8000\n";
        CaseFileOptions o;
        o.checkBodyFiles = false;
        return readCaseFile((dir / "case.yaml").string(), o);
    };
    // Either response of the liner: the record is its forced response in both.
    EXPECT_TRUE(read(yaml).acoustics.enabled);
    const std::size_t at = yaml.find("response: quasi_static");
    ASSERT_NE(at, std::string::npos);
    yaml.replace(at, std::string("response: quasi_static").size(), "response: dynamic");
    const EngineCase c = read(yaml);
    EXPECT_TRUE(c.acoustics.enabled);
    EXPECT_EQ(c.acoustics.surface, "outer");
    EXPECT_DOUBLE_EQ(c.acoustics.sampleRateHz(), 2.56 * 8000.0);
    EXPECT_DOUBLE_EQ(c.time.maxStepDeg, 6.0 * 1000.0 / (2.56 * 8000.0));  // 0.293 deg < 0.5
    std::string rigid = yaml;
    const std::size_t liner = rigid.find("  liner:");
    ASSERT_NE(liner, std::string::npos);
    rigid = rigid.substr(0, liner) + "  liner: rigid\n" + rigid.substr(rigid.find('\n', rigid.find("interface", liner)) + 1);
    try {
        read(rigid);
        ADD_FAILURE() << "a rigid liner was accepted";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("needs a flexible liner"), std::string::npos) << e.what();
    }
}

TEST(SurfaceVelocity, TheReportOfATranslatingSleeveRadiatesHalfRhoCVSquaredPiRH) {
    const modal::ReducedBody sleeve = translatingSleeve();
    const std::filesystem::path dir = flexehd::test::scratchDir();
    // 3000 rpm: a cycle of 0.04 s; 2.56 × 2500 Hz = 6400 samples per second, 256 per cycle, bins of
    // 25 Hz; the 3rd order (150 Hz) on bin 6.
    // Two cycles: the first lets the start's transient die (ζω = 754/s: e^{-30}); the file holds the
    // second. Steps of 1/16 sampling interval: the linear force's factor sinc²(ΩΔt/2) = 1 − 7e-6.
    SurfaceVelocityRecorder r(acousticCase(2500.0), sleeve, {}, 0, (dir / "acoustics.h5").string());
    const double fs = 6400.0, V = 1e-3, f = 150.0, W = 2.0 * std::numbers::pi * f;
    const double F = V * std::abs(std::complex<double>(kOmega[0] * kOmega[0] - W * W, 2.0 * kZeta[0] * kOmega[0] * W)) / W;
    StepEvaluation evaluation;
    for (int cycle = 1; cycle <= 2; ++cycle) {
        for (int k = (cycle - 1) * 4096 + (cycle == 1 ? 0 : 1); k <= cycle * 4096; ++k) {
            StepState s;
            s.time = k / (16.0 * fs);
            s.crankDeg = 18000.0 * s.time;
            s.f = Eigen::Vector3d(F * std::sin(W * s.time), 0.0, 0.0);
            r.stepAccepted(AcceptedStep{s, evaluation, cycle, 0.0, 0.0});
        }
        r.cycleEnded(CycleEnd{cycle, 0, cycle == 2, nullptr});
    }
    LinerVibrationOptions o;
    o.window = acoustics::WindowKind::Rectangular;
    const nlohmann::json doc = reportLinerVibration(dir.string(), o);
    const double R = 0.043, H = 0.050, rhoC = 1.204 * 343.0;
    const double expected = 0.5 * rhoC * V * V * std::numbers::pi * R * H;
    EXPECT_EQ(doc["record"]["samples"].get<int>(), 256);  // the cycle's last sample repeats its first
    EXPECT_NEAR(doc["erp"]["total_w"].get<double>(), expected, 3e-3 * expected);
    double inBand = 0.0;
    for (const auto& band : doc["erp"]["bands"])
        if (band["lower_hz"].get<double>() <= f && f < band["upper_hz"].get<double>()) inBand = band["erp_w"].get<double>();
    EXPECT_NEAR(inBand, doc["erp"]["total_w"].get<double>(), 1e-9 * expected);
    EXPECT_DOUBLE_EQ(doc["erp"]["orders"][0]["order"].get<double>(), 3.0);
    EXPECT_NEAR(doc["velocity"]["rms_m_per_s"].get<double>(), 0.5 * V, 3e-3 * V);
    // The energy over the cycle in the steady state: the work the force does equals what the
    // damping c = 2ζω takes, c ⟨v²⟩ T = ζ ω V² T, the stored energy back where it started.
    const double T = 0.04, damped = kZeta[0] * kOmega[0] * V * V * T;
    const nlohmann::json& energy = doc["energy"];
    EXPECT_NEAR(energy["work_in_j"].get<double>(), damped, 1e-4 * damped);
    EXPECT_NEAR(energy["damped_j"].get<double>(), damped, 1e-4 * damped);
    EXPECT_NEAR(energy["stored_change_j"].get<double>(), 0.0, 1e-6 * damped);
    EXPECT_NEAR(energy["input_power_mean_w"].get<double>(), damped / T, 1e-4 * damped / T);
    std::printf("translating sleeve: work in %.6g J, damped %.6g J (zeta omega V^2 T = %.6g J)\n",
                energy["work_in_j"].get<double>(), energy["damped_j"].get<double>(), damped);
    std::printf("translating sleeve: ERP %.6g W against 1/2 rho c V^2 pi R H = %.6g W\n",
                doc["erp"]["total_w"].get<double>(), expected);
    // The surface's band velocities for ParaView: in the band of 150 Hz each point's rms is
    // V |n_x| / √2 (to the normal's turn over its neighbourhood), and all of it; four flat
    // triangles per quadratic one.
    const auto surface = flexehd::test::readVtu(dir / "acoustics_surface.vtu");
    ASSERT_EQ(surface->GetNumberOfPoints(), r.areas().size());
    EXPECT_EQ(surface->GetNumberOfCells(), 4 * fem::BoundarySurface(sleeve.mesh, "outer").triangles().size());
    vtkDataArray* band = surface->GetPointData()->GetArray("normal_velocity_rms_m_per_s_158hz");
    vtkDataArray* all = surface->GetPointData()->GetArray("normal_velocity_rms_m_per_s_total");
    ASSERT_NE(band, nullptr);
    ASSERT_NE(all, nullptr);
    EXPECT_STREQ(surface->GetPointData()->GetArrayName(0), "normal_velocity_rms_m_per_s_total");
    for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c) {  // outward, as the points' normals
        vtkIdType count = 0;
        const vtkIdType* ids = nullptr;
        surface->GetCellPoints(c, count, ids);
        ASSERT_EQ(count, 3);
        Eigen::Vector3d x[3];
        for (int k = 0; k < 3; ++k) surface->GetPoint(ids[k], x[k].data());
        const Eigen::Vector3d n = (x[1] - x[0]).cross(x[2] - x[0]);
        ASSERT_GT(n.dot(r.normals().col(ids[0])), 0.0) << "triangle " << c;
    }
    double worst = 0.0;
    for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i) {
        const double expected = V * std::abs(r.normals()(0, i)) / std::sqrt(2.0);
        worst = std::max(worst, std::abs(band->GetTuple1(i) - expected) / V);
        EXPECT_NEAR(all->GetTuple1(i), band->GetTuple1(i), 1e-6 * V) << i;
    }
    EXPECT_LT(worst, 3e-3);
    EXPECT_TRUE(std::filesystem::exists(dir / "acoustics.csv"));
    EXPECT_TRUE(std::filesystem::exists(dir / "acoustics_map.csv"));
    EXPECT_THROW(reportLinerVibration((dir / "nothing").string()), std::runtime_error);
}
