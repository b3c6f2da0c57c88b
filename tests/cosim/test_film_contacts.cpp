// The master's film contacts add up (docs/coupling.md §1, "Film contacts"): the isoviscous
// Reynolds problem with the cavitation pressure at gauge zero is positively homogeneous in the
// viscosity — for the same film thickness and squeeze rate, p(η/2) = p(η)/2 exactly, and so are
// the shear stresses — so a skirt whose film is carried by two contacts of half the viscosity
// each (the asperity contact and its boundary friction in the first only) is the same skirt as
// one contact of the whole viscosity. The runs must agree in the secondary motion, in the modal
// coordinates of a flexible piston (modal loads, coupling residual and the coupled Newton
// Jacobian summed over the contacts) and in the pressure field (the first contact's is half).
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "CliRunner.hpp"
#include "SmallEngineCase.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <unistd.h>
#include <vector>

using namespace flexehd;
using namespace flexehd::cosim;
namespace fs = std::filesystem;

namespace {

std::vector<Snapshot> snapshots(PistonSimulation& sim, double spanDeg) {
    std::vector<Snapshot> snaps;
    SimulationCallbacks cb;
    cb.onSnapshot = [&](const Snapshot& s) { snaps.push_back(s); };
    sim.run(cb, spanDeg);
    return snaps;
}

// The case's skirt as one contact, and as two contacts of half its viscosity; the second
// without asperity contact (its floor is then 0.01 c, the first's 0.05 σ: the comparison is
// over a span where no node is floored, checked by the contact pressure being zero).
void compareSplitSkirt(EngineCase c, double spanDeg, double& worstLateral, double& worstTilt, double& worstPressure,
                       double& worstModal, int& compared) {
    c.output.vtkEveryDeg = 10.0;
    PistonSimulation whole(c);
    const std::vector<Snapshot> a = snapshots(whole, spanDeg);

    EngineCase half = c;
    half.lubricant.viscosity = 0.5 * c.lubricant.viscosity;
    EngineCase halfDry = half;
    halfDry.contact.compositeModulus = 0.0;
    PistonSimulation split(half);
    split.addContact(std::make_unique<SkirtContact>(halfDry, CaseBodies{split.pistonBody(), split.linerBody()},
                                                    [&split](double deg) { return split.linerOffset(deg); }));
    const std::vector<Snapshot> b = snapshots(split, spanDeg);

    ASSERT_EQ(a.size(), b.size());
    const double reach = std::max(c.piston.skirtTop, -c.piston.skirtBottom);
    // The pressure's scale: the whole skirt's peak over the span. (Near a dead centre the film
    // carries little but its squeeze, a difference of velocities, which the runs' motion
    // differences change by a larger part: 442 against 447 Pa at BDC in the flexible test, 3e-5 of
    // the span's peak.)
    double peak = 1.0;
    for (const Snapshot& s : a) peak = std::max(peak, s.pressure.cwiseAbs().maxCoeff());
    for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_NEAR(a[i].continuousDeg, b[i].continuousDeg, 1e-9);
        if (a[i].contactPressure.cwiseAbs().maxCoeff() > 0.0) continue;  // floors differ: not comparable
        ++compared;
        worstLateral = std::max(worstLateral, std::abs(a[i].lateral - b[i].lateral) / c.piston.clearance);
        worstTilt = std::max(worstTilt, std::abs(a[i].tilt - b[i].tilt) * reach / c.piston.clearance);
        worstPressure = std::max(worstPressure, (a[i].pressure - 2.0 * b[i].pressure).cwiseAbs().maxCoeff() / peak);
        if (a[i].pistonModal.size()) {  // the film change of the modal difference, in clearances
            Eigen::VectorXd dh;
            whole.contact<SkirtContact>().piston()->filmChange(a[i].pistonModal - b[i].pistonModal, 0.0, dh);
            worstModal = std::max(worstModal, dh.cwiseAbs().maxCoeff() / c.piston.clearance);
        }
    }
}

}  // namespace

// Bars: halving the viscosity scales every operation of the film solvers by a power of two,
// which is exact in binary floating point, so the two runs differ by round-off in the sums over
// contacts only — unless round-off flips one step's convergence decision, which leaves them apart
// by at most the Newton tolerance, an update of 1e-5 of the clearance (docs/coupling.md §1), and
// by the coupling tolerance in the film change of the modal coordinates (1e-5 c in the flexible
// test). The bars are ten times that on the motion and on the modal coordinates' film change
// (in clearances, as the coupling tolerance: relative to the largest modal coordinate the bar
// would tighten without bound where the skirt barely deflects); the pressure, which
// changes by about 3 δh/h with the film thickness h ≥ 0.1 c here, gets 1e-2 of its peak over the span.
constexpr double kMotionBar = 1e-4, kPressureBar = 1e-2;

TEST(FilmContacts, TwoHalfViscosityContactsAreTheWholeSkirtRigid) {
    double lateral = 0.0, tilt = 0.0, pressure = 0.0, modal = 0.0;
    int compared = 0;
    const EngineCase c = test::smallCase();
    compareSplitSkirt(c, 360.0, lateral, tilt, pressure, modal, compared);
    std::printf("rigid: %d snapshots, worst |de|/c %.3g, |dbeta| reach/c %.3g, |dp|/max p %.3g\n", compared, lateral,
                tilt, pressure);
    EXPECT_GE(compared, 20);
    EXPECT_LT(lateral, kMotionBar);
    EXPECT_LT(tilt, kMotionBar);
    EXPECT_LT(pressure, kPressureBar);

    // The control: the half-viscosity skirt alone (the second contact left out of the sums) is
    // far from the whole one, so the comparison above sees whether the second contact acts.
    EngineCase half = c;
    half.lubricant.viscosity = 0.5 * c.lubricant.viscosity;
    half.output.vtkEveryDeg = 10.0;
    EngineCase whole = c;
    whole.output.vtkEveryDeg = 10.0;
    PistonSimulation a(whole), b(half);
    const std::vector<Snapshot> sa = snapshots(a, 360.0), sb = snapshots(b, 360.0);
    double apart = 0.0;
    for (std::size_t i = 0; i < std::min(sa.size(), sb.size()); ++i)
        apart = std::max(apart, std::abs(sa[i].lateral - sb[i].lateral) / c.piston.clearance);
    std::printf("one half-viscosity contact alone: worst |de|/c %.3g\n", apart);
    EXPECT_GT(apart, 100.0 * kMotionBar);
}

TEST(FilmContacts, TwoHalfViscosityContactsAreTheWholeSkirtFlexible) {
    const fs::path dir = fs::temp_directory_path() / ("flexehd_contacts_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string file = (dir / "piston.h5").string();
    const auto red = test::reduceSmallPiston(file);
    ASSERT_EQ(red.status, 0) << red.err;
    for (const CouplingMethod method : {CouplingMethod::Newton, CouplingMethod::Partitioned}) {
        EngineCase c = test::smallFlexibleCase(file);
        c.coupling.method = method;
        c.coupling.elasticSqueeze = method == CouplingMethod::Newton;
        c.coupling.tolerance = 1e-5;
        c.coupling.maxIterations = 60;
        double lateral = 0.0, tilt = 0.0, pressure = 0.0, modal = 0.0;
        int compared = 0;
        compareSplitSkirt(c, 360.0, lateral, tilt, pressure, modal, compared);
        const char* name = method == CouplingMethod::Newton ? "newton" : "partitioned";
        std::printf("%s: %d snapshots, worst |de|/c %.3g, |dbeta| reach/c %.3g, |dp|/max p %.3g, max|dh(dq)|/c %.3g\n",
                    name, compared, lateral, tilt, pressure, modal);
        EXPECT_GE(compared, 20) << name;
        EXPECT_LT(lateral, kMotionBar) << name;
        EXPECT_LT(tilt, kMotionBar) << name;
        EXPECT_LT(pressure, kPressureBar) << name;
        EXPECT_LT(modal, kMotionBar) << name;
    }
    fs::remove_all(dir);
}
