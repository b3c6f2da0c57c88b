// The master's film contacts add up (docs/coupling.md §1, "Film contacts"): the isoviscous
// Reynolds problem with the cavitation pressure at gauge zero is positively homogeneous in the
// viscosity — for the same film thickness and squeeze rate, p(η/2) = p(η)/2 exactly, and so are
// the shear stresses — so a skirt whose film is carried by two contacts of half the viscosity
// each is the same skirt as one contact of the whole viscosity. The runs must agree in the
// secondary motion, in the modal coordinates of a flexible piston (modal loads, coupling residual
// and the coupled Newton Jacobian summed over the contacts) and in the pressure field (each
// contact's is half). The skirt runs without asperity contact: the Greenwood–Tripp pressure does
// not scale with the viscosity, so no split into half-viscosity contacts carries it, and with it
// the film floor is 0.05 σ instead of 0.01 c (docs/lube.md §4) — a different skirt wherever the
// film comes within 4 σ of the liner, at some steps of a run even where no snapshot shows it.
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/coupling/PistonSimulation.hpp"
#include "CliRunner.hpp"
#include "SmallEngineCase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

// The largest differences of two runs' snapshots: lateral shift and tilt at the skirt's reach in
// clearances, pressure relative to a's peak over the span, and the film change of the piston's
// modal difference in clearances.
struct RunDifference {
    double lateral = 0.0, tilt = 0.0, pressure = 0.0, modal = 0.0;
};

RunDifference runDifference(const EngineCase& c, const PistonSimulation& sim, const std::vector<Snapshot>& a,
                            const std::vector<Snapshot>& b) {
    RunDifference d;
    EXPECT_EQ(a.size(), b.size());
    const double reach = std::max(c.piston.skirtTop, -c.piston.skirtBottom);
    // The pressure's scale: the whole skirt's peak over the span. (Near a dead centre the film
    // carries little but its squeeze, a difference of velocities, which the runs' motion
    // differences change by a larger part.)
    double peak = 1.0;
    for (const Snapshot& s : a) peak = std::max(peak, s.pressure.cwiseAbs().maxCoeff());
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
        EXPECT_NEAR(a[i].continuousDeg, b[i].continuousDeg, 1e-9);
        d.lateral = std::max(d.lateral, std::abs(a[i].lateral - b[i].lateral) / c.piston.clearance);
        d.tilt = std::max(d.tilt, std::abs(a[i].tilt - b[i].tilt) * reach / c.piston.clearance);
        d.pressure = std::max(d.pressure, (a[i].pressure - b[i].pressure).cwiseAbs().maxCoeff() / peak);
        if (a[i].pistonModal.size()) {  // the film change of the modal difference, in clearances
            Eigen::VectorXd dh;
            sim.contact<SkirtContact>().piston()->filmChange(a[i].pistonModal - b[i].pistonModal, 0.0, dh);
            d.modal = std::max(d.modal, dh.cwiseAbs().maxCoeff() / c.piston.clearance);
        }
    }
    return d;
}

EngineCase withoutAsperityContact(EngineCase c) {
    c.contact.compositeModulus = 0.0;
    c.output.vtkEveryDeg = 10.0;
    return c;
}

// The case's skirt (without asperity contact) as one contact, its snapshots in `whole`, and as
// two contacts of half its viscosity, whose pressures are doubled (each carries half the film's).
RunDifference compareSplitSkirt(const EngineCase& c, double spanDeg, std::vector<Snapshot>& whole) {
    PistonSimulation one(c);
    whole = snapshots(one, spanDeg);
    EngineCase half = c;
    half.lubricant.viscosity = 0.5 * c.lubricant.viscosity;
    PistonSimulation split(half);
    split.addContact(std::make_unique<SkirtContact>(half, CaseBodies{split.pistonBody(), split.linerBody()},
                                                    [&split](double deg) { return split.linerOffset(deg); }));
    std::vector<Snapshot> b = snapshots(split, spanDeg);
    for (Snapshot& s : b) s.pressure *= 2.0;
    return runDifference(c, one, whole, b);
}

}  // namespace

// Bars: halving the viscosity scales every operation of the film solvers by a power of two,
// which is exact in binary floating point, so the two runs differ by round-off in the sums over
// contacts only — and by where that round-off leaves each step's iteration within its
// tolerances: an update of 1e-5 of the clearance (docs/coupling.md §1) and, with a flexible body,
// the coupling tolerance in the film change of the modal coordinates (1e-5 c in the flexible
// test), carried along the run's 722 steps. How far round-off alone carries a run, the whole
// skirt's shows against itself with its viscosity changed by one part in 1e13 (the coupled
// Newton run: 2e-5 to 6e-5 of the clearance in the tilt, measured on one machine). The bars on the
// motion and on the modal coordinates' film change (in clearances, as the coupling tolerance:
// relative to the largest modal coordinate the bar would tighten without bound where the skirt
// barely deflects) are ten times that spread, and at least ten times the update tolerance; the
// pressure, which changes by about 3 δh/h with the film thickness h, gets 1e-2 of its peak over
// the span. Each run is compared at its 36 snapshots, one every 10°.
constexpr double kMotionBar = 1e-4, kPressureBar = 1e-2;

// The whole skirt's run (its snapshots `whole`) against itself with its viscosity changed by one
// part in 1e13.
RunDifference roundOffSpread(const EngineCase& c, double spanDeg, const std::vector<Snapshot>& whole) {
    EngineCase nudged = c;
    nudged.lubricant.viscosity *= 1.0 + 1e-13;
    PistonSimulation again(nudged);
    return runDifference(c, again, whole, snapshots(again, spanDeg));
}

// The half-viscosity skirt alone (the second contact left out of the sums) against the whole.
RunDifference oneHalfAlone(const EngineCase& c, double spanDeg, const std::vector<Snapshot>& whole) {
    EngineCase half = c;
    half.lubricant.viscosity = 0.5 * c.lubricant.viscosity;
    PistonSimulation alone(half);
    return runDifference(c, alone, whole, snapshots(alone, spanDeg));
}

TEST(FilmContacts, TwoHalfViscosityContactsAreTheWholeSkirtRigid) {
    const EngineCase c = withoutAsperityContact(test::smallCase());
    std::vector<Snapshot> whole;
    const RunDifference d = compareSplitSkirt(c, 360.0, whole);
    const RunDifference spread = roundOffSpread(c, 360.0, whole);
    const double motionBar = std::max(kMotionBar, 10.0 * std::max(spread.lateral, spread.tilt));
    std::printf("rigid: %zu snapshots, worst |de|/c %.3g, |dbeta| reach/c %.3g, |dp|/max p %.3g; the whole skirt "
                "against itself at a viscosity 1e-13 apart: %.3g, %.3g, %.3g\n",
                whole.size(), d.lateral, d.tilt, d.pressure, spread.lateral, spread.tilt, spread.pressure);
    EXPECT_EQ(whole.size(), 36u);
    EXPECT_LT(d.lateral, motionBar);
    EXPECT_LT(d.tilt, motionBar);
    EXPECT_LT(d.pressure, kPressureBar);
    // The control: the half-viscosity skirt alone is far from the whole one, so the comparison
    // above sees whether the second contact acts.
    const RunDifference apart = oneHalfAlone(c, 360.0, whole);
    std::printf("one half-viscosity contact alone: worst |de|/c %.3g\n", apart.lateral);
    EXPECT_GT(apart.lateral, 100.0 * motionBar);
}

TEST(FilmContacts, TwoHalfViscosityContactsAreTheWholeSkirtFlexible) {
    const fs::path dir = fs::temp_directory_path() / ("flexehd_contacts_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string file = (dir / "piston.h5").string();
    const auto red = test::reduceSmallPiston(file);
    ASSERT_EQ(red.status, 0) << red.err;
    for (const CouplingMethod method : {CouplingMethod::Newton, CouplingMethod::Partitioned}) {
        EngineCase c = withoutAsperityContact(test::smallFlexibleCase(file));
        c.coupling.method = method;
        c.coupling.elasticSqueeze = method == CouplingMethod::Newton;
        c.coupling.tolerance = 1e-5;
        c.coupling.maxIterations = 60;
        std::vector<Snapshot> whole;
        const RunDifference d = compareSplitSkirt(c, 360.0, whole);
        const RunDifference spread = roundOffSpread(c, 360.0, whole);
        const double motionBar = std::max(kMotionBar, 10.0 * std::max(spread.lateral, spread.tilt));
        const double modalBar = std::max(kMotionBar, 10.0 * spread.modal);
        const char* name = method == CouplingMethod::Newton ? "newton" : "partitioned";
        std::printf("%s: %zu snapshots, worst |de|/c %.3g, |dbeta| reach/c %.3g, |dp|/max p %.3g, max|dh(dq)|/c "
                    "%.3g; the whole skirt against itself at a viscosity 1e-13 apart: %.3g, %.3g, %.3g, %.3g\n",
                    name, whole.size(), d.lateral, d.tilt, d.pressure, d.modal, spread.lateral, spread.tilt,
                    spread.pressure, spread.modal);
        EXPECT_EQ(whole.size(), 36u) << name;
        EXPECT_LT(d.lateral, motionBar) << name;
        EXPECT_LT(d.tilt, motionBar) << name;
        EXPECT_LT(d.pressure, kPressureBar) << name;
        EXPECT_LT(d.modal, modalBar) << name;
        // The control: the half-viscosity skirt alone is far from the whole one, beyond the bars.
        const RunDifference apart = oneHalfAlone(c, 360.0, whole);
        std::printf("%s, one half-viscosity contact alone: worst |de|/c %.3g, max|dh(dq)|/c %.3g\n", name,
                    apart.lateral, apart.modal);
        EXPECT_GT(apart.lateral, 10.0 * motionBar) << name;
        EXPECT_GT(apart.modal, 10.0 * modalBar) << name;
    }
    fs::remove_all(dir);
}
