// Craig–Bampton reduction of a body on Winkler spring supports (ReductionSettings::supports):
// the springs must be in every vector of the basis. Checked on tests/fem/data/bar.geo
// (L = 0.1 m along x, a × a = 0.02 × 0.02 m) against the full FE model with the same spring
// matrix (held frequencies: fixed-interface modes; static response to a uniform end pressure:
// the static correction) and against the closed form of a stiff bar's rigid motions on its
// side springs (constraint modes and inertia relief, reference node free).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "../fem/TestData.hpp"
#include "fem/BoundarySurface.hpp"
#include "fem/DofMap.hpp"
#include "fem/EigenmodeSolver.hpp"
#include "fem/ElasticityAssembler.hpp"
#include "fem/MeshReader.hpp"
#include "fem/StaticSolver.hpp"
#include "fem/SurfaceSpring.hpp"
#include "modal/CraigBamptonReducer.hpp"
#include "modal/ModalSuperposition.hpp"

using namespace flexehd;

namespace {
constexpr double kL = 0.1, kA = 0.02;
const fem::ElasticMaterial kSteel{2.1e11, 0.3, 7850.0};

const fem::Mesh& bar() {
    static const fem::Mesh m = fem::readMesh(test::dataPath("bar.geo"), {2, 0.01});
    return m;
}

modal::ReductionSettings settings(int modes, std::vector<std::string> supports) {
    modal::ReductionSettings s;
    s.normalModes = modes;
    s.supports = std::move(supports);
    return s;
}

// Full model: K + K_s of the support on `spring`, every node of `held` fixed (a held RBE2 reference).
struct FullModel {
    fem::SparseMatrix K, M;
    fem::DofMap dofs;
    FullModel(const fem::Mesh& m, const std::string& held, const std::string& spring, double k)
        : dofs(m.numNodes(), 3) {
        fem::ElasticityAssembler a(m);
        K = a.stiffness(kSteel) + fem::surfaceSpringMatrix(fem::BoundarySurface(m, spring), k);
        M = a.mass(kSteel.rho);
        dofs.constrain(m.groupNodes(held), fem::kAllComponents);
        dofs.finalize();
    }
};
}  // namespace

// With end0 held and a cut-off above the frequencies compared, the held body's frequencies are
// the full model's held modes (docs/modal.md, "Command line"), here with springs of K = 2e10 N/m³
// on end1 (K A = 8e6 N/m, about the cantilever's tip stiffness 3EI/L³ = 8.4e6 N/m).
TEST(SpringSupport, HeldFrequenciesAreTheFullModelsWithTheSameSprings) {
    const double k = 2e10;
    FullModel full(bar(), "end0", "end1", k);
    fem::EigenmodeOptions opt;
    opt.count = 6;
    const Eigen::VectorXd ref =
        fem::solveEigenmodes(full.dofs.reduce(full.K), full.dofs.reduce(full.M), opt).frequenciesHz();
    modal::CraigBamptonReducer reducer(bar(), kSteel);
    const auto itf = std::vector{modal::parseInterface("end0:rbe2")};
    const Eigen::VectorXd held = modal::heldFrequenciesHz(reducer.reduce(itf, settings(12, {"end1:2e10"})), {0});
    const Eigen::VectorXd bare = modal::heldFrequenciesHz(reducer.reduce(itf, settings(12, {})), {0});
    double worst = 0.0;
    for (int i = 0; i < 6; ++i) worst = std::max(worst, std::abs(held(i) / ref(i) - 1.0));
    std::printf("held, end1 on springs: first %.6g Hz (%.6g Hz without), worst error of 6 vs full %.3g\n", held(0),
                bare(0), worst);
    EXPECT_LT(worst, 1e-8);  // measured 2.2e-13
    EXPECT_GT(held(0), 1.3 * bare(0));  // the support stiffens the first bending pair
}

// A uniform pressure vector on end1 spans the load: the held quasi-static response equals the
// full model's with the same springs to round-off only if the static correction saw them.
TEST(SpringSupport, StaticResponseToAUniformEndPressureIsTheFullModels) {
    const double k = 2e12;  // K A = 8e8 N/m, comparable to the bar's axial E A / L = 8.4e8 N/m
    FullModel full(bar(), "end0", "end1", k);
    const fem::BoundarySurface end1(bar(), "end1");
    const Eigen::VectorXd f = fem::ElasticityAssembler(bar()).pressureLoad(end1, 1e6);
    const Eigen::VectorXd ref =
        full.dofs.expand(fem::StaticSolver(full.dofs.reduce(full.K)).solve(full.dofs.reduceLoad(f, full.K)));
    auto s = settings(10, {"end1:2e12"});
    s.pressurePatterns = {"end1"};
    const auto body = modal::CraigBamptonReducer(bar(), kSteel).reduce({modal::parseInterface("end0:rbe2")}, s);
    modal::ModalSuperposition sup(body);
    const Eigen::VectorXd u = sup.displacement(sup.quasiStatic(sup.modalForce(f), {0}));
    const double error = (u - ref).lpNorm<Eigen::Infinity>() / ref.lpNorm<Eigen::Infinity>();
    // Closed form of the axial end displacement, bar and springs in parallel: p A / (E A / L + K A)
    // (1-D; the 3-D bar's Poisson effect and the end0 clamp make it stiffer: measured 0.43 %).
    double ux = 0.0;
    const auto nodes = bar().groupNodes("end1");
    for (auto n : nodes) ux += u(3 * n) / double(nodes.size());
    const double oneD = -1e6 / (kSteel.E / kL + k);
    std::printf("end pressure on springs: max error vs full %.3g, mean u_x %.6g m (1-D %.6g m)\n", error, ux, oneD);
    EXPECT_LT(error, 1e-8);  // measured 2.3e-14
    EXPECT_NEAR(ux / oneD, 1.0, 0.01);
}

// Reference node free, springs on the four sides, E = 1e13 Pa so that the bar is rigid next to
// them: the reduced body's own lowest six frequencies are its rigid motions on the foundation
// (Winkler 1867). Sides symmetric about the centre of mass, m = ρ a² L, side area 4 a L:
//   translations x, y, z:   ω² = 4 K / (ρ a),
//   rocking about y and z:  ω² = 4 K (L² + 2a²) / (ρ a (L² + a²)),
//   twist about x:          ω² = 8 K / (ρ a).
TEST(SpringSupport, StiffBarOnSideSpringsWithAFreeInterfaceHasTheRigidOnFoundationFrequencies) {
    const fem::ElasticMaterial stiff{1e13, 0.3, 7850.0};
    const double k = 1.55e7;  // translations at about 100 Hz
    auto s = settings(6, {"sides:1.55e7"});
    const auto body = modal::CraigBamptonReducer(bar(), stiff).reduce({modal::parseInterface("end0:rbe2")}, s);
    const double t = 4 * k / (stiff.rho * kA);
    const double rock = t * (kL * kL + 2 * kA * kA) / (kL * kL + kA * kA), twist = 2 * t;
    const double expected[6] = {t, t, t, rock, rock, twist};
    EXPECT_EQ(std::count(body.rigidBody.begin(), body.rigidBody.end(), 1), 0);
    double worst = 0.0;
    for (int i = 0; i < 6; ++i) {
        const double omega = 2 * std::numbers::pi * body.frequenciesHz(i);
        worst = std::max(worst, std::abs(omega * omega / expected[i] - 1.0));
    }
    std::printf("stiff bar on side springs, free interface: f = %.6g Hz, worst error of ω² %.3g\n",
                body.frequenciesHz(0), worst);
    EXPECT_LT(worst, 1e-6);  // measured 8.1e-8: the bar's own elasticity
    EXPECT_GT(body.frequenciesHz(6), 100 * body.frequenciesHz(5));  // then the elastic modes
}

TEST(SpringSupport, BadSupportsGiveClearErrors) {
    modal::CraigBamptonReducer reducer(bar(), kSteel);
    const auto itf = std::vector{modal::parseInterface("end0:rbe2")};
    const auto message = [&](std::vector<std::string> supports) {
        try {
            reducer.reduce(itf, settings(4, std::move(supports)));
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message({"end0:1e9"}).find("--support 'end0:1e9': group 'end0' is also an interface"), std::string::npos);
    EXPECT_NE(message({"nope:1e9"}).find("--support 'nope:1e9': "), std::string::npos);
    EXPECT_NE(message({"nope:1e9"}).find("no physical group 'nope'"), std::string::npos);
    EXPECT_NE(message({"bar:1e9"}).find("is a volume"), std::string::npos);
    EXPECT_NE(message({"end1:1e9", "end1:2e9"}).find("has a support already"), std::string::npos);
    for (const std::string bad : {"end1", "end1:", ":1e9", "end1:abc", "end1:1e9x"})
        EXPECT_NE(message({bad}).find("--support '" + bad + "': "), std::string::npos) << bad;
    for (const std::string bad : {"end1:0", "end1:-1e9", "end1:inf", "end1:nan"})
        EXPECT_NE(message({bad}).find("K must be finite and > 0"), std::string::npos) << bad;
}
