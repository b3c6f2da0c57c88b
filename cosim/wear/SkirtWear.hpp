#pragma once
// SkirtWear: the wear maps of skirt and liner as an observer of the run (docs/coupling.md §7):
// Archard's rate from the skirt contact's pressure at every accepted step (ArchardWear), the
// mean-rate maps of each cycle and their largest values with where they are.
#include "cosim/case/EngineCase.hpp"
#include "cosim/coupling/RunObserver.hpp"
#include "cosim/wear/ArchardWear.hpp"

namespace flexehd::cosim {

class PistonSimulation;
class SkirtContact;

/// The largest mean wear rates of the last finished cycle (m/h) and their places: on the skirt at
/// piston-frame z and θ, on the liner at its depth below the deck and θ.
struct WearMaxima {
    double pistonRate = 0.0, pistonZ = 0.0, pistonThetaDeg = 0.0;
    double linerRate = 0.0, linerDepth = 0.0, linerThetaDeg = 0.0;
};

class SkirtWear final : public RunObserver {
public:
    /// The maps over the skirt's grid and the liner's reach of the skirt over a revolution, with
    /// the case's contact.piston_wear_coefficient and liner_wear_coefficient (m²/N).
    SkirtWear(const EngineCase& c, const PistonSimulation& sim);

    /// Whether the case asks for wear maps (either coefficient > 0).
    static bool wanted(const EngineCase& c);

    void stepAccepted(const AcceptedStep& step) override;
    void cycleEnded(const CycleEnd& end) override;

    const ArchardWear& maps() const { return wear_; }
    /// The last finished cycle's maxima (finished() false: none yet).
    const WearMaxima& maxima() const { return maxima_; }
    bool finished() const { return wear_.finished(); }

    /// The grid the maps are on (the skirt's).
    const lube::FilmGrid& grid() const;

private:
    const PistonSimulation& sim_;
    const SkirtContact& skirt_;
    std::size_t index_ = 0;  // the skirt's place among the run's contacts
    ArchardWear wear_;
    WearMaxima maxima_;
};

}  // namespace flexehd::cosim
