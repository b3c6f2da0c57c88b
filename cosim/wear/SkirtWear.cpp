#include "cosim/wear/SkirtWear.hpp"

#include "cosim/contact/LinerOffsetRange.hpp"
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/coupling/PistonSimulation.hpp"

#include <algorithm>
#include <limits>
#include <numbers>

namespace flexehd::cosim {
namespace {

// The liner's z range the skirt's grid covers over a revolution (liner frame, m).
std::pair<double, double> skirtReach(const PistonSimulation& sim, const lube::FilmGrid& g) {
    const LinerOffsetRange r = linerOffsetRange([&sim](double deg) { return sim.linerOffset(deg); });
    return {r.low + g.z(0), r.high + g.z(g.nAxial() - 1)};
}

ArchardWear makeWear(const EngineCase& c, const PistonSimulation& sim, const lube::FilmGrid& g) {
    const auto [lo, hi] = skirtReach(sim, g);
    return ArchardWear(g, c.contact.pistonWearCoefficient, c.contact.linerWearCoefficient, lo, hi);
}

std::size_t indexOf(const PistonSimulation& sim, const FilmContact& contact) {
    const auto& all = sim.contacts();
    return std::size_t(std::find_if(all.begin(), all.end(), [&](const auto& c) { return c.get() == &contact; }) -
                       all.begin());
}

}  // namespace

bool SkirtWear::wanted(const EngineCase& c) {
    return c.contact.pistonWearCoefficient > 0.0 || c.contact.linerWearCoefficient > 0.0;
}

SkirtWear::SkirtWear(const EngineCase& c, const PistonSimulation& sim)
    : sim_(sim),
      skirt_(sim.contact<SkirtContact>()),
      index_(indexOf(sim, skirt_)),
      wear_(makeWear(c, sim, skirt_.grid())) {}

const lube::FilmGrid& SkirtWear::grid() const { return skirt_.grid(); }

void SkirtWear::stepAccepted(const AcceptedStep& step) {
    const double deg = step.state.crankDeg;
    wear_.add(step.evaluation.films[index_].pc, sim_.kinematics().at(deg).velocity, sim_.linerOffset(deg), step.seconds);
}

void SkirtWear::cycleEnded(const CycleEnd& /*end*/) {
    // The largest mean rates of the cycle's maps and where they are (docs/coupling.md §7).
    wear_.finishCycle();
    const lube::FilmGrid& g = skirt_.grid();
    Eigen::Index kp = 0, kl = 0;
    maxima_.pistonRate = wear_.pistonRate().maxCoeff(&kp) * 3600.0;
    maxima_.pistonZ = g.z(g.axialIndex(int(kp)));
    maxima_.pistonThetaDeg = g.theta(g.thetaIndex(int(kp))) * 180.0 / std::numbers::pi;
    maxima_.linerRate = wear_.linerRate().maxCoeff(&kl) * 3600.0;
    maxima_.linerDepth = -wear_.linerCellZ(int(kl) / g.nTheta());
    maxima_.linerThetaDeg = g.theta(int(kl) % g.nTheta()) * 180.0 / std::numbers::pi;
}

}  // namespace flexehd::cosim
