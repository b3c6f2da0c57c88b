#pragma once
// MassConservingFilm: the film with the mass-conserving JFO (Elrod–Adams) cavitation
// (lube::JfoSolver, its multigrid method), pressure and film fraction on the piston-fixed grid
// (docs/coupling.md §6). The transient term is that of the film's oil content φh in the grid's
// frame, by backward Euler from the last accepted step: V (φh − φₙhₙ)/Δt, the thickness h the
// film equation sees (floored, with the elastic change), so each step conserves the oil: the
// change of Σ V φ h is the net inflow through the film's edges times Δt, to the solver's tolerance. The supply at the
// skirt's edges is flooded (φ_in = 1) or the liner's oil layer (SkirtOilExchange). The
// linearisation holds the partition (lube::JfoLinearization) and the inlets' fractions, or where
// the liner layer feeds them the oil flux they bring.
#include "cosim/case/EngineCase.hpp"
#include "cosim/contact/FilmEquation.hpp"
#include "cosim/oil/SkirtOilExchange.hpp"
#include "lube/JfoLinearization.hpp"
#include "lube/JfoSolver.hpp"

#include <functional>
#include <memory>
#include <vector>

namespace flexehd::cosim {

class MassConservingFilm final : public FilmEquation {
public:
    /// linerOffset(crank angle in degrees): where the grid stands on the liner (the reach of its
    /// edges on the liner's layer).
    MassConservingFilm(const EngineCase& c, const lube::FilmGrid& grid, const std::function<double(double)>& linerOffset);

    void initialize(ContactState& s) const override;
    void solve(const ContactStep& step, const ContactState& now, const ContactState& before, ContactIterate& it,
               lube::FilmState& fs, WorkTally& work) override;
    void accept(const ContactStep& step, const ContactState& now, const ContactIterate& it,
                ContactState& s) const override;
    void linearize(const ContactStep& step, const ContactState& now, const ContactIterate& it) override;
    /// The JFO linearisation over the full film and the cavities upstream of it (docs/lube.md §3b).
    bool linearizationFollowsRigidMotion() const override { return true; }
    Eigen::MatrixXd pressureChange(const Eigen::Ref<const Eigen::MatrixXd>& dh) const override;
    /// On the full-film nodes (a starved film's few).
    lube::NodeColumns pressureChangeOnNodes(const Eigen::Ref<const Eigen::MatrixXd>& dh) const override;
    /// Zero: the content term V (φh − φₙhₙ)/Δt is in h, whole (pressureChange has it).
    Eigen::MatrixXd rateChange(const ContactStep& step, const Eigen::MatrixXd& dhs) const override;
    bool rateChangeIsZero() const override { return true; }
    const lube::Lubricant& lubricant() const override { return lubricant_; }
    bool conservesOil() const override { return true; }
    std::optional<LinerFootprint> linerFootprint() const override;
    void exchangeOil(const ContactState& now, const ContactState& next, const ContactIterate& it,
                     LinerOilExchange& ex) const override;

    /// The film solve's tolerance on the scaled mass residual (lube::JfoSolver), as the Reynolds
    /// film's: each step's oil balance holds to it (its error is the sum of the nodes' residuals).
    static constexpr double kTolerance = 1e-8;
    /// The liner's oil layer rules (null: flooded supply).
    const SkirtOilExchange* exchange() const { return exchange_.get(); }

private:
    /// The inlet fractions of the edge nodes for the iterate's thickness (liner oil layer).
    void setInlets(const ContactStep& step, const ContactState& now, const Eigen::VectorXd& h);
    void edgeFlows(const lube::JfoResult& r, ContactIterate& it) const;

    const lube::FilmGrid& grid_;
    lube::Lubricant lubricant_;
    lube::JfoSolver solver_;
    std::unique_ptr<SkirtOilExchange> exchange_;
    std::vector<double> inlet_;  // inlet fraction per node, this iterate
    lube::JfoResult warm_;       // the last solve's pressure and film fraction (the next warm start)
    std::unique_ptr<lube::JfoLinearization> linearization_;  // built on the first linearize
};

}  // namespace flexehd::cosim
