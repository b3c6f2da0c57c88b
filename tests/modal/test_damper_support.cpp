// Craig–Bampton reduction of a body on viscous (dashpot) supports (ReductionSettings::dampers):
// the reduction stays undamped and the dashpots C_s = C ∫ N_a N_b dA ⊗ I₃ are projected on its
// basis, D_s = Φᵀ C_s Φ, which couples the modes (non-proportional damping; Craig & Kurdila,
// *Fundamentals of Structural Dynamics*, 2006). Checked on tests/fem/data/bar.geo (L = 0.1 m
// along x, a × a = 0.02 × 0.02 m): against the full FE model's quadratic eigenproblem
// (K + K_s + λ C_s + λ² M) x = 0, against the closed form of a stiff bar's rigid motions on side
// springs and dashpots, and for the energy the dashpots take over a ringing decay.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseLU>
#include <gtest/gtest.h>

#include "../TestScratch.hpp"
#include "../fem/TestData.hpp"
#include "Bdf2Integration.hpp"
#include "fem/BoundarySurface.hpp"
#include "fem/DofMap.hpp"
#include "fem/ElasticityAssembler.hpp"
#include "fem/MeshReader.hpp"
#include "fem/SurfaceSpring.hpp"
#include "modal/CraigBamptonReducer.hpp"
#include "modal/DampedEnergyQuadrature.hpp"
#include "modal/HeldModalDynamics.hpp"
#include "modal/ModalDamping.hpp"
#include "modal/ModalPropagator.hpp"
#include "modal/ModalSuperposition.hpp"
#include "modal/ReducedBodyFile.hpp"

using namespace flexehd;
using Complex = std::complex<double>;

namespace {
constexpr double kL = 0.1, kA = 0.02;
const fem::ElasticMaterial kSteel{2.1e11, 0.3, 7850.0};

const fem::Mesh& bar() {
    static const fem::Mesh m = fem::readMesh(test::dataPath("bar.geo"), {2, 0.01});
    return m;
}

modal::ReductionSettings settings(int modes, std::vector<std::string> supports, std::vector<std::string> dampers) {
    modal::ReductionSettings s;
    s.normalModes = modes;
    s.supports = std::move(supports);
    s.dampers = std::move(dampers);
    return s;
}

// A damped mode of the held body: its eigenvalue and its shape u = Φ q on the mesh.
struct DampedMode {
    Complex lambda;
    Eigen::VectorXcd shape;
};

// The body's damped modes in the upper half plane, by frequency: the eigenvalues of ModalPropagator
// (its held first-order system), the shapes from the held quadratic eigenproblem on the held
// basis N, [[0, I], [−Mₙ⁻¹Kₙ, −Mₙ⁻¹Cₙ]] with Cₙ = Nᵀ (diag(c) + D_s) N.
std::vector<DampedMode> dampedModes(const modal::ReducedBody& body, const std::vector<int>& held) {
    const modal::ModalPropagator propagator(body, held);
    const Eigen::VectorXcd& l = propagator.eigenvalues();
    const Eigen::MatrixXd N = modal::heldBasis(body, held);
    const Eigen::Index n = N.cols();
    const Eigen::MatrixXd Mn = N.transpose() * body.massMatrix * N, Kn = N.transpose() * body.stiffnessMatrix * N,
                          Cn = N.transpose() * modal::bodyDampingMatrix(body) * N;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    A.topRightCorner(n, n).setIdentity();
    A.bottomLeftCorner(n, n) = -Mn.ldlt().solve(Kn);
    A.bottomRightCorner(n, n) = -Mn.ldlt().solve(Cn);
    const Eigen::EigenSolver<Eigen::MatrixXd> eig(A);
    std::vector<DampedMode> up;
    for (Eigen::Index j = 0; j < l.size(); ++j) {
        if (l(j).imag() <= 0.0) continue;
        Eigen::Index nearest = 0;
        (eig.eigenvalues().array() - l(j)).abs().minCoeff(&nearest);
        const Eigen::VectorXcd q = N.cast<Complex>() * eig.eigenvectors().col(nearest).head(n);
        up.push_back({l(j), body.shapes.cast<Complex>() * q});
    }
    std::sort(up.begin(), up.end(), [](const DampedMode& a, const DampedMode& b) { return a.lambda.imag() < b.lambda.imag(); });
    return up;
}

double ratio(Complex l) { return -l.real() / std::abs(l); }

// Full model, end0 clamped: K + K_s, C_s, M on the free DOFs (full symmetric storage).
struct FullModel {
    Eigen::SparseMatrix<Complex> K, C, M;
    FullModel(double k, double c) {
        const fem::Mesh& m = bar();
        fem::DofMap dofs(m.numNodes(), 3);
        dofs.constrain(m.groupNodes("end0"), fem::kAllComponents);
        dofs.finalize();
        fem::ElasticityAssembler a(m);
        const fem::BoundarySurface end1(m, "end1");
        const auto full = [&](const fem::SparseMatrix& upper) {
            return Eigen::SparseMatrix<Complex>(
                fem::SparseMatrix(dofs.reduce(upper).selfadjointView<Eigen::Upper>()).cast<Complex>());
        };
        K = full(a.stiffness(kSteel) + fem::surfaceSpringMatrix(end1, k));
        C = full(fem::surfaceDashpotMatrix(end1, c));
        M = full(a.mass(kSteel.rho));
        T = dofs.transformation().cast<Complex>();
    }
    Eigen::SparseMatrix<Complex> T;  // free DOFs -> all (u = T u_free; a selection here)

    // The eigenvalue of T(λ) = K + λ C + λ² M near `start` (a reduced mode: its eigenvalue and its
    // shape on all DOFs, which starts the iteration on the right one of a close pair): nonlinear inverse iteration
    // x ← T(λ)⁻¹ T'(λ) x with λ the root, nearest the last, of the complex-symmetric Rayleigh
    // functional xᵀ T(λ) x = 0 (Ruhe 1973, SIAM J. Numer. Anal. 10, "Algorithms for the nonlinear
    // eigenvalue problem"). Returns λ; `residual` = ‖T(λ) x‖ / (‖K x‖).
    Complex eigenvalueNear(const DampedMode& start, double& residual) const {
        Complex l = start.lambda;
        Eigen::VectorXcd x = T.transpose() * start.shape;
        for (int it = 0; it < 6; ++it) {
            const Eigen::SparseMatrix<Complex> T = K + l * C + l * l * M;
            Eigen::SparseLU<Eigen::SparseMatrix<Complex>> lu(T);
            x = lu.solve(Eigen::VectorXcd(C * x + 2.0 * l * (M * x)));
            x /= x.norm();
            const Complex a = x.transpose() * (M * x), b = x.transpose() * (C * x), c = x.transpose() * (K * x);
            const Complex d = std::sqrt(b * b - 4.0 * a * c);
            const Complex r1 = (-b + d) / (2.0 * a), r2 = (-b - d) / (2.0 * a);
            l = std::abs(r1 - l) < std::abs(r2 - l) ? r1 : r2;
        }
        residual = Eigen::VectorXcd((K + l * C + l * l * M) * x).norm() / Eigen::VectorXcd(K * x).norm();
        return l;
    }
};
}  // namespace

// End0 held, springs K = 2e10 N/m³ and dashpots C = 3e5 N·s/m³ on end1: the reduced body's lowest
// damped modes (ModalPropagator, the held first-order system) are the full model's to the
// reduction's truncation error, which falls as modes are added (the dashpots change the mode
// shapes; the undamped held frequencies alone are exact, test_spring_support.cpp). The damping
// comes only from the dashpots (modal damping ratio 0), so the check is on D_s alone.
TEST(DamperSupport, HeldDampedModesAreTheFullModelsQuadraticEigenvalues) {
    const double k = 2e10, c = 3e5;
    const FullModel full(k, c);
    modal::CraigBamptonReducer reducer(bar(), kSteel);
    std::vector<Complex> ref;
    double worst[2][2] = {};  // [12 or 24 modes][eigenvalue, damping ratio]
    for (int pass = 0; pass < 2; ++pass) {
        const int count = pass == 0 ? 12 : 24;
        const auto body = reducer.reduce({modal::parseInterface("end0:rbe2")}, settings(count, {"end1:2e10"}, {"end1:3e5"}));
        ASSERT_EQ(body.supportDamping.rows(), body.numModes());
        EXPECT_LT((body.supportDamping - body.supportDamping.transpose()).cwiseAbs().maxCoeff(), 1e-12);
        const std::vector<DampedMode> modes = dampedModes(body, {0});
        for (int i = 0; i < 4; ++i) {
            if (pass == 0) {  // the full model's eigenvalues, each from the 12-mode body's mode
                double residual = 0.0;
                ref.push_back(full.eigenvalueNear(modes[std::size_t(i)], residual));
                ASSERT_LT(residual, 1e-10) << i;
                EXPECT_GT(ratio(ref.back()), 0.005);  // the dashpots damp every mode compared
            }
            const Complex red = modes[std::size_t(i)].lambda, r = ref[std::size_t(i)];
            const double errValue = std::abs(red / r - 1.0), errRatio = std::abs(ratio(red) / ratio(r) - 1.0);
            worst[pass][0] = std::max(worst[pass][0], errValue);
            worst[pass][1] = std::max(worst[pass][1], errRatio);
            std::printf("%d modes, damped mode %d: full %.7g Hz, zeta %.6g; reduced %.7g Hz, zeta %.6g (|dl/l| %.3g, "
                        "dzeta/zeta %.3g)\n",
                        count, i + 1, std::abs(r) / (2 * std::numbers::pi), ratio(r),
                        std::abs(red) / (2 * std::numbers::pi), ratio(red), errValue, errRatio);
        }
    }
    EXPECT_LT(worst[0][0], 5e-5);  // measured 1.7e-5
    EXPECT_LT(worst[0][1], 2e-4);  // measured 6.6e-5
    EXPECT_LT(worst[1][0], 0.7 * worst[0][0]);  // measured 9.3e-6
    EXPECT_LT(worst[1][1], 0.7 * worst[0][1]);  // measured 3.8e-5
}

// Reference node free, springs K and dashpots C on the four sides, E = 1e13 Pa so that the bar
// is rigid next to them: its translation on the foundation (mass m = ρ a² L, side area
// A_s = 4 a L) is a one-degree-of-freedom oscillator with ω² = K A_s / m and damping ratio
//   ζ = C A_s / (2 √(K A_s m)) = C ω / (2 K),
// and, as the dashpots are distributed as the springs, every rigid motion on the foundation has
// ζ = C ω / (2 K) with its own ω (rocking, twist).
TEST(DamperSupport, StiffBarOnSideSpringsAndDashpotsHasTheOscillatorsDampingRatio) {
    const fem::ElasticMaterial stiff{1e13, 0.3, 7850.0};
    const double k = 1.55e7, c = 5e3;  // translations at about 100 Hz, ζ ≈ 0.1
    const auto body = modal::CraigBamptonReducer(bar(), stiff)
                          .reduce({modal::parseInterface("end0:rbe2")}, settings(6, {"sides:1.55e7"}, {"sides:5e3"}));
    std::vector<Complex> modes;
    for (const auto& d : dampedModes(body, {})) modes.push_back(d.lambda);
    const double m = stiff.rho * kA * kA * kL, As = 4 * kA * kL;
    const double zeta = c * As / (2 * std::sqrt(k * As * m)), omega = std::sqrt(k * As / m);
    double worstTranslation = 0.0, worstAll = 0.0;
    for (int i = 0; i < 6; ++i) {
        const Complex l = modes[std::size_t(i)];
        const double expected = c * std::abs(l) / (2 * k);
        worstAll = std::max(worstAll, std::abs(ratio(l) / expected - 1.0));
        if (i < 3) {
            worstTranslation = std::max(worstTranslation, std::abs(ratio(l) / zeta - 1.0));
            EXPECT_NEAR(std::abs(l) / omega, 1.0, 1e-6);  // undamped ω = |λ|
        }
    }
    std::printf("stiff bar on side springs and dashpots: zeta %.6g (closed form %.6g), worst error translations "
                "%.3g, all six rigid motions %.3g\n",
                ratio(modes[0]), zeta, worstTranslation, worstAll);
    EXPECT_NEAR(zeta, 0.1, 0.01);
    EXPECT_LT(worstTranslation, 1e-6);
    EXPECT_LT(worstAll, 1e-6);
}

// Released from the static deflection under a tip load, the held bar rings down on its end1
// dashpots: over every step the stored energy lost equals the energy the dashpots take,
// ∫ q̇ᵀ (diag(c) + D_s) q̇ dt (DampedEnergyQuadrature), to the quadrature's estimate.
TEST(DamperSupport, EnergyTheDashpotsTakeIsTheStoredEnergyLost) {
    auto s = settings(12, {"end1:2e10"}, {"end1:3e5"});
    s.dampingRatio = 0.01;  // modal damping as well: the full matrix diag(c) + D_s
    const auto body = modal::CraigBamptonReducer(bar(), kSteel).reduce({modal::parseInterface("end0:rbe2")}, s);
    const modal::ModalPropagator propagator(body, {0});
    ASSERT_TRUE(propagator.coupledDamping());
    EXPECT_EQ(propagator.dampingMatrix(), modal::bodyDampingMatrix(body));
    modal::ModalSuperposition sup(body);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * bar().numNodes());
    for (auto n : bar().groupNodes("end1")) f(3 * n + 1) = 10.0;  // sideways tip load, N per node
    Eigen::VectorXd y = sup.quasiStatic(sup.modalForce(f), {0}), w = Eigen::VectorXd::Zero(body.numModes());
    const auto energy = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
        return 0.5 * v.dot(body.massMatrix * v) + 0.5 * q.dot(body.stiffnessMatrix * q);
    };
    const double e0 = energy(y, w), dt = 2e-5;
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(body.numModes());
    const modal::DampedEnergyQuadrature quadrature(12);
    double lost = 0.0, taken = 0.0, bound = 0.0, worst = 0.0;
    for (int n = 0; n < 100; ++n) {  // 2 ms, about four periods of the first bending pair
        Eigen::MatrixXd q, v;
        propagator.responseWithin(y, w, zero, zero, dt, {dt}, q, v);
        const modal::DampedEnergy d = quadrature.overStep(propagator, y, w, zero, zero, dt);
        const double drop = energy(y, w) - energy(q.col(0), v.col(0));
        worst = std::max(worst, std::abs(drop - d.energy) - d.error);
        lost += drop;
        taken += d.energy;
        bound += d.error;
        y = q.col(0);
        w = v.col(0);
    }
    std::printf("ring-down on dashpots: stored energy %.6g J, lost %.6g J, taken by the damping %.6g J (difference "
                "%.3g J, quadrature estimate %.3g J; worst step beyond its estimate %.3g J)\n",
                e0, lost, taken, lost - taken, bound, worst);
    EXPECT_GT(lost, 0.5 * e0);  // most of the energy is gone
    EXPECT_LT(worst, 1e-12 * e0);  // every step within its estimate and round-off (measured 8.6e-17 J, 2e-14 E0)
    EXPECT_LT(std::abs(lost - taken), bound + 1e-12 * e0);  // measured 7.5e-17 J of 4.2e-3 J
}

// The run's dynamic response (HeldModalDynamics, BDF2) carries the dashpots too: end0 held, springs
// and dashpots on end1, no modal damping, a sideways tip load F (1 − cos Ωt)/2 from rest at
// Ω/2π = 1 kHz over 2 ms. Against the exact response (ModalPropagator at steps 20× finer than the
// finest BDF2 ones, its linear force then exact to about 1e-7), BDF2's error falls as Δt² (ratio 4
// per halving; measured 5.4e-3, 1.4e-3, 3.4e-4 of max |q| at 200, 400, 800 steps); BDF2 on the same
// body without D_s stays off by the dashpots' effect (9.0e-2).
TEST(DamperSupport, TheRunsBdf2ResponseConvergesToTheExactOneWithTheDashpots) {
    const auto body =
        modal::CraigBamptonReducer(bar(), kSteel).reduce({modal::parseInterface("end0:rbe2")}, settings(12, {"end1:2e10"}, {"end1:3e5"}));
    ASSERT_GT(body.supportDamping.size(), 0);
    modal::ModalSuperposition sup(body);
    Eigen::VectorXd tip = Eigen::VectorXd::Zero(3 * bar().numNodes());
    for (auto n : bar().groupNodes("end1")) tip(3 * n + 1) = 10.0;  // N per node
    const Eigen::VectorXd g = sup.modalForce(tip);
    const double T = 2e-3, W = 2.0 * std::numbers::pi * 1000.0;
    const auto force = [&](double t) { return Eigen::VectorXd(g * 0.5 * (1.0 - std::cos(W * t))); };
    const int fine = 16000;  // exact reference
    const modal::ModalPropagator propagator(body, {0});
    std::vector<Eigen::VectorXd> exact{Eigen::VectorXd::Zero(body.numModes())};
    Eigen::VectorXd w = exact.back();
    for (int k = 0; k < fine; ++k) {
        const double h = T / fine;
        Eigen::MatrixXd q, v;
        propagator.responseWithin(exact.back(), w, force(k * h), force((k + 1) * h), h, {h}, q, v);
        exact.push_back(q.col(0));
        w = v.col(0);
    }
    double scale = 0.0;
    for (const auto& q : exact) scale = std::max(scale, q.norm());
    const auto error = [&](const modal::ReducedBody& b, int n) {
        modal::HeldModalDynamics dyn(b, {0});
        const auto q = test::integrateBdf2(dyn, std::vector<double>(std::size_t(n), T / n), force);
        double e = 0.0;
        for (int k = 0; k < n; ++k) e = std::max(e, (q[std::size_t(k)] - exact[std::size_t((k + 1) * (fine / n))]).norm());
        return e / scale;
    };
    std::vector<double> errors;
    for (int n : {200, 400, 800}) errors.push_back(error(body, n));
    auto undamped = body;
    undamped.supportDamping.resize(0, 0);
    const double withoutDashpots = error(undamped, 800);
    std::printf("BDF2 against the exact response with dashpots: max error / max |q| = %.3g, %.3g, %.3g at 200, 400, "
                "800 steps; without D_s %.3g\n",
                errors[0], errors[1], errors[2], withoutDashpots);
    for (std::size_t k = 1; k < errors.size(); ++k) {
        EXPECT_GT(errors[k - 1] / errors[k], 3.5) << "refinement " << k;
        EXPECT_LT(errors[k - 1] / errors[k], 4.5) << "refinement " << k;
    }
    EXPECT_LT(errors.back(), 0.01);
    EXPECT_GT(withoutDashpots, 10.0 * errors.back());
}

// Without dampers nothing changes: no matrix, the diagonal modal damping. With them the file
// keeps D_s bitwise, and bodies without it read as none.
TEST(DamperSupport, MatrixIsStoredWithTheBodyAndAbsentWithoutDampers) {
    modal::CraigBamptonReducer reducer(bar(), kSteel);
    const auto itf = std::vector{modal::parseInterface("end0:rbe2")};
    auto plainSettings = settings(4, {"end1:2e10"}, {});
    plainSettings.dampingRatio = 0.02;
    const auto plain = reducer.reduce(itf, plainSettings);
    EXPECT_EQ(plain.supportDamping.size(), 0);
    EXPECT_FALSE(modal::ModalPropagator(plain, {0}).coupledDamping());
    EXPECT_EQ(modal::bodyDampingMatrix(plain), Eigen::MatrixXd(modal::modalDampingCoefficients(plain).asDiagonal()));
    const auto damped = reducer.reduce(itf, settings(4, {"end1:2e10"}, {"end1:3e5", "sides:1e4"}));
    EXPECT_EQ(damped.frequenciesHz, reducer.reduce(itf, settings(4, {"end1:2e10"}, {})).frequenciesHz);
    const auto dir = test::scratchDir();
    const std::string a = (dir / "plain.h5").string(), b = (dir / "damped.h5").string();
    modal::writeReducedBody(plain, a);
    modal::writeReducedBody(damped, b);
    EXPECT_EQ(modal::readReducedBody(a).supportDamping.size(), 0);
    const auto back = modal::readReducedBody(b);
    EXPECT_EQ(back.settings.dampers, damped.settings.dampers);
    EXPECT_EQ(back.supportDamping, damped.supportDamping);
    EXPECT_THROW(modal::ModalDynamics(damped, 1e-5), std::invalid_argument);
}

TEST(DamperSupport, BadDampersGiveClearErrors) {
    modal::CraigBamptonReducer reducer(bar(), kSteel);
    const auto itf = std::vector{modal::parseInterface("end0:rbe2")};
    const auto message = [&](std::vector<std::string> dampers) {
        try {
            reducer.reduce(itf, settings(4, {"end1:1e9"}, std::move(dampers)));
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message({"end0:1e5"}).find("--damper 'end0:1e5': group 'end0' is also an interface"), std::string::npos);
    EXPECT_NE(message({"nope:1e5"}).find("--damper 'nope:1e5': "), std::string::npos);
    EXPECT_NE(message({"nope:1e5"}).find("no physical group 'nope'"), std::string::npos);
    EXPECT_NE(message({"bar:1e5"}).find("is a volume"), std::string::npos);
    EXPECT_NE(message({"end1:1e5", "end1:2e5"}).find("has a damper already"), std::string::npos);
    EXPECT_EQ(message({"end1:1e5"}), "no error");  // on a spring-supported group too
    for (const std::string bad : {"end1", "end1:", ":1e5", "end1:abc", "end1:1e5x"})
        EXPECT_NE(message({bad}).find("--damper '" + bad + "': "), std::string::npos) << bad;
    for (const std::string bad : {"end1:0", "end1:-1e5", "end1:inf", "end1:nan"})
        EXPECT_NE(message({bad}).find("C must be finite and > 0"), std::string::npos) << bad;
    EXPECT_THROW(fem::surfaceDashpotMatrix(fem::BoundarySurface(bar(), "end1"), 0.0), std::invalid_argument);
}
