// Craig–Bampton reduced bodies against the full finite-element model of the same mesh:
// free-interface frequencies (converging as modes are added) and the quasi-static skirt
// and bore deformation under film-like pressures, with and without static correction.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "../fem/TestData.hpp"
#include "fem/BoundarySurface.hpp"
#include "fem/DofMap.hpp"
#include "fem/ElasticityAssembler.hpp"
#include "fem/EigenmodeSolver.hpp"
#include "fem/MeshReader.hpp"
#include "fem/ModalAnalysis.hpp"
#include "fem/StaticSolver.hpp"
#include "modal/CraigBamptonReducer.hpp"
#include "modal/ModalSuperposition.hpp"

using namespace flexehd;
using flexehd::test::meshPath;

namespace {
const fem::ElasticMaterial kAlu{7.5e10, 0.33, 2700.0};
const fem::ElasticMaterial kIron{1.1e11, 0.26, 7200.0};

const fem::Mesh& piston() {
    static const fem::Mesh m = fem::readMesh(meshPath("piston.geo"), {2, 0.0065});
    return m;
}
const fem::Mesh& liner() {
    static const fem::Mesh m = fem::readMesh(meshPath("liner.geo"), {2, 0.009});
    return m;
}

modal::ReductionSettings settings(int modes, std::vector<std::string> correction = {}) {
    modal::ReductionSettings s;
    s.normalModes = modes;
    s.staticCorrection = std::move(correction);
    s.axialOrder = 4;
    s.circumferentialOrder = 6;
    return s;
}

// Full model, free, with the same RBE2 tie as the reduced body: its elastic frequencies
// are what the reduction must reproduce.
Eigen::VectorXd fullFreeWithRbe2(const fem::Mesh& m, const std::string& group, int count) {
    fem::DofMap dofs(m.numNodes(), 3);
    const auto nodes = m.groupNodes(group);
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (auto n : nodes) c += m.nodes.col(n);
    dofs.addRigidLink(nodes, m.nodes, c / double(nodes.size()));
    dofs.finalize();
    fem::ElasticityAssembler a(m);
    fem::EigenmodeOptions opt;
    opt.count = count;
    return fem::solveEigenmodes(dofs.reduce(a.stiffness(kAlu)), dofs.reduce(a.mass(kAlu.rho)), opt).frequenciesHz();
}

// Full static solution with the given groups held (= RBE2 reference nodes held).
Eigen::VectorXd fullStatic(const fem::Mesh& m, const fem::ElasticMaterial& mat, const Eigen::VectorXd& f,
                           const std::vector<std::string>& held) {
    fem::ElasticityAssembler a(m);
    const fem::SparseMatrix K = a.stiffness(mat);
    fem::DofMap dofs(m.numNodes(), 3);
    for (const auto& g : held) dofs.constrain(m.groupNodes(g), fem::kAllComponents);
    dofs.finalize();
    return dofs.expand(fem::StaticSolver(dofs.reduce(K)).solve(dofs.reduceLoad(f, K)));
}

// Smooth pressure bump p0 exp(-((z-zc)/wz)² - (θ/wθ)²) on a surface (thrust side θ = 0).
Eigen::VectorXd bump(const fem::Mesh& m, const std::string& surface, double p0, double zc, double wz, double wt) {
    Eigen::VectorXd p = Eigen::VectorXd::Zero(m.numNodes());
    for (auto n : m.groupNodes(surface)) {
        const double th = std::atan2(m.nodes(1, n), m.nodes(0, n));
        p(n) = p0 * std::exp(-std::pow((m.nodes(2, n) - zc) / wz, 2) - std::pow(th / wt, 2));
    }
    return p;
}

// Max radial-displacement error on a surface relative to the largest radial displacement.
double radialError(const fem::Mesh& m, const std::string& surface, const Eigen::VectorXd& u,
                   const Eigen::VectorXd& ref) {
    double err = 0.0, scale = 0.0;
    for (auto n : m.groupNodes(surface)) {
        const Eigen::Vector2d er = m.nodes.col(n).head<2>().normalized();
        const double a = u.segment<2>(3 * n).dot(er), b = ref.segment<2>(3 * n).dot(er);
        err = std::max(err, std::abs(a - b));
        scale = std::max(scale, std::abs(b));
    }
    return err / scale;
}
}  // namespace

TEST(CraigBampton, FreePistonFrequenciesConvergeToFullModel) {
    const Eigen::VectorXd full = fullFreeWithRbe2(piston(), "pin_bore", 16);
    modal::CraigBamptonReducer reducer(piston(), kAlu);
    double previous = 1e300;
    for (int modes : {10, 20, 30}) {
        const modal::ReducedBody body = reducer.reduce({modal::parseInterface("pin_bore:rbe2")}, settings(modes));
        ASSERT_EQ(std::count(body.rigidBody.begin(), body.rigidBody.end(), 1), 6);
        // Orthonormal to round-off.
        EXPECT_LT((body.massMatrix - Eigen::MatrixXd::Identity(body.numModes(), body.numModes())).norm(), 1e-9);
        double worst = 0.0;
        for (int k = 6; k < 16; ++k) {
            const double e = body.frequenciesHz(k) / full(k) - 1.0;
            EXPECT_GT(e, -1e-9) << "Rayleigh–Ritz bound, mode " << k + 1;  // a reduction only stiffens
            worst = std::max(worst, e);
        }
        std::printf("free piston, %d fixed-interface modes: worst error of the first ten elastic modes %.3e\n",
                    modes, worst);
        EXPECT_LT(worst, previous);  // converges as modes are added
        previous = worst;
        if (modes == 30) {
            EXPECT_LT(worst, 1e-3);
        }
    }
}

// Held at both seats, the liner reduced as scripts/example.sh reduces it (20 fixed-interface
// normal modes, static correction on the bore) vibrates at the full model's frequencies with both
// seats fixed: its normal modes are those very modes, and the static-correction vectors only add
// to the Ritz basis (modal::heldFrequenciesHz, what `flexehd inspect` prints as "held").
TEST(CraigBampton, HeldLinerFrequenciesAreTheFullModelsWithTheSeatsFixed) {
    const fem::Mesh& m = liner();
    fem::ElasticityAssembler a(m);
    fem::DofMap dofs(m.numNodes(), 3);
    for (const char* g : {"top_seat", "bottom_seat"}) dofs.constrain(m.groupNodes(g), fem::kAllComponents);
    dofs.finalize();
    fem::EigenmodeOptions opt;
    opt.count = 21;
    const Eigen::VectorXd full =
        fem::solveEigenmodes(dofs.reduce(a.stiffness(kIron)), dofs.reduce(a.mass(kIron.rho)), opt).frequenciesHz();
    auto s = settings(20, {"bore"});
    s.axialHats = 17;
    const auto body =
        modal::CraigBamptonReducer(m, kIron)
            .reduce({modal::parseInterface("top_seat:rbe2"), modal::parseInterface("bottom_seat:rbe2")}, s);
    const Eigen::VectorXd held = modal::heldFrequenciesHz(body, {0, 1});
    double worst = 0.0;
    for (int k = 0; k < 12; ++k) worst = std::max(worst, std::abs(held(k) / full(k) - 1.0));
    std::printf("liner held at its seats: first held frequency %.2f Hz (full model %.2f Hz), worst of 12: %.2e\n",
                held(0), full(0), worst);
    EXPECT_LT(worst, 1e-9);  // the Lanczos tolerance 1e-10 on the eigenvalues; measured 1.5e-13
    // The range the basis covers (modal::normalModesUpToHz): with --modes 20, the full model's 20th
    // mode; with a cut-off between the full model's 10th and 11th modes, the cut-off, and the held
    // body has the full model's ten modes below it.
    EXPECT_NEAR(modal::normalModesUpToHz(body) / full(19), 1.0, 1e-9);
    auto cut = settings(0);
    cut.cutoffHz = 0.5 * (full(9) + full(10));
    ASSERT_GT(full(10) / full(9), 1.0 + 1e-6);  // a gap for the cut-off
    const auto cutBody =
        modal::CraigBamptonReducer(m, kIron)
            .reduce({modal::parseInterface("top_seat:rbe2"), modal::parseInterface("bottom_seat:rbe2")}, cut);
    EXPECT_EQ(cutBody.settings.normalModes, 10);
    EXPECT_EQ(modal::normalModesUpToHz(cutBody), cut.cutoffHz);
    const Eigen::VectorXd heldCut = modal::heldFrequenciesHz(cutBody, {0, 1});
    for (int k = 0; k < 10; ++k) EXPECT_NEAR(heldCut(k) / full(k), 1.0, 1e-9) << "mode " << k + 1;
    EXPECT_GT(heldCut(10), cut.cutoffHz);
    std::printf("covered: %.2f Hz with 20 modes (full model's 20th %.2f Hz); cut-off %.2f Hz keeps %d modes\n",
                modal::normalModesUpToHz(body), full(19), cut.cutoffHz, cutBody.settings.normalModes);
}

TEST(CraigBampton, QuasiStaticSkirtBumpWithinTwoPercent) {
    const fem::Mesh& m = piston();
    const Eigen::VectorXd p = bump(m, "skirt", 5e6, -0.008, 0.008, 0.3);
    const Eigen::VectorXd f = fem::ElasticityAssembler(m).pressureLoad(fem::BoundarySurface(m, "skirt"), p);
    const Eigen::VectorXd ref = fullStatic(m, kAlu, f, {"pin_bore"});
    modal::CraigBamptonReducer reducer(m, kAlu);
    double errors[2];
    for (int withCorrection : {0, 1}) {
        const auto body = reducer.reduce({modal::parseInterface("pin_bore:rbe2")},
                                         settings(30, withCorrection ? std::vector<std::string>{"skirt"}
                                                                     : std::vector<std::string>{}));
        modal::ModalSuperposition sup(body);
        const Eigen::VectorXd u = sup.displacement(sup.quasiStatic(sup.modalForce(f), {0}));
        errors[withCorrection] = radialError(m, "skirt", u, ref);
    }
    std::printf("skirt bump, max radial error: %.2f %% without, %.2f %% with static correction\n",
                100 * errors[0], 100 * errors[1]);
    EXPECT_LT(errors[1], 0.02);
    EXPECT_LT(errors[1], errors[0]);
}

// Max error of the axial displacement on a surface relative to its largest |u_z| there.
double axialError(const fem::Mesh& m, const std::string& surface, const Eigen::VectorXd& u,
                  const Eigen::VectorXd& ref) {
    double err = 0.0, scale = 0.0;
    for (auto n : m.groupNodes(surface)) {
        err = std::max(err, std::abs(u(3 * n + 2) - ref(3 * n + 2)));
        scale = std::max(scale, std::abs(ref(3 * n + 2)));
    }
    return err / scale;
}

// The cylinder's gas pressure on the flat crown: the z–θ patterns cannot describe it, one
// uniform-pressure vector spans it exactly (docs/modal.md, "The basis").
TEST(CraigBampton, QuasiStaticCrownPressureMatchesFullModel) {
    const fem::Mesh& m = piston();
    const fem::BoundarySurface crownSurface(m, "crown");
    const Eigen::VectorXd f = fem::ElasticityAssembler(m).pressureLoad(crownSurface, 5e6);
    const Eigen::VectorXd ref = fullStatic(m, kAlu, f, {"pin_bore"});
    modal::CraigBamptonReducer reducer(m, kAlu);
    double crown[2], skirt[2];
    for (int withPattern : {0, 1}) {
        auto s = settings(20, {"skirt"});  // as scripts/example.sh reduces the piston
        if (withPattern) s.pressurePatterns = {"crown"};
        const auto body = reducer.reduce({modal::parseInterface("pin_bore:rbe2")}, s);
        modal::ModalSuperposition sup(body);
        const Eigen::VectorXd u = sup.displacement(sup.quasiStatic(sup.modalForce(f), {0}));
        crown[withPattern] = axialError(m, "crown", u, ref);
        skirt[withPattern] = radialError(m, "skirt", u, ref);
    }
    std::printf("crown pressure 5 MPa: max crown u_z error %.3e without, %.3e with the pattern; max skirt radial "
                "error %.3e without, %.3e with\n",
                crown[0], crown[1], skirt[0], skirt[1]);
    // The pattern spans the load: both errors are round-off (measured 2.5e-12 and 8.6e-12).
    EXPECT_LT(crown[1], 1e-8);
    EXPECT_LT(skirt[1], 1e-8);
    EXPECT_LT(crown[1], crown[0]);
    EXPECT_LT(skirt[1], skirt[0]);
}

TEST(CraigBampton, QuasiStaticLinerBandLoadWithinTwoPercent) {
    const fem::Mesh& m = liner();
    // A skirt-sized band (Gaussian half-width 15 mm) on the thrust side, mid-stroke.
    const Eigen::VectorXd p = bump(m, "bore", 3e6, -0.08, 0.015, 0.4);
    const Eigen::VectorXd f = fem::ElasticityAssembler(m).pressureLoad(fem::BoundarySurface(m, "bore"), p);
    const Eigen::VectorXd ref = fullStatic(m, kIron, f, {"top_seat", "bottom_seat"});
    modal::CraigBamptonReducer reducer(m, kIron);
    double errors[2];
    for (int withCorrection : {0, 1}) {
        auto s = settings(30, withCorrection ? std::vector<std::string>{"bore"} : std::vector<std::string>{});
        s.axialHats = 17;  // 10 mm spacing along the 160 mm bore: the load travels with the piston
        const auto body = reducer.reduce(
            {modal::parseInterface("top_seat:rbe2"), modal::parseInterface("bottom_seat:rbe2")}, s);
        modal::ModalSuperposition sup(body);
        const Eigen::VectorXd u = sup.displacement(sup.quasiStatic(sup.modalForce(f), {0, 1}));
        errors[withCorrection] = radialError(m, "bore", u, ref);
    }
    std::printf("liner band, max radial error: %.2f %% without, %.2f %% with static correction\n",
                100 * errors[0], 100 * errors[1]);
    EXPECT_LT(errors[1], 0.02);
}

TEST(CraigBampton, BadInputGivesClearErrors) {
    modal::CraigBamptonReducer reducer(piston(), kAlu);
    using test::errorOf;
    using testing::HasSubstr;
    EXPECT_THAT(errorOf([&] { reducer.reduce({modal::parseInterface("pin:rbe2")}, settings(5)); }),
                HasSubstr("no physical group 'pin'"));
    EXPECT_THAT(errorOf([&] { modal::parseInterface("pin_bore:rbe9"); }), HasSubstr("expected rbe2 or rbe3"));
    EXPECT_THAT(errorOf([&] { reducer.reduce({}, settings(5)); }), HasSubstr("no interface"));
    EXPECT_THAT(errorOf([&] {
                    reducer.reduce({modal::parseInterface("pin_bore"), modal::parseInterface("pin_bore")}, settings(5));
                }),
                HasSubstr("overlapping interfaces"));
    EXPECT_THAT(errorOf([&] { reducer.reduce({modal::parseInterface("pin_bore")}, settings(10000000)); }),
                HasSubstr("normal modes requested"));
    const auto withPatterns = [](std::vector<std::string> groups) {
        auto s = settings(5);
        s.pressurePatterns = std::move(groups);
        return s;
    };
    EXPECT_THAT(errorOf([&] { reducer.reduce({modal::parseInterface("pin_bore")}, withPatterns({"nosuchgroup"})); }),
                HasSubstr("pressure pattern 'nosuchgroup': mesh"));
    EXPECT_THAT(errorOf([&] { reducer.reduce({modal::parseInterface("pin_bore")}, withPatterns({"crown", "crown"})); }),
                HasSubstr("pressure pattern 'crown' is listed twice"));
    EXPECT_THAT(errorOf([&] { reducer.reduce({modal::parseInterface("pin_bore")}, withPatterns({"pin_bore"})); }),
                HasSubstr("pressure pattern 'pin_bore' is also an interface"));
    // A band of a group: well formed and not empty.
    for (const char* bad : {"crown@", "crown@0.03", "crown@0.03:0.02", "crown@a:b", "@0:1", "crown@:"})
        EXPECT_THAT(errorOf([&] { reducer.reduce({modal::parseInterface("pin_bore")}, withPatterns({bad})); }),
                    HasSubstr("expected GROUP or GROUP@ZLOW:ZHIGH"))
            << bad;
    EXPECT_THAT(errorOf([&] { reducer.reduce({modal::parseInterface("pin_bore")}, withPatterns({"crown@5:6"})); }),
                HasSubstr("pressure pattern 'crown@5:6': surface group 'crown' of mesh"));
}

// An RBE3 interface adds no constraint: the reduced free beam converges to the plain free
// beam (no link at all), an independent reference.
TEST(CraigBampton, Rbe3InterfaceConvergesToThePlainFreeBody) {
    const fem::Mesh m = fem::readMesh(test::dataPath("beam.geo"), {2, 0.01});
    const fem::ElasticMaterial steel{2.1e11, 0.3, 7850.0};
    fem::EigenmodeOptions opt;
    opt.count = 12;
    const Eigen::VectorXd plain = fem::analyseModes(m, steel, {}, opt).modes.frequenciesHz();
    const auto body = modal::CraigBamptonReducer(m, steel).reduce({modal::parseInterface("clamped:rbe3")}, settings(20));
    ASSERT_EQ(std::count(body.rigidBody.begin(), body.rigidBody.end(), 1), 6);
    for (int k = 0; k < 6; ++k) EXPECT_EQ(body.frequenciesHz(k), 0.0) << "rigid-body mode " << k + 1 << " as 0 Hz";
    for (int k = 6; k < 12; ++k) EXPECT_NEAR(body.frequenciesHz(k) / plain(k), 1.0, 1e-3) << "mode " << k + 1;
}

TEST(CraigBampton, InterfaceThatCannotHoldTheBodyIsReported) {
    const fem::Mesh m = fem::readMesh(test::dataPath("two_blocks.geo"), {1, 0});
    modal::CraigBamptonReducer reducer(m, kIron);
    EXPECT_THAT(test::errorOf([&] { reducer.reduce({modal::parseInterface("left_end")}, settings(4)); }),
                testing::HasSubstr("do not hold the body"));
}

// Degenerate input: patterns that load nothing are dropped, not fatal; rigid-body flags do
// not depend on how many (or how stiff) basis vectors were computed; collinear RBE2 sets
// are refused with a reason.
TEST(CraigBampton, DegeneratePatternsAreDroppedAndRigidModesCountedRight) {
    const fem::Mesh m = fem::readMesh(test::dataPath("cube.geo"), {2, 0.5});
    auto s = settings(6, {"xmin"});  // face x = 0: θ = ±π/2 everywhere, so cos θ, sin 2θ, ... vanish
    modal::ReductionReport rep;
    const auto body = modal::CraigBamptonReducer(m, kIron).reduce({modal::parseInterface("xmax:rbe2")}, s, &rep);
    EXPECT_GT(rep.droppedDependent, 0);
    EXPECT_EQ(std::count(body.rigidBody.begin(), body.rigidBody.end(), 1), 6);
    // A free unit cube of iron: its first elastic mode is far from zero (~1 kHz scale).
    EXPECT_GT(body.frequenciesHz(6), 100.0);
}

TEST(CraigBampton, CollinearRigidInterfaceIsRefused) {
    const fem::Mesh m = fem::readMesh(test::dataPath("cube.geo"), {1, 0.5});
    fem::DofMap dofs(m.numNodes(), 3);
    const std::vector<fem::Index> one{0};
    EXPECT_THAT(test::errorOf([&] { dofs.addRigidLink(one, m.nodes, Eigen::Vector3d::Zero()); }),
                testing::HasSubstr("collinear"));
}
