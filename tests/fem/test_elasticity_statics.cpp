// Static elasticity checks against closed-form solutions: constant-strain patch test,
// stress-free thermal expansion, Lamé's thick cylinder; assembly against an independent
// triplet assembly.
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "TestData.hpp"
#include "fem/DofMap.hpp"
#include "fem/EigenmodeSolver.hpp"
#include "fem/ElasticityAssembler.hpp"
#include "fem/ElasticityElement.hpp"
#include "fem/MeshReader.hpp"
#include "fem/StaticSolver.hpp"

using namespace flexehd::fem;
using flexehd::test::dataPath;

namespace {
const ElasticMaterial kSteel{2.1e11, 0.3, 7850.0};

// Solves K u = f with the given DofMap (finalised inside).
Eigen::VectorXd solveStatic(const SparseMatrix& K, const Eigen::VectorXd& f, DofMap& dofs) {
    dofs.finalize();
    StaticSolver solver(dofs.reduce(K));
    return dofs.expand(solver.solve(dofs.reduceLoad(f, K)));
}

// Nodes nearest to given points (for point constraints).
Index nearestNode(const Mesh& m, const Eigen::Vector3d& p) {
    Index best = 0;
    (m.nodes.colwise() - p).colwise().squaredNorm().minCoeff(&best);
    return best;
}
}  // namespace

class PatchTest : public testing::TestWithParam<int> {};

// A linear displacement field u = A x + c prescribed on the boundary must be reproduced
// exactly inside by any conforming element (Irons patch test), here on unstructured tets.
TEST_P(PatchTest, LinearFieldReproducedToRoundOff) {
    const Mesh m = readMesh(dataPath("cube.geo"), {GetParam(), 0.3});
    Eigen::Matrix3d A;
    A << 1.0e-3, 2.0e-4, -3.0e-4, -1.0e-4, 5.0e-4, 2.5e-4, 3.0e-4, -2.0e-4, -7.0e-4;
    const Eigen::Vector3d c(1e-4, -2e-4, 3e-4);
    ElasticityAssembler asm_(m);
    const SparseMatrix K = asm_.stiffness(kSteel);
    DofMap dofs(m.numNodes(), 3);
    const auto boundary = m.groupNodes("boundary");
    for (Index n : boundary) {
        const Eigen::Vector3d u = A * m.nodes.col(n) + c;
        for (int i = 0; i < 3; ++i) dofs.constrainDof(3 * n + i, u(i));
    }
    ASSERT_LT(boundary.size(), std::size_t(m.numNodes()));  // there are interior nodes
    const Eigen::VectorXd u = solveStatic(K, Eigen::VectorXd::Zero(asm_.numDofs()), dofs);
    double err = 0.0;
    for (Index n = 0; n < m.numNodes(); ++n)
        err = std::max(err, (u.segment<3>(3 * n) - (A * m.nodes.col(n) + c)).norm());
    EXPECT_LT(err, 1e-12 * A.norm());
}
INSTANTIATE_TEST_SUITE_P(Tet4AndTet10, PatchTest, testing::Values(1, 2));

// Free thermal expansion under a temperature linear in x, T = T0 + g x, is stress-free
// with the quadratic displacement
//   u_x = α(T0 x + g x²/2 - g(y² + z²)/2),  u_y = α(T0 + g x) y,  u_z = α(T0 + g x) z
// (plus a rigid motion fixed by 3-2-1 point constraints at the origin). TET10 spans it.
TEST(ThermalStrain, FreeExpansionUnderLinearTemperatureIsExactOnTet10) {
    const Mesh m = readMesh(dataPath("cube.geo"), {2, 0.3});
    const double alpha = 1.2e-5, T0 = 80.0, g = 150.0, Tref = 20.0;
    Eigen::VectorXd T(m.numNodes());
    for (Index n = 0; n < m.numNodes(); ++n) T(n) = Tref + T0 + g * m.nodes(0, n);
    auto exact = [&](const Eigen::Vector3d& x) {
        const double e = alpha * (T0 + g * x(0));
        return Eigen::Vector3d(alpha * (T0 * x(0) + g * x(0) * x(0) / 2 - g * (x(1) * x(1) + x(2) * x(2)) / 2),
                               e * x(1), e * x(2));
    };
    ElasticityAssembler asm_(m);
    const SparseMatrix K = asm_.stiffness(kSteel);
    const Eigen::VectorXd f = asm_.thermalLoad(kSteel, alpha, T, Tref);
    // Hold the exact field at three corners (3-2-1): removes rigid motion without stress.
    DofMap dofs(m.numNodes(), 3);
    const Index n0 = nearestNode(m, {0, 0, 0}), n1 = nearestNode(m, {1, 0, 0}), n2 = nearestNode(m, {0, 1, 0});
    for (int i = 0; i < 3; ++i) dofs.constrainDof(3 * n0 + i, exact(m.nodes.col(n0))(i));
    for (int i : {1, 2}) dofs.constrainDof(3 * n1 + i, exact(m.nodes.col(n1))(i));
    dofs.constrainDof(3 * n2 + 2, exact(m.nodes.col(n2))(2));
    const Eigen::VectorXd u = solveStatic(K, f, dofs);
    double err = 0.0, scale = 0.0;
    for (Index n = 0; n < m.numNodes(); ++n) {
        err = std::max(err, (u.segment<3>(3 * n) - exact(m.nodes.col(n))).norm());
        scale = std::max(scale, exact(m.nodes.col(n)).norm());
    }
    EXPECT_LT(err, 1e-9 * scale);
}

// Lamé: thick cylinder a = 0.05, b = 0.1 m under internal pressure p, free ends
// (σ_z = 0 exactly in 3-D): u_r = p a² / (E (b² - a²)) [(1 - ν) r + (1 + ν) b² / r].
TEST(Lame, ThickCylinderUnderInternalPressure) {
    const Mesh m = readMesh(dataPath("thick_cylinder.geo"), {2, 0.01});
    const double a = 0.05, b = 0.1, p = 1e8, E = kSteel.E, nu = kSteel.nu;
    auto ur = [&](double r) { return p * a * a / (E * (b * b - a * a)) * ((1 - nu) * r + (1 + nu) * b * b / r); };
    ElasticityAssembler asm_(m);
    const SparseMatrix K = asm_.stiffness(kSteel);
    const Eigen::VectorXd f = asm_.pressureLoad(BoundarySurface(m, "inner"), p);
    // Total force on the quarter inner surface: p a H along (1,1,0) (projected areas).
    EXPECT_NEAR(f.reshaped(3, m.numNodes()).rowwise().sum()(0), p * a * 0.02, 1e-6 * p * a * 0.02);
    DofMap dofs(m.numNodes(), 3);
    dofs.constrain(m.groupNodes("sym_x"), kX);
    dofs.constrain(m.groupNodes("sym_y"), kY);
    dofs.constrain(m.groupNodes("bottom"), kZ);
    const Eigen::VectorXd u = solveStatic(K, f, dofs);
    double worst = 0.0;
    for (Index n = 0; n < m.numNodes(); ++n) {
        const Eigen::Vector3d x = m.nodes.col(n);
        const double r = x.head<2>().norm();
        const double urFe = u.segment<2>(3 * n).dot(x.head<2>() / r);
        worst = std::max(worst, std::abs(urFe / ur(r) - 1.0));
    }
    EXPECT_LT(worst, 5e-3);  // discretisation error of the 1/r term at h = 10 mm
}

// The pattern-based scatter assembly against Eigen's triplet assembly (an independent
// route), and K annihilating the six rigid-body motions.
TEST(Assembly, MatchesTripletAssemblyAndHasRigidBodyNullSpace) {
    const Mesh m = readMesh(dataPath("thick_cylinder.geo"), {2, 0.02});
    ElasticityAssembler asm_(m);
    const SparseMatrix K = asm_.stiffness(kSteel);
    std::vector<Eigen::Triplet<double>> trips;
    using El = ElasticityElement<ElementType::Tet10>;
    El::Matrix Ke;
    for (Index e = 0; e < m.volume.size(); ++e) {
        El::Coordinates X;
        for (int a = 0; a < 10; ++a) X.col(a) = m.nodes.col(m.volume.nodes(a, e));
        El::stiffness(X, kSteel.lambda(), kSteel.mu(), Ke);
        for (int a = 0; a < 30; ++a)
            for (int b = 0; b < 30; ++b)
                trips.emplace_back(3 * m.volume.nodes(a / 3, e) + a % 3, 3 * m.volume.nodes(b / 3, e) + b % 3, Ke(a, b));
    }
    SparseMatrix Kref(asm_.numDofs(), asm_.numDofs());
    Kref.setFromTriplets(trips.begin(), trips.end());
    const SparseMatrix Kfull = K.selfadjointView<Eigen::Upper>();
    EXPECT_LT((Kfull - Kref).norm(), 1e-13 * Kref.norm());

    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(asm_.numDofs(), 6);
    for (Index n = 0; n < m.numNodes(); ++n) {
        const Eigen::Vector3d x = m.nodes.col(n);
        R.block<3, 3>(3 * n, 0).setIdentity();
        R.block<3, 3>(3 * n, 3) << 0, x(2), -x(1), -x(2), 0, x(0), x(1), -x(0), 0;
    }
    const Eigen::MatrixXd KR = K.selfadjointView<Eigen::Upper>() * R;
    EXPECT_LT(KR.norm(), 1e-9 * Kref.norm() * R.norm() / std::sqrt(double(asm_.numDofs())));
}

// Consistent mass: total mass ρV in each direction, and the rigid rotation inertia.
TEST(Assembly, MassMatrixCarriesTotalMass) {
    const Mesh m = readMesh(dataPath("thick_cylinder.geo"), {2, 0.02});
    ElasticityAssembler asm_(m);
    const SparseMatrix M = asm_.mass(kSteel.rho);
    Eigen::VectorXd ex = Eigen::VectorXd::Zero(asm_.numDofs());
    for (Index n = 0; n < m.numNodes(); ++n) ex(3 * n) = 1.0;
    const double mass = ex.dot(M.selfadjointView<Eigen::Upper>() * ex);
    EXPECT_NEAR(mass / (kSteel.rho * m.volumeMeasure()), 1.0, 1e-12);
    // Polar moment of the quarter annulus about z: ρ H π/8 (b⁴ - a⁴).
    Eigen::VectorXd rot = Eigen::VectorXd::Zero(asm_.numDofs());
    for (Index n = 0; n < m.numNodes(); ++n) rot.segment<3>(3 * n) << -m.nodes(1, n), m.nodes(0, n), 0.0;
    const double J = rot.dot(M.selfadjointView<Eigen::Upper>() * rot);
    const double Jexact = kSteel.rho * 0.02 * std::numbers::pi / 8.0 * (std::pow(0.1, 4) - std::pow(0.05, 4));
    EXPECT_NEAR(J / Jexact, 1.0, 1e-4);  // curved-boundary geometry error only
}

TEST(StaticSolver, UnconstrainedBodyIsReported) {
    const Mesh m = readMesh(dataPath("cube.geo"), {1, 0.5});
    ElasticityAssembler asm_(m);
    const std::string msg = flexehd::test::errorOf([&] { StaticSolver s(asm_.stiffness(kSteel)); });
    EXPECT_NE(msg.find("not constrained"), std::string::npos) << msg;
}

// Rigid links (RBE2): the O(nnz) reduction against the plain sparse product Tᵀ K T, and
// the tie itself: a held reference node holds the whole set (exact zero displacement).
TEST(DofMapRigidLink, ReductionMatchesTransformationProduct) {
    const Mesh m = readMesh(dataPath("thick_cylinder.geo"), {2, 0.02});
    ElasticityAssembler asm_(m);
    const SparseMatrix K = asm_.stiffness(kSteel);
    DofMap dofs(m.numNodes(), 3);
    const auto inner = m.groupNodes("inner");
    dofs.addRigidLink(inner, m.nodes, Eigen::Vector3d(0.0, 0.0, 0.01));
    std::vector<Index> bottom;  // the bottom face without the edge it shares with the link
    for (Index n : m.groupNodes("bottom"))
        if (!std::binary_search(inner.begin(), inner.end(), n)) bottom.push_back(n);
    dofs.constrain(bottom, kZ);
    dofs.finalize();
    const SparseMatrix R = dofs.reduce(K);
    const SparseMatrix full = K.selfadjointView<Eigen::Upper>();
    const SparseMatrix ref = dofs.transformation().transpose() * full * dofs.transformation();
    const SparseMatrix Rfull = R.selfadjointView<Eigen::Upper>();
    EXPECT_LT((Rfull - ref).norm(), 1e-12 * ref.norm());
    // A unit rotation of the reference about z moves every tied node by e_z × (x - x_r).
    Eigen::VectorXd q = Eigen::VectorXd::Zero(dofs.numFree());
    q(dofs.linkEquation(0) + 5) = 1.0;
    const Eigen::VectorXd u = dofs.expand(q);
    for (Index n : m.groupNodes("inner")) {
        const Eigen::Vector3d d = m.nodes.col(n) - Eigen::Vector3d(0.0, 0.0, 0.01);
        EXPECT_LT((u.segment<3>(3 * n) - Eigen::Vector3d::UnitZ().cross(d)).norm(), 1e-15);
    }
    // Holding a linked DOF is refused.
    EXPECT_THROW(
        {
            DofMap bad(m.numNodes(), 3);
            bad.addRigidLink(m.groupNodes("inner"), m.nodes, Eigen::Vector3d::Zero());
            bad.constrain(m.groupNodes("inner"), kX);
        },
        std::invalid_argument);
}

// RBE3: whatever the unknowns, the set's displacements satisfy the least-squares fit
// Gᵀ u_S = GᵀG q_r (G_s = [I, -[d_s]x]), i.e. the reference follows the average motion;
// and the link adds no stiffness: a free body keeps exactly its frequencies.
TEST(DofMapAveragingLink, ReferenceFollowsTheLeastSquaresFitAndAddsNoStiffness) {
    const Mesh m = readMesh(dataPath("beam.geo"), {2, 0.01});
    const auto tip = m.groupNodes("tip");
    const Eigen::Vector3d xr(1.0, 0.01, 0.01);
    DofMap dofs(m.numNodes(), 3);
    dofs.addAveragingLink(tip, m.nodes, xr);
    dofs.finalize();
    Eigen::VectorXd w = Eigen::VectorXd::Random(dofs.numFree());
    const Eigen::VectorXd u = dofs.expand(w);
    const Eigen::Matrix<double, 6, 1> q = w.tail<6>();
    Eigen::Matrix<double, 6, 1> Gtu = Eigen::Matrix<double, 6, 1>::Zero(), GtGq = Gtu;
    for (Index n : tip) {
        const Eigen::Vector3d d = m.nodes.col(n) - xr, us = u.segment<3>(3 * n);
        const Eigen::Vector3d rigid = q.head<3>() + q.tail<3>().cross(d);  // G_s q
        Gtu.head<3>() += us;
        Gtu.tail<3>() += d.cross(us);
        GtGq.head<3>() += rigid;
        GtGq.tail<3>() += d.cross(rigid);
    }
    EXPECT_LT((Gtu - GtGq).norm(), 1e-10 * GtGq.norm());

    ElasticityAssembler a(m);
    const SparseMatrix K = a.stiffness(kSteel), M = a.mass(kSteel.rho);
    EigenmodeOptions opt;
    opt.count = 12;
    const Eigen::VectorXd plain = solveEigenmodes(K, M, opt).frequenciesHz();
    const Eigen::VectorXd linked = solveEigenmodes(dofs.reduce(K), dofs.reduce(M), opt).frequenciesHz();
    for (int k = 6; k < 12; ++k) EXPECT_NEAR(linked(k) / plain(k), 1.0, 1e-8) << "mode " << k + 1;
}
