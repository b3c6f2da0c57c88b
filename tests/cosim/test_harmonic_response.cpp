// The liner's recorded surface velocity under a harmonic load, against a full finite-element
// harmonic solve on the same mesh (docs/acoustics.md §8, docs/modal.md "Superposition and
// response").
//
// The example liner (meshes/liner.geo at 0.009 m, held at both seats, reduced as
// scripts/example.sh reduces it: 20 normal modes, static correction on the bore, 17 axial hats)
// under a pressure bump on the bore's thrust side (1 MPa, Gaussian half-widths 15 mm and
// 0.4 rad, 30 mm below the top face: where the skirt slaps after firing TDC), p(t) = p̂ sin Ωt.
// Damping C = βK with β = 2 µs, so that the reduced body's modal damping ζ_k = β ω_k / 2 is the
// projection of the full model's (the reduced basis diagonalises K).
//
//  1. Truncation: the reduced body's harmonic response (K_r − Ω² M_r + iΩ C_r) q̂ = Φᵀ f̂ on the
//     held coordinates against the full model's (K(1 + iΩβ) − Ω² M) û = f̂ (complex sparse LU),
//     as the outer surface's normal velocity iΩ n·û at each node, in the area-weighted norm.
//  2. The record: SurfaceVelocityRecorder's forced response (ModalPropagator) to the modal force
//     given at the steps, from rest over 60 ms, sampled at 12.8 kHz
//     (acoustics.up_to_hz 5000), analysed over its last 30 ms (whole periods, Hann window, the
//     tone on a bin). The force it sees is the load sampled at the steps and linear between them,
//     whose component at Ω is the load's times sinc²(ΩΔt/2) (a triangle kernel); the record must
//     match the reduced harmonic response times that factor — at steps that are not aligned with
//     the sampling grid (0.77 sampling intervals, the run's typical step at the acoustic cap).
//  3. BDF2 (HeldModalDynamics, the run's dynamic response) at steps of one sampling interval:
//     its numerical damping and phase error there are why the record is the propagator's; it
//     must be far off.
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include <Eigen/LU>
#include <Eigen/SparseLU>
#include <gtest/gtest.h>

#include "acoustics/SpectrumAnalyzer.hpp"
#include "cosim/results/SurfaceVelocityRecorder.hpp"
#include "fem/BoundarySurface.hpp"
#include "fem/DofMap.hpp"
#include "fem/ElasticityAssembler.hpp"
#include "fem/MeshReader.hpp"
#include "modal/CraigBamptonReducer.hpp"
#include "modal/HeldModalDynamics.hpp"
#include "modal/ModalSuperposition.hpp"

using namespace flexehd;
using namespace flexehd::cosim;
using Complex = std::complex<double>;

namespace {
const std::string kSource = FLEXEHD_SOURCE_DIR;
constexpr double kPi = std::numbers::pi;
const fem::ElasticMaterial kIron{1.1e11, 0.26, 7200.0};
constexpr double kBeta = 2.0e-6;  // s, C = βK

// The full symmetric matrix of an upper triangle.
Eigen::SparseMatrix<double> symmetric(const fem::SparseMatrix& upper) {
    Eigen::SparseMatrix<double> a = upper.selfadjointView<Eigen::Upper>();
    return a;
}

struct Liner {
    fem::Mesh mesh;
    modal::ReducedBody body;
    Eigen::VectorXd load;  // nodal forces of the bump at p̂ (N)
    std::vector<int> held{0, 1};
};

const Liner& liner() {
    static const Liner l = [] {
        Liner r;
        fem::MeshOptions o;
        o.order = 2;
        o.size = 0.009;
        r.mesh = fem::readMesh(kSource + "/meshes/liner.geo", o);
        Eigen::VectorXd p = Eigen::VectorXd::Zero(r.mesh.numNodes());
        for (auto n : r.mesh.groupNodes("bore")) {
            const double th = std::atan2(r.mesh.nodes(1, n), r.mesh.nodes(0, n));
            p(n) = 1e6 * std::exp(-std::pow((r.mesh.nodes(2, n) + 0.03) / 0.015, 2) - std::pow(th / 0.4, 2));
        }
        r.load = fem::ElasticityAssembler(r.mesh).pressureLoad(fem::BoundarySurface(r.mesh, "bore"), p);
        modal::ReductionSettings s;
        s.normalModes = 20;
        s.staticCorrection = {"bore"};
        s.axialOrder = 4;
        s.circumferentialOrder = 6;
        s.axialHats = 17;
        r.body = modal::CraigBamptonReducer(r.mesh, kIron)
                     .reduce({modal::parseInterface("top_seat:rbe2"), modal::parseInterface("bottom_seat:rbe2")}, s);
        for (int k = 0; k < r.body.numModes(); ++k)
            r.body.dampingRatios(k) = r.body.rigidBody[k] ? 0.0 : 0.5 * kBeta * 2 * kPi * r.body.frequenciesHz(k);
        return r;
    }();
    return l;
}

EngineCase acousticCase() {
    EngineCase c;
    c.engine.speedRpm = 1000.0;
    c.acoustics.enabled = true;
    c.acoustics.surface = "outer";
    c.acoustics.upToHz = 5000.0;
    return c;
}

// The full model's complex displacement amplitude û (3·nodes) at Ω, both seats held.
Eigen::VectorXcd fullHarmonic(const Liner& l, double omega) {
    fem::ElasticityAssembler a(l.mesh);
    const fem::SparseMatrix K = a.stiffness(kIron), M = a.mass(kIron.rho);
    fem::DofMap dofs(l.mesh.numNodes(), 3);
    for (const char* g : {"top_seat", "bottom_seat"}) dofs.constrain(l.mesh.groupNodes(g), fem::kAllComponents);
    dofs.finalize();
    const Eigen::SparseMatrix<Complex> Z = symmetric(dofs.reduce(K)).cast<Complex>() * Complex(1.0, omega * kBeta) -
                                           symmetric(dofs.reduce(M)).cast<Complex>() * (omega * omega);
    Eigen::SparseLU<Eigen::SparseMatrix<Complex>> lu(Z);
    EXPECT_EQ(lu.info(), Eigen::Success);
    const Eigen::VectorXcd u = lu.solve(dofs.reduceLoad(l.load, K).cast<Complex>());
    return dofs.expand(u.real()).cast<Complex>() + Complex(0.0, 1.0) * dofs.expand(u.imag()).cast<Complex>();
}

// The reduced body's modal amplitude q̂ at Ω on the held coordinates.
Eigen::VectorXcd reducedHarmonic(const Liner& l, double omega) {
    const Eigen::MatrixXd N = modal::heldBasis(l.body, l.held);
    const Eigen::Index m = l.body.numModes();
    Eigen::VectorXd c(m);
    for (Eigen::Index k = 0; k < m; ++k)
        c(k) = 2 * l.body.dampingRatios(k) * std::sqrt(std::max(l.body.stiffnessMatrix(k, k), 0.0));
    const Eigen::MatrixXcd Z = (N.transpose() * l.body.stiffnessMatrix * N).cast<Complex>() +
                               Complex(0.0, omega) * (N.transpose() * c.asDiagonal() * N).cast<Complex>() -
                               (omega * omega) * (N.transpose() * l.body.massMatrix * N).cast<Complex>();
    const Eigen::VectorXd f = modal::ModalSuperposition(l.body).modalForce(l.load);
    return N.cast<Complex>() * Z.partialPivLu().solve((N.transpose() * f).cast<Complex>());
}

double areaNorm(const Eigen::VectorXd& area, const Eigen::VectorXcd& v) {
    return std::sqrt((v.cwiseAbs2().array() * area.array()).sum());
}

// The complex amplitude at Ω of the normal velocities (samples × points) over their last
// `analysed` seconds (whole periods, Hann window, the tone on a bin), referred to t = 0 (a sine of
// amplitude V reads −iV).
Eigen::VectorXcd amplitudeAt(const Eigen::MatrixXd& v, const std::vector<double>& times, double fs, double omega,
                             double analysed) {
    const int per = int(std::lround(fs * 2 * kPi / omega));
    const int n = per * int(std::lround(analysed * fs / per));
    acoustics::SpectrumAnalyzer analyzer(n, fs, acoustics::WindowKind::Hann);
    const acoustics::VelocitySpectrum spectrum = analyzer.analyze(v.bottomRows(n));
    const auto bin = Eigen::Index(std::lround(omega / (2 * kPi) * n / fs));
    const double t0 = times[times.size() - std::size_t(n)];
    return spectrum.complexAmplitude().row(bin).transpose() * std::exp(Complex(0.0, -omega * t0));
}

// The recorder's record of the liner under the modal force f̂ sin Ωt, given at steps of dt from
// rest over `duration`: its amplitude at Ω over the last `analysed` seconds.
Eigen::VectorXcd recordedAmplitude(SurfaceVelocityRecorder& recorder, const Eigen::VectorXd& fHat, double omega,
                                   double dt, double duration, double analysed) {
    StepEvaluation ev;
    const int steps = int(std::ceil(duration / dt));
    for (int k = 0; k <= steps; ++k) {
        StepState s;
        s.time = k * dt;
        s.crankDeg = 6000.0 * s.time;
        s.f = fHat * std::sin(omega * s.time);
        recorder.stepAccepted(AcceptedStep{s, ev, 1, 0.0, dt});
    }
    return amplitudeAt(recorder.sampleVelocities() * recorder.normalShapes().transpose(), recorder.sampleTimes(),
                       recorder.sampleRate(), omega, analysed);
}

// BDF2 (the run's `bodies.response: dynamic` integrator) from rest at steps of one sampling
// interval under the same force, its velocities taken at the steps: the amplitude at Ω.
Eigen::VectorXcd bdf2Amplitude(const Liner& l, const Eigen::MatrixXd& normalShapes, const Eigen::VectorXd& fHat,
                               double omega, double fs, double duration, double analysed) {
    modal::HeldModalDynamics bdf2(l.body, l.held);
    const Eigen::Index m = fHat.size();
    const double dt = 1.0 / fs;
    const int steps = int(std::ceil(duration / dt));
    Eigen::VectorXd y = Eigen::VectorXd::Zero(m), w = y, yOld = y, wOld = y, yNew;
    Eigen::MatrixXd v(steps + 1, m);
    std::vector<double> times;
    v.row(0).setZero();
    times.push_back(0.0);
    for (int k = 1; k <= steps; ++k) {
        modal::ModalStepStart start;
        start.dt = dt;
        if (k > 1) start.a0 = 1.5, start.a1 = -2.0, start.a2 = 0.5;
        start.y = y, start.yBefore = yOld, start.w = w, start.wBefore = wOld;
        bdf2.beginStep(start);
        const Eigen::VectorXd f = fHat * std::sin(omega * k * dt);
        bdf2.respond(f, yNew);
        yOld = y, wOld = w;
        w = bdf2.velocity(yNew, f);
        y = yNew;
        v.row(k) = w.transpose();
        times.push_back(k * dt);
    }
    return amplitudeAt(v * normalShapes.transpose(), times, fs, omega, analysed);
}
}  // namespace

TEST(HarmonicResponse, TheLinersRecordedSurfaceVelocityMatchesTheFullModel) {
    const Liner& l = liner();
    const EngineCase c = acousticCase();
    const SurfaceVelocityRecorder shapes(c, l.body, l.held, 0, "unused.h5");
    const Eigen::VectorXd& area = shapes.areas();
    const auto outer = l.mesh.groupNodes("outer");
    const Eigen::VectorXd fHat = modal::ModalSuperposition(l.body).modalForce(l.load);
    const double fs = shapes.sampleRate(), dt = 0.77 / fs;
    for (const double hz : {1600.0, 3200.0}) {
        const double omega = 2 * kPi * hz;
        // 1. Truncation of the reduced body.
        const Eigen::VectorXcd u = fullHarmonic(l, omega);
        const Eigen::VectorXcd reduced = Complex(0.0, omega) * (shapes.normalShapes().cast<Complex>() * reducedHarmonic(l, omega));
        Eigen::VectorXcd full(area.size());
        for (Eigen::Index i = 0; i < area.size(); ++i)
            full(i) = Complex(0.0, omega) * shapes.normals().col(i).cast<Complex>().dot(u.segment<3>(3 * outer[std::size_t(i)]));
        const double truncation = areaNorm(area, reduced - full) / areaNorm(area, full);
        // 2. The record of the run's integrator; 3. BDF2's.
        const double x = 0.5 * omega * dt, kernel = std::pow(std::sin(x) / x, 2);
        const Eigen::VectorXcd expected = Complex(0.0, -1.0) * kernel * reduced;
        SurfaceVelocityRecorder record(c, l.body, l.held, 0, "unused.h5");
        const Eigen::VectorXcd recorded = recordedAmplitude(record, fHat, omega, dt, 0.06, 0.03);
        const Eigen::VectorXcd bdf2Recorded = bdf2Amplitude(l, shapes.normalShapes(), fHat, omega, fs, 0.06, 0.03);
        const double recordError = areaNorm(area, recorded - expected) / areaNorm(area, expected);
        const Eigen::VectorXcd truth = Complex(0.0, -1.0) * reduced;
        const double bdf2Error = areaNorm(area, bdf2Recorded - truth) / areaNorm(area, truth);
        std::printf("%.0f Hz: rms normal velocity %.4g m/s (full model); reduced body off by %.2f %%; record at "
                    "steps of %.3g us off by %.3f %% (force kernel %.4f), BDF2's at %.3g us by %.1f %%\n",
                    hz, areaNorm(area, full) / std::sqrt(2.0 * area.sum()), 100 * truncation, dt * 1e6,
                    100 * recordError, kernel, 1e6 / fs, 100 * bdf2Error);
        // The reduced basis spans the bump up to the load patterns' resolution (measured 0.9 % and
        // 0.6 %; the same with 60 normal modes: the first held mode is at 4.4 kHz).
        EXPECT_LT(truncation, 0.015) << hz << " Hz";
        EXPECT_LT(recordError, 2e-3) << hz << " Hz";
        EXPECT_GT(bdf2Error, 10 * recordError) << hz << " Hz";
    }
}
