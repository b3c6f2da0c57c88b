// Natural frequencies against closed-form beam and ring theory (Euler–Bernoulli; thin ring in-plane bending, Blevins, Formulas for Natural Frequency and Mode Shape).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "TestData.hpp"
#include <Eigen/Eigenvalues>

#include "fem/ElasticityAssembler.hpp"
#include "fem/MeshReader.hpp"
#include "fem/ModalAnalysis.hpp"

using namespace flexehd::fem;
using flexehd::test::dataPath;

namespace {
const ElasticMaterial kSteel{2.1e11, 0.3, 7850.0};
constexpr double kPi = std::numbers::pi;

// Euler–Bernoulli: f = (βL)² / (2π L²) √(EI / ρA); square section h: EI/ρA = E h² / (12 ρ).
double beamFrequency(double betaL, double L, double h) {
    return betaL * betaL / (2 * kPi * L * L) * std::sqrt(kSteel.E * h * h / (12 * kSteel.rho));
}

const Mesh& beamMesh() {
    static const Mesh m = readMesh(dataPath("beam.geo"), {2, 0.01});
    return m;
}
}  // namespace

TEST(BeamModes, CantileverFirstThreeBendingPairsWithinOnePointFivePercent) {
    EigenmodeOptions opt;
    opt.count = 6;
    const ModalAnalysis r = analyseModes(beamMesh(), kSteel, {{"clamped", kAllComponents}}, opt);
    const Eigen::VectorXd f = r.modes.frequenciesHz();
    const double betaL[3] = {1.875104, 4.694091, 7.854757};
    for (int k = 0; k < 6; ++k)  // square section: each bending mode twice (y and z)
        EXPECT_NEAR(f(k) / beamFrequency(betaL[k / 2], 1.0, 0.02), 1.0, 0.015) << "mode " << k + 1;
    EXPECT_EQ(r.rigidBodyModes(), 0);
}

TEST(BeamModes, FreeFreeRigidBodyModesAndBendingPairs) {
    EigenmodeOptions opt;
    opt.count = 12;
    const ModalAnalysis r = analyseModes(beamMesh(), kSteel, {}, opt);
    const Eigen::VectorXd f = r.modes.frequenciesHz();
    ASSERT_EQ(r.rigidBodyModes(), 6);
    const double firstElastic = r.modes.eigenvalues(6);
    for (int k = 0; k < 6; ++k) EXPECT_LT(std::abs(r.modes.eigenvalues(k)), 1e-4 * firstElastic);
    // Reported: the rigid-body modes as exactly 0 Hz, the elastic ones as computed.
    const Eigen::VectorXd reported = r.frequenciesHz();
    for (int k = 0; k < 6; ++k) EXPECT_EQ(reported(k), 0.0) << "mode " << k + 1;
    for (int k = 6; k < 12; ++k) EXPECT_EQ(reported(k), f(k)) << "mode " << k + 1;
    const double betaL[3] = {4.730041, 7.853205, 10.995608};
    for (int k = 6; k < 12; ++k)
        EXPECT_NEAR(f(k) / beamFrequency(betaL[(k - 6) / 2], 1.0, 0.02), 1.0, 0.015) << "mode " << k + 1;
}

// Thin free ring, in-plane bending: f_n = n(n²-1) / (2π √(n²+1)) √(EI / (ρ A R⁴)).
// The out-of-plane (bending-torsion) pairs interleave with these, so in-plane modes are
// picked by shape: axial (z) displacement small against the in-plane one.
TEST(RingModes, InPlaneBendingPairsN2AndN3) {
    const Mesh m = readMesh(dataPath("ring.geo"), {2, 0.004});
    EigenmodeOptions opt;
    opt.count = 12;
    const ModalAnalysis r = analyseModes(m, kSteel, {}, opt);
    ASSERT_EQ(r.rigidBodyModes(), 6);
    const double R = 0.1, t = 0.003;
    const double base = std::sqrt(kSteel.E * t * t / (12 * kSteel.rho)) / (R * R);
    const Eigen::VectorXd f = r.modes.frequenciesHz();
    std::vector<double> inPlane;
    int outOfPlane = 0;
    for (int k = 6; k < 12; ++k) {
        const auto shape = r.modes.shapes.col(k).reshaped(3, m.numNodes());
        const double zFraction = shape.row(2).norm() / shape.norm();
        if (zFraction < 0.05) inPlane.push_back(f(k));
        else if (zFraction > 0.5) ++outOfPlane;  // clearly out-of-plane, nothing in between
    }
    ASSERT_EQ(inPlane.size(), 4u);
    EXPECT_EQ(outOfPlane, 2);
    for (int k = 0; k < 4; ++k) {
        const int n = k < 2 ? 2 : 3;
        const double exact = n * (n * n - 1) / (2 * kPi * std::sqrt(n * n + 1.0)) * base;
        EXPECT_NEAR(inPlane[k] / exact, 1.0, 0.01) << "in-plane mode n = " << n;
    }
}

// Shift-invert Lanczos on CHOLMOD against a dense generalized eigensolver (LAPACK-style
// tridiagonalisation in Eigen) on a small free body, and M-orthonormal shapes.
TEST(EigenmodeSolver, AgreesWithDenseSolverOnSmallFreeBody) {
    const Mesh m = readMesh(dataPath("cube.geo"), {1, 0.5});  // ~1000 DOFs: dense is cheap
    EigenmodeOptions opt;
    opt.count = 15;
    const ModalAnalysis r = analyseModes(m, kSteel, {}, opt);
    ElasticityAssembler asm_(m);
    const Eigen::MatrixXd K = Eigen::MatrixXd(SparseMatrix(asm_.stiffness(kSteel).selfadjointView<Eigen::Upper>()));
    const Eigen::MatrixXd M = Eigen::MatrixXd(SparseMatrix(asm_.mass(kSteel.rho).selfadjointView<Eigen::Upper>()));
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(K, M);
    const double scale = dense.eigenvalues()(14);
    for (int k = 0; k < 15; ++k)
        EXPECT_NEAR(r.modes.eigenvalues(k), dense.eigenvalues()(k), 1e-8 * scale) << "mode " << k + 1;
    const Eigen::MatrixXd& P = r.modes.shapes;
    EXPECT_LT((P.transpose() * M * P - Eigen::MatrixXd::Identity(15, 15)).norm(), 1e-8);
    EXPECT_LT((P.transpose() * K * P - Eigen::MatrixXd(r.modes.eigenvalues.asDiagonal())).norm(), 1e-6 * scale);
}

// Progress of a long solve: with a reporting interval of 0 every application of (K − σM)⁻¹ is
// reported, counted from 1, with non-decreasing times, as many as the solve reports it made.
TEST(EigenmodeSolver, ReportsProgressOfTheIteration) {
    const Mesh m = readMesh(dataPath("cube.geo"), {1, 0.5});
    EigenmodeOptions opt;
    opt.count = 15;
    opt.progressSeconds = 0.0;
    std::vector<int> solves;
    std::vector<double> times;
    opt.progress = [&](int n, double s) {
        solves.push_back(n);
        times.push_back(s);
    };
    const ModalAnalysis r = analyseModes(m, kSteel, {}, opt);
    ASSERT_FALSE(solves.empty());
    EXPECT_EQ(int(solves.size()), r.modes.operations);
    for (std::size_t i = 0; i < solves.size(); ++i) EXPECT_EQ(solves[i], int(i) + 1);
    EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
    EXPECT_EQ(lanczosBasisSize(1000, 15), 31);
    EXPECT_EQ(lanczosBasisSize(1000, 3), 20);
    EXPECT_EQ(lanczosBasisSize(25, 15), 25);
}
