#include "cosim/wear/SkirtWear.hpp"

#include "cosim/coupling/PistonSimulation.hpp"

#include <algorithm>
#include <limits>
#include <numbers>

namespace flexehd::cosim {
namespace {

// The liner's z range the skirt's grid covers over a revolution (liner frame, m).
std::pair<double, double> skirtReach(const PistonSimulation& sim) {
    const lube::FilmGrid& g = sim.film().grid();
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int k = 0; k <= 1440; ++k) {
        lo = std::min(lo, sim.linerOffset(0.25 * k) + g.z(0));
        hi = std::max(hi, sim.linerOffset(0.25 * k) + g.z(g.nAxial() - 1));
    }
    return {lo, hi};
}

ArchardWear makeWear(const EngineCase& c, const PistonSimulation& sim) {
    const auto [lo, hi] = skirtReach(sim);
    return ArchardWear(sim.film().grid(), c.contact.pistonWearCoefficient, c.contact.linerWearCoefficient, lo, hi);
}

}  // namespace

bool SkirtWear::wanted(const EngineCase& c) {
    return c.contact.pistonWearCoefficient > 0.0 || c.contact.linerWearCoefficient > 0.0;
}

SkirtWear::SkirtWear(const EngineCase& c, const PistonSimulation& sim) : sim_(sim), wear_(makeWear(c, sim)) {}

void SkirtWear::stepAccepted(const AcceptedStep& step) {
    // The skirt is the run's first contact.
    const double deg = step.state.crankDeg;
    wear_.add(step.evaluation.films.front().pc, sim_.kinematics().at(deg).velocity, sim_.linerOffset(deg), step.seconds);
}

void SkirtWear::cycleEnded(const CycleEnd& /*end*/) {
    // The largest mean rates of the cycle's maps and where they are (docs/coupling.md §7).
    wear_.finishCycle();
    const lube::FilmGrid& g = sim_.film().grid();
    Eigen::Index kp = 0, kl = 0;
    maxima_.pistonRate = wear_.pistonRate().maxCoeff(&kp) * 3600.0;
    maxima_.pistonZ = g.z(g.axialIndex(int(kp)));
    maxima_.pistonThetaDeg = g.theta(g.thetaIndex(int(kp))) * 180.0 / std::numbers::pi;
    maxima_.linerRate = wear_.linerRate().maxCoeff(&kl) * 3600.0;
    maxima_.linerDepth = -wear_.linerCellZ(int(kl) / g.nTheta());
    maxima_.linerThetaDeg = g.theta(int(kl) % g.nTheta()) * 180.0 / std::numbers::pi;
}

}  // namespace flexehd::cosim
