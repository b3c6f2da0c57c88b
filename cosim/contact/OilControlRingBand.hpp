#pragma once
// OilControlRingBand: the oil-control ring as the liner's oil layer sees it (docs/coupling.md §6,
// "The oil-control ring"): a band round the piston, above the skirt, that takes the whole layer
// its leading edge meets and leaves a layer of set thickness behind its trailing edge. What it
// scrapes beyond that drains through the ring to the crankcase; what it leaves beyond what it
// took comes from the oil the ring holds, fed from the crankcase through its drain holes. Both
// are its side flow in the run's oil balance. It carries no film load and no modal load (the
// ring's film, friction and radial balance are the ring pack's, docs/ring-pack.md).
#include "cosim/case/EngineCase.hpp"
#include "cosim/contact/FilmContact.hpp"

namespace flexehd::cosim {

class OilControlRingBand final : public FilmContact {
public:
    /// ring: its band and the layer it leaves; columns: the layer's columns (the footprint of the
    /// contact that runs on the layer with it, whose θ columns it shares); zLow, zHigh: the liner-
    /// frame z range its edges sweep over a revolution (m).
    OilControlRingBand(const OilControlRingSpec& ring, const LinerFootprint& columns, double zLow, double zHigh);

    ContactState initialState(double linerOffset) const override;
    void evaluate(const ContactStep& step, const ContactState& now, const ContactState& before,
                  const Eigen::Vector2d& x, const Eigen::VectorXd& y, ContactIterate& it, WorkTally& work) override;
    void addModalLoad(const ContactStep&, const ContactIterate&, Eigen::VectorXd&, WorkTally&) const override {}
    double filmChange(const ContactStep&, const Eigen::VectorXd&, WorkTally&) const override { return 0.0; }
    double filmChangeBound(const Eigen::VectorXd&) const override { return 0.0; }
    /// No load changes with y or with the rigid motion: every part of J empty.
    void linearize(const ContactStep& step, const ContactState& now, const Eigen::Vector2d& x, const ContactIterate& it,
                   ContactJacobian& J, WorkTally& work) override;
    ContactState accepted(const ContactStep& step, const ContactState& now, const ContactIterate& it) const override;

    /// oil_control_ring_drain_m3_per_s: the net flow the ring returns to the crankcase (what it
    /// scrapes less what it lays down; < 0: it lays down more than it meets).
    std::vector<ContactColumn> columns() const override;
    /// Its summary.json figure: the drain's cycle mean (m³/s).
    static constexpr const char* kDrainFigure = "oil_control_ring.drain_mean_m3_per_s";
    void columnValues(const ContactIterate& it, std::vector<double>& values) const override;

    bool carriesOil() const override { return true; }
    std::optional<LinerFootprint> linerFootprint() const override { return footprint_; }
    LinerCover linerCover(double linerOffset) const override {
        return {linerOffset + ring_.bottom, linerOffset + ring_.top};
    }
    void exchangeOil(const ContactState& now, const ContactState& next, const ContactIterate& it,
                     LinerOilExchange& ex) const override;

private:
    OilControlRingSpec ring_;
    LinerFootprint footprint_;
};

}  // namespace flexehd::cosim
