// The flexible piston's gas and inertia loads (cosim/mapping/PistonBodyLoads) against the full
// finite-element model of the same mesh: the static response of the piston held at its pin bore
// to a uniform crown pressure and to the body force −ρ a(r) of its rigid acceleration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "cosim/mapping/FlexibleBody.hpp"
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/mapping/PistonBodyLoads.hpp"
#include "cosim/mapping/RingBeltLoads.hpp"
#include "PistonFullModel.hpp"
#include "fem/ElasticityAssembler.hpp"
#include "fem/MeshReader.hpp"
#include "modal/CraigBamptonReducer.hpp"

using namespace flexehd;

namespace {

const fem::ElasticMaterial kAlu{7.5e10, 0.33, 2700.0};

const fem::Mesh& piston() {
    static const fem::Mesh m = fem::readMesh(std::string(FLEXEHD_SOURCE_DIR) + "/meshes/piston.geo", {2, 0.0065});
    return m;
}

// As the example's piston (20 normal modes, skirt patterns), with or without the crown's pattern.
const modal::ReducedBody& body(bool crownPattern) {
    auto make = [](bool crown) {
        modal::ReductionSettings s;
        s.normalModes = 20;
        s.staticCorrection = {"skirt"};
        s.axialOrder = 4;
        s.circumferentialOrder = 6;
        if (crown) s.pressurePatterns = {"crown"};
        return modal::CraigBamptonReducer(piston(), kAlu).reduce({modal::parseInterface("pin_bore:rbe2@0,0,0")}, s);
    };
    if (crownPattern) {
        static const modal::ReducedBody b = make(true);
        return b;
    }
    static const modal::ReducedBody b = make(false);
    return b;
}

Eigen::VectorXd fullStatic(const Eigen::VectorXd& f) { return test::pinBoreHeldStatic(piston(), kAlu, f); }

Eigen::VectorXd inertiaForces(double lateral, double tilt, double axial) {
    return test::rigidAccelerationForces(piston(), kAlu.rho, lateral, tilt, axial);
}

// The reduced body's quasi-static displacement (pin bore held) under the loads.
Eigen::VectorXd reducedStatic(const modal::ReducedBody& b, const cosim::PistonLoadSpec& spec, double pGauge,
                              double lateral, double tilt, double axial) {
    const cosim::FlexibleBody piston(b, {"pin_bore"});
    const cosim::PistonBodyLoads loads(piston, spec, "piston.h5");
    Eigen::VectorXd f = Eigen::VectorXd::Zero(b.numModes()), q;
    loads.add(pGauge, Eigen::Vector2d(lateral, tilt), axial, nullptr, f);
    piston.quasiStatic(f, q);
    return b.shapes * q;
}

// Largest error of a displacement component over a group's nodes, relative to the largest value.
double groupError(const std::string& group, const Eigen::VectorXd& u, const Eigen::VectorXd& ref, bool radial) {
    const fem::Mesh& m = piston();
    double err = 0.0, scale = 0.0;
    for (auto n : m.groupNodes(group)) {
        Eigen::Vector3d d = Eigen::Vector3d::UnitZ();
        if (radial) d << m.nodes.col(n).head<2>().normalized(), 0.0;
        const double a = u.segment<3>(3 * n).dot(d), b = ref.segment<3>(3 * n).dot(d);
        err = std::max(err, std::abs(a - b));
        scale = std::max(scale, std::abs(b));
    }
    return err / scale;
}

}  // namespace

TEST(PistonBodyLoads, InertiaOfTheRigidAccelerationMatchesTheFullModel) {
    // A fired-cycle magnitude: 6000 m/s² axial (about 3000 rpm at TDC), the secondary motion's
    // 200 m/s² and 5e4 rad/s² (docs/coupling.md §2).
    cosim::PistonLoadSpec spec;
    spec.inertia = true;
    const double lateral = 200.0, tilt = 5e4, axial = -6000.0;
    const Eigen::VectorXd ref = fullStatic(inertiaForces(lateral, tilt, axial));
    const Eigen::VectorXd u = reducedStatic(body(false), spec, 0.0, lateral, tilt, axial);
    const double skirt = groupError("skirt", u, ref, true), crown = groupError("crown", u, ref, false);
    const double all = (u - ref).lpNorm<Eigen::Infinity>() / ref.lpNorm<Eigen::Infinity>();
    std::printf("inertia: largest displacement %.3e m; error %.2e (all nodes), %.2e (skirt radial), %.2e (crown axial)\n",
                ref.lpNorm<Eigen::Infinity>(), all, skirt, crown);
    // The inertia-relief vectors span the interior's static response to a rigid acceleration of
    // the interface exactly (docs/modal.md): equal to the orthonormalisation's round-off.
    EXPECT_LT(all, 1e-6);
    EXPECT_LT(skirt, 1e-6);
    EXPECT_LT(crown, 1e-6);
    EXPECT_LT(cosim::PistonBodyLoads(cosim::FlexibleBody(body(false), {"pin_bore"}), spec, "piston.h5").rigidFitResidual(), 1e-9);
}

TEST(PistonBodyLoads, CrownGasPressureAndInertiaTogetherMatchTheFullModel) {
    // Near firing TDC: 5 MPa on the crown, the piston decelerating at 600 m/s² (1000 rpm).
    cosim::PistonLoadSpec spec;
    spec.gasPressure = true;
    spec.inertia = true;
    const double p = 5e6, axial = -600.0;
    const fem::Mesh& m = piston();
    const Eigen::VectorXd f =
        fem::ElasticityAssembler(m).pressureLoad(fem::BoundarySurface(m, "crown"), p) + inertiaForces(0.0, 0.0, axial);
    const Eigen::VectorXd ref = fullStatic(f);
    const Eigen::VectorXd u = reducedStatic(body(true), spec, p, 0.0, 0.0, axial);
    const double skirt = groupError("skirt", u, ref, true), crown = groupError("crown", u, ref, false);
    std::printf("crown pressure and inertia: largest displacement %.3e m; error %.2e (skirt radial), %.2e (crown axial)\n",
                ref.lpNorm<Eigen::Infinity>(), skirt, crown);
    EXPECT_LT(skirt, 1e-6);
    EXPECT_LT(crown, 1e-6);
}

TEST(PistonBodyLoads, AGasLoadWithoutItsPatternIsRefusedNamingTheReduceOption) {
    cosim::PistonLoadSpec spec;
    spec.gasPressure = true;
    try {
        cosim::PistonBodyLoads(cosim::FlexibleBody(body(false), {"pin_bore"}), spec, "out/piston.h5");
        FAIL() << "a body without the crown's pattern was accepted";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("out/piston.h5"), std::string::npos) << what;
        EXPECT_NE(what.find("--pressure-pattern crown"), std::string::npos) << what;
    }
    spec.gasSurface = "no_such_group";
    try {
        cosim::PistonBodyLoads(cosim::FlexibleBody(body(true), {"pin_bore"}), spec, "out/piston.h5");
        FAIL() << "an unknown gas surface was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("'no_such_group'"), std::string::npos) << e.what();
    }
}

// The ring pack's loads on the ring belt (cosim/mapping/RingBeltLoads): the example's pack.
namespace {

const cosim::EngineCase& examplePack() {
    static const cosim::EngineCase c =
        cosim::readCaseFile(std::string(FLEXEHD_SOURCE_DIR) + "/examples/engine86/hd_rings.yaml");
    return c;
}

// As body(true), with every part of the pack's ring belt as a pattern.
const modal::ReducedBody& ringBeltBody() {
    static const modal::ReducedBody b = [] {
        modal::ReductionSettings s;
        s.normalModes = 20;
        s.staticCorrection = {"skirt"};
        s.axialOrder = 4;
        s.circumferentialOrder = 6;
        s.pressurePatterns = {"crown"};
        for (const modal::PressurePattern& p : cosim::RingBeltLoads::patterns(examplePack().rings))
            s.pressurePatterns.push_back(p.text());
        return modal::CraigBamptonReducer(piston(), kAlu).reduce({modal::parseInterface("pin_bore:rbe2@0,0,0")}, s);
    }();
    return b;
}

}  // namespace

// The bands cut the parts the pack's geometry says: the second groove's lower flank is the flat
// annulus between the groove's root (R 39.2 mm) and the land (R 42.7 mm) at z = 19.8 mm, its root
// the cylinder of R 39.2 mm over the groove's 1.5 mm (meshes/piston.geo), to the polygonal mesh's
// chordal error (about (2π/n)²/6 with n ≈ 40 edges round the circle).
TEST(RingBeltLoads, TheBandsAreTheGroovesFlanksAndRoots) {
    const fem::Mesh& m = piston();
    const double pi = std::numbers::pi, root = 39.2e-3, land = 42.7e-3;
    const double flank = fem::BoundarySurface(m, "ring_grooves", 0.0198 - 2e-5, 0.0198 + 2e-5).area();
    const double cylinder = fem::BoundarySurface(m, "ring_grooves", 0.0198 + 2e-5, 0.0213 - 2e-5).area();
    std::printf("second groove: lower flank %.5g mm² (annulus %.5g), root %.5g mm² (cylinder %.5g)\n", flank * 1e6,
                pi * (land * land - root * root) * 1e6, cylinder * 1e6, 2 * pi * root * 1.5e-3 * 1e6);
    EXPECT_NEAR(flank, pi * (land * land - root * root), 1e-2 * flank);
    EXPECT_NEAR(cylinder, 2.0 * pi * root * 1.5e-3, 1e-2 * cylinder);
}

// The pack's gas and flank forces near firing TDC, each ring in another state: the top ring pressed
// on its lower flank, the second on its upper flank, the oil-control ring in flight. The full
// model's static response to the same pressures, each part's band chosen here from the grooves'
// and lands' positions (rings.yaml) with a band of its own width, against the reduced body's.
TEST(RingBeltLoads, RingPackLoadsMatchTheFullModelsStaticResponse) {
    const cosim::EngineCase& c = examplePack();
    std::vector<cosim::RingGas> gas(3);
    gas[0] = {40e5, 40e5, 6e5, 0.0, 0.0, 2.0e4};
    gas[1] = {6e5, 6e5, 2e5, 0.0, 50e-6, -3.0e3};
    gas[2] = {2e5, 1e5, 0.0, 0.0, 30e-6, 0.0};
    const fem::Mesh& m = piston();
    const fem::ElasticityAssembler a(m);
    const double tol = 3e-5, circumference = std::numbers::pi * c.engine.bore;
    auto load = [&](const std::string& group, double lo, double hi, double p) {
        return a.pressureLoad(fem::BoundarySurface(m, group, lo, hi), p);
    };
    Eigen::VectorXd f = load("ring_lands", 0.0265, 1.0, gas[0].above) + load("ring_lands", 0.0213, 0.0253, gas[0].below) +
                        load("ring_lands", 0.0163, 0.0198, gas[1].below);
    for (std::size_t i = 0; i < 3; ++i) {
        const cosim::RingSpec& r = c.rings[i];
        const double low = r.groove.lowerFlank, high = r.grooveTop(), force = gas[i].flankForce * circumference;
        const fem::BoundarySurface lower(m, "ring_grooves", low - tol, low + tol), upper(m, "ring_grooves", high - tol, high + tol);
        f += load("ring_grooves", low + tol, high - tol, gas[i].behind);
        f += a.pressureLoad(lower, 0.5 * (gas[i].behind + gas[i].below) + std::max(force, 0.0) / lower.area());
        f += a.pressureLoad(upper, 0.5 * (gas[i].behind + gas[i].above) + std::max(-force, 0.0) / upper.area());
    }
    const Eigen::VectorXd ref = fullStatic(f);
    cosim::PistonLoadSpec spec;
    spec.ringPack = true;
    const cosim::FlexibleBody body(ringBeltBody(), {"pin_bore"});
    const cosim::PistonBodyLoads loads(body, spec, "piston.h5", c.rings, c.engine.bore);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(ringBeltBody().numModes()), q;
    loads.add(0.0, Eigen::Vector2d::Zero(), 0.0, &gas, g);
    body.quasiStatic(g, q);
    const Eigen::VectorXd u = ringBeltBody().shapes * q;
    const double skirt = groupError("skirt", u, ref, true), belt = groupError("ring_grooves", u, ref, false);
    const double all = (u - ref).lpNorm<Eigen::Infinity>() / ref.lpNorm<Eigen::Infinity>();
    std::printf("ring pack loads: largest displacement %.3e m, skirt radial %.3e m; error %.2e (all), %.2e (skirt "
                "radial), %.2e (grooves axial); %lld modes\n",
                ref.lpNorm<Eigen::Infinity>(), [&] {
                    double r = 0.0;
                    for (auto n : m.groupNodes("skirt"))
                        r = std::max(r, std::abs(ref.segment<3>(3 * n).head<2>().dot(m.nodes.col(n).head<2>().normalized())));
                    return r;
                }(),
                all, skirt, belt, static_cast<long long>(ringBeltBody().numModes()));
    EXPECT_LT(all, 1e-6);
    EXPECT_LT(skirt, 1e-6);
    EXPECT_LT(belt, 1e-6);
}

TEST(RingBeltLoads, ABodyWithoutTheBeltsPatternsIsRefusedNamingEveryOption) {
    const cosim::EngineCase& c = examplePack();
    cosim::PistonLoadSpec spec;
    spec.ringPack = true;
    try {
        cosim::PistonBodyLoads(cosim::FlexibleBody(body(true), {"pin_bore"}), spec, "out/piston.h5", c.rings,
                               c.engine.bore);
        FAIL() << "a body without the ring belt's patterns was accepted";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        std::printf("%s\n", what.c_str());
        EXPECT_NE(what.find("out/piston.h5"), std::string::npos) << what;
        EXPECT_NE(what.find("--pressure-pattern ring_lands@0.0265:"), std::string::npos) << what;
        EXPECT_NE(what.find("--pressure-pattern ring_grooves@0.02529:0.02531"), std::string::npos) << what;
        EXPECT_NE(what.find("--pressure-pattern ring_grooves@0.01381:0.01629"), std::string::npos) << what;
    }
}
