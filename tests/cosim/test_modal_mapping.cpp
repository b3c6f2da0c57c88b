// Modal pre-multiplied mappings (cosim/mapping/ModalMapping) on a Craig–Bampton piston: equal to the
// two-step nodal route, rigid-body modal forces equal to the closed-form resultant of the
// source, and the quasi-static modal grid deformation against the full finite-element solution.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "cosim/mapping/ModalMapping.hpp"
#include "fem/DofMap.hpp"
#include "fem/ElasticityAssembler.hpp"
#include "fem/MeshReader.hpp"
#include "fem/StaticSolver.hpp"
#include "modal/CraigBamptonReducer.hpp"
#include "modal/ModalSuperposition.hpp"

using namespace flexehd;
using cosim::DeformationMapping;
using cosim::LoadMapping;
using cosim::ModalMapping;
using lube::FilmGrid;

namespace {

const fem::ElasticMaterial kAlu{7.5e10, 0.33, 2700.0};

const fem::Mesh& piston() {
    static const fem::Mesh m =
        fem::readMesh(std::string(FLEXEHD_SOURCE_DIR) + "/meshes/piston.geo", {2, 0.0065});
    return m;
}

// Pin bore tied by RBE2; `correction`: residual attachment modes for skirt pressure patterns.
const modal::ReducedBody& body(bool correction) {
    auto make = [](bool c) {
        modal::ReductionSettings s;
        s.normalModes = 10;
        if (c) {
            s.staticCorrection = {"skirt"};
            s.axialOrder = 4;
            s.circumferentialOrder = 6;
        }
        return modal::CraigBamptonReducer(piston(), kAlu).reduce({modal::parseInterface("pin_bore:rbe2")}, s);
    };
    if (correction) {
        static const modal::ReducedBody b = make(true);
        return b;
    }
    static const modal::ReducedBody b = make(false);
    return b;
}

// Thrust-side skirt panel: an open arc around θ = 0 inside the panel.
const FilmGrid& grid() {
    static const FilmGrid g = FilmGrid::arc(0.043, FilmGrid::uniform(-0.0249, 0.0107, 40), -0.69, 0.69, 61);
    return g;
}

Eigen::VectorXd bump(const FilmGrid& g) {
    Eigen::VectorXd p(g.size());
    for (int k = 0; k < g.size(); ++k) {
        const double z = g.z(g.axialIndex(k)), th = g.theta(g.thetaIndex(k));
        p(k) = 5e6 * std::exp(-std::pow((z + 0.008) / 0.008, 2) - std::pow(th / 0.3, 2));
    }
    return p;
}

}  // namespace

TEST(ModalMapping, EqualsTheTwoStepNodalRoute) {
    const modal::ReducedBody& b = body(false);
    const LoadMapping load(piston(), "skirt", grid());
    const DeformationMapping def(piston(), "skirt", grid());
    const ModalMapping mm(b, load, def);
    ASSERT_EQ(mm.loadOperator().rows(), b.numModes());
    ASSERT_EQ(mm.loadOperator().cols(), grid().size());
    ASSERT_EQ(mm.gridShapes().rows(), grid().size());
    ASSERT_EQ(mm.gridShapes().cols(), b.numModes());

    const Eigen::VectorXd p = Eigen::VectorXd::Random(grid().size()).array() * 1e6 + 2e6;
    const Eigen::VectorXd twoStep = b.shapes.transpose() * load.apply(p);
    const double eF = (mm.modalForce(p) - twoStep).norm() / twoStep.norm();
    const Eigen::VectorXd q = Eigen::VectorXd::Random(b.numModes()) * 1e-4;
    const Eigen::VectorXd ref = def.radial() * (b.shapes * q);
    const double eU = (mm.radialDisplacement(q) - ref).norm() / ref.norm();
    std::printf("  modal vs two-step: force %.1e, displacement %.1e (relative)\n", eF, eU);
    EXPECT_LE(eF, 1e-13);
    EXPECT_LE(eU, 1e-13);

    EXPECT_THAT([&] { (void)mm.modalForce(Eigen::VectorXd::Zero(5)); },
                ::testing::ThrowsMessage<std::invalid_argument>(::testing::HasSubstr("5 pressures")));
    const FilmGrid other = FilmGrid::arc(0.043, FilmGrid::uniform(-0.02, 0.01, 10), -0.5, 0.5, 11);
    const DeformationMapping defOther(piston(), "skirt", other);
    EXPECT_THAT([&] { ModalMapping(b, load, defOther); },
                ::testing::ThrowsMessage<std::invalid_argument>(::testing::HasSubstr("not the same grid")));
}

// A rigid-body mode moves every node by u + ω × (x − x_ref) (u, ω: interface motion per unit q),
// so its modal force is F·u + ω·M_ref. For a uniform p0 on the arc [θa, θb] × [z0, z1], closed
// forms (body inside the film, F = −∫ p n_r dA):
//   F = −p0 R (z1 − z0) (sin θb − sin θa, cos θa − cos θb, 0),
//   M_0 = −p0 R (z1² − z0²)/2 (cos θb − cos θa, sin θb − sin θa, 0),  M_ref = M_0 − x_ref × F.

// Restricted to the grid nodes that carry film (a masked band of the arc grid, as FlexibleSurface
// passes the non-Void nodes): the modal force of a pressure that vanishes off those nodes and the
// grid displacement on them equal the unrestricted products to round-off; 0 off them.
TEST(ModalMapping, RestrictedToFilmNodesEqualsTheFullProducts) {
    const modal::ReducedBody& b = body(true);
    const FilmGrid& g = grid();
    const LoadMapping load(piston(), "skirt", g);
    const DeformationMapping def(piston(), "skirt", g);
    std::vector<int> active;
    for (int k = 0; k < g.size(); ++k)
        if (std::abs(g.theta(g.thetaIndex(k))) <= 0.45 && g.axialIndex(k) % 7 != 3) active.push_back(k);
    ASSERT_GT(active.size(), 100u);
    ASSERT_LT(active.size(), std::size_t(g.size()));
    const ModalMapping full(b, load, def), restricted(b, load, def, active);
    EXPECT_EQ(int(full.activeNodes().size()), g.size());
    EXPECT_EQ(restricted.activeNodes(), active);
    std::vector<bool> on(std::size_t(g.size()), false);
    for (int k : active) on[std::size_t(k)] = true;
    Eigen::VectorXd p = bump(g);
    for (int k = 0; k < g.size(); ++k)
        if (!on[std::size_t(k)]) p[k] = 0.0;
    const Eigen::VectorXd fFull = full.modalForce(p), fRes = restricted.modalForce(p);
    const double eF = (fRes - fFull).norm() / fFull.norm();
    const Eigen::VectorXd q = Eigen::VectorXd::Random(b.numModes());
    const Eigen::VectorXd uFull = full.radialDisplacement(q), uRes = restricted.radialDisplacement(q);
    ASSERT_EQ(uRes.size(), g.size());
    double eU = 0.0;
    for (int k = 0; k < g.size(); ++k) {
        if (on[std::size_t(k)])
            eU = std::max(eU, std::abs(uRes[k] - uFull[k]));
        else
            EXPECT_EQ(uRes[k], 0.0) << k;
    }
    eU /= uFull.cwiseAbs().maxCoeff();
    std::printf("  restricted (%zu of %d nodes) vs full: modal force %.1e, grid displacement %.1e\n", active.size(),
                g.size(), eF, eU);
    EXPECT_LE(eF, 1e-13);
    EXPECT_LE(eU, 1e-14);
    // Many pressure fields at once: the same modal forces.
    Eigen::MatrixXd P(g.size(), 2), F;
    P.col(0) = p;
    P.col(1) = 0.5 * p;
    restricted.modalForces(P, F);
    EXPECT_LE((F.col(0) - fRes).norm(), 1e-14 * fRes.norm());
    EXPECT_LE((F.col(1) - 0.5 * fRes).norm(), 1e-14 * fRes.norm());
    // Pressure changes on a few nodes only (a starved film's patches; the product skips the
    // unloaded nodes): the full operator's product.
    Eigen::MatrixXd Ps = Eigen::MatrixXd::Zero(g.size(), 3);
    for (std::size_t i = 0; i < active.size(); i += 37) Ps.row(active[i]) = Eigen::RowVector3d(p[active[i]], -1e5, 2e4);
    restricted.modalForces(Ps, F);
    const Eigen::MatrixXd expected = restricted.loadOperator() * Ps;
    EXPECT_LE((F - expected).norm(), 1e-13 * expected.norm());
    // The same fields given on their nodes (lube::NodeColumns), one off the active nodes added
    // (ignored, as by the grid-wide product of a field that is zero there).
    lube::NodeColumns onNodes = lube::NodeColumns::fromDense(Ps);
    Eigen::MatrixXd Fn;
    restricted.modalForces(onNodes, Fn);
    EXPECT_LE((Fn - expected).norm(), 1e-13 * expected.norm());
    for (int k = 0; k < g.size(); ++k)
        if (!on[std::size_t(k)]) {
            lube::NodeColumns extra;
            extra.nodes = {k};
            extra.values = Eigen::RowVector3d(1e6, 1e6, 1e6);
            restricted.modalForces(lube::NodeColumns::sum(onNodes, extra), Fn);
            EXPECT_LE((Fn - expected).norm(), 1e-13 * expected.norm());
            break;
        }
    const Eigen::VectorXd fs = restricted.modalForce(Eigen::VectorXd(Ps.col(1)));
    EXPECT_LE((fs - expected.col(1)).norm(), 1e-13 * expected.col(1).norm());
    // The full-size operators: zero columns / rows off the active nodes, the same products.
    const Eigen::MatrixXd B = restricted.loadOperator(), G = restricted.gridShapes();
    EXPECT_LE((B * p - fRes).norm(), 1e-13 * fRes.norm());
    EXPECT_LE((G * q - uRes).norm(), 1e-14 * uRes.norm());
    EXPECT_THAT([&] { ModalMapping(b, load, def, {5, 4}); },
                ::testing::ThrowsMessage<std::invalid_argument>(::testing::HasSubstr("not ascending")));
    EXPECT_THAT([&] { ModalMapping(b, load, def, {g.size()}); },
                ::testing::ThrowsMessage<std::invalid_argument>(::testing::HasSubstr("out of range")));
}

TEST(ModalMapping, RigidBodyModalForcesEqualTheClosedFormResultant) {
    const modal::ReducedBody& b = body(false);
    const FilmGrid& g = grid();
    const ModalMapping mm(b, LoadMapping(piston(), "skirt", g), DeformationMapping(piston(), "skirt", g));
    const double p0 = 3e6, R = g.radius(), z0 = g.axial().front(), z1 = g.axial().back();
    const double ta = g.theta(0), tb = g.theta(g.nTheta() - 1);
    const Eigen::Vector3d F = -p0 * R * (z1 - z0) * Eigen::Vector3d(std::sin(tb) - std::sin(ta), std::cos(ta) - std::cos(tb), 0.0);
    const Eigen::Vector3d M0 =
        -p0 * R * 0.5 * (z1 * z1 - z0 * z0) * Eigen::Vector3d(std::cos(tb) - std::cos(ta), std::sin(tb) - std::sin(ta), 0.0);
    const Eigen::Vector3d xr = b.interfaces[0].referencePoint;
    const Eigen::Vector3d Mref = M0 - xr.cross(F);
    const Eigen::VectorXd Q = mm.modalForce(Eigen::VectorXd::Constant(g.size(), p0));
    int rigid = 0;
    for (int k = 0; k < b.numModes(); ++k) {
        if (!b.rigidBody[static_cast<std::size_t>(k)]) continue;
        ++rigid;
        const Eigen::Vector3d u = b.interfaceMotion.col(k).head<3>(), w = b.interfaceMotion.col(k).segment<3>(3);
        const double expected = F.dot(u) + w.dot(Mref);
        const double scale = F.norm() * u.norm() + (F.norm() * R + Mref.norm()) * w.norm();
        // Tolerance: the torque about the axis carries the faceting error (≤ 2e-7, docs/mapping.md),
        // and the rigid modes come from an eigen-solution (round-off ~1e-10).
        EXPECT_NEAR(Q(k), expected, 1e-6 * scale) << "mode " << k;
        std::printf("  rigid mode %d: modal force %.9e, closed form %.9e\n", k, Q(k), expected);
    }
    EXPECT_EQ(rigid, 6);
}

// Physical check: quasi-static modal response (pin bore held) to the mapped pressure vs the full
// finite-element static solution under the same nodal forces, both read on the grid through the
// deformation mapping. With static correction (skirt patterns) the Ritz error is a few per cent
// (cf. tests/modal/test_craig_bampton.cpp); plain Craig–Bampton with 10 modes is far off.
TEST(ModalMapping, QuasiStaticGridDeformationMatchesTheFullModel) {
    const fem::Mesh& m = piston();
    const FilmGrid& g = grid();
    const LoadMapping load(m, "skirt", g);
    const DeformationMapping def(m, "skirt", g);
    const Eigen::VectorXd p = bump(g);
    const Eigen::VectorXd f = load.apply(p);

    fem::ElasticityAssembler a(m);
    const fem::SparseMatrix K = a.stiffness(kAlu);
    fem::DofMap dofs(m.numNodes(), 3);
    dofs.constrain(m.groupNodes("pin_bore"), fem::kAllComponents);
    dofs.finalize();
    const Eigen::VectorXd uFull = dofs.expand(fem::StaticSolver(dofs.reduce(K)).solve(dofs.reduceLoad(f, K)));
    const Eigen::VectorXd ref = def.radial() * uFull;

    double errors[2];
    for (int c : {0, 1}) {
        const modal::ReducedBody& b = body(c == 1);
        const ModalMapping mm(b, load, def);
        const modal::ModalSuperposition sup(b);
        const Eigen::VectorXd q = sup.quasiStatic(mm.modalForce(p), {0});
        errors[c] = (mm.radialDisplacement(q) - ref).cwiseAbs().maxCoeff() / ref.cwiseAbs().maxCoeff();
    }
    std::printf("  grid radial displacement: max |u| %.3e m; modal error %.2f %% (10 modes), %.2f %% (10 modes + "
                "skirt correction)\n",
                ref.cwiseAbs().maxCoeff(), 100 * errors[0], 100 * errors[1]);
    EXPECT_LT(errors[1], 0.01);
    EXPECT_LT(errors[1], errors[0]);
}
