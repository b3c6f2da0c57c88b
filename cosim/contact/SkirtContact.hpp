#pragma once
// SkirtContact: the piston skirt's film against the liner as a FilmContact (docs/coupling.md §1).
// Its grid is fixed to the piston (SkirtFilm); the film thickness is the rigid motion's
// (docs/dynamics.md §3) plus the clearance terms at the liner offset (ClearanceTerms: bore
// distortion, thermal growth) plus the elastic change of the flexible piston and liner
// (FlexibleSurface over this grid). Where the surfaces touch, the Greenwood–Tripp asperity
// pressure of the unfloored thickness and the coating's hard contact below h = 0 carry the load,
// and the film equation sees the thickness floored (docs/lube.md §4). The film is solved by
// lube::ReynoldsSolver (multigrid, the active set where it stalls) with the liner sliding past
// the grid at minus the piston's velocity.

#include "cosim/case/EngineCase.hpp"
#include "cosim/contact/CouplingNeeds.hpp"
#include "cosim/contact/FilmContact.hpp"
#include "cosim/contact/FilmEquation.hpp"
#include "cosim/engine/SkirtFilm.hpp"
#include "cosim/mapping/FlexibleBodyLoader.hpp"
#include "cosim/mapping/FlexibleSurface.hpp"
#include "lube/ElasticFoundation.hpp"
#include "lube/GreenwoodTripp.hpp"

#include <functional>
#include <limits>
#include <memory>
#include <optional>

namespace flexehd::cosim {

class ClearanceTerms;

/// The film thickness with the piston centred (no lateral shift, no tilt) and no elastic
/// deformation — clearance + profile + ovality + bore distortion + thermal growth, i.e. the hot
/// running clearance when the case names a thermal file — over the skirt's film nodes.
struct ClearanceRange {
    double min = 0.0, mean = 0.0, max = 0.0;  ///< m
};

class SkirtContact final : public FilmContact {
public:
    /// Builds the grid and the film solver, the flexible bodies' surfaces over the grid (bodies:
    /// the case's, null when rigid) and reads the clearance files the case names.
    /// linerOffset(crank angle in degrees): the liner-frame z of the piston frame's origin (the
    /// range the grid slides over the liner).
    SkirtContact(const EngineCase& c, const CaseBodies& bodies, std::function<double(double)> linerOffset);
    ~SkirtContact() override;

    ContactState initialState(double linerOffset) const override;
    void evaluate(const ContactStep& step, const ContactState& now, const ContactState& before,
                  const Eigen::Vector2d& x, const Eigen::VectorXd& y, ContactIterate& it, WorkTally& work) override;
    void addModalLoad(const ContactStep& step, const ContactIterate& it, Eigen::VectorXd& f,
                      WorkTally& work) const override;
    double filmChange(const ContactStep& step, const Eigen::VectorXd& dy, WorkTally& work) const override;
    /// Σ_j |dy_j| max|Ψ_j| over the piston's modes; none (infinity) with a flexible liner, whose
    /// shapes move with the grid's offset.
    double filmChangeBound(const Eigen::VectorXd& dy) const override;
    Eigen::VectorXd modalFilmChangeScale() const override;
    void linearize(const ContactStep& step, const ContactState& now, const Eigen::Vector2d& x, const ContactIterate& it,
                   ContactJacobian& J, WorkTally& work) override;
    ContactState accepted(const ContactStep& step, const ContactState& now, const ContactIterate& it) const override;
    void checkLoadMapping(const ContactIterate& it, double& worstDiff, double& largestForce) const override;
    bool carriesOil() const override { return equation_->conservesOil(); }
    /// The mass-conserving film on a liner oil layer: the film equation's footprint; the skirt
    /// covers the liner between its grid's edge rows.
    std::optional<LinerFootprint> linerFootprint() const override { return equation_->linerFootprint(); }
    LinerCover linerCover(double linerOffset) const override;
    void exchangeOil(const ContactState& now, const ContactState& next, const ContactIterate& it,
                     LinerOilExchange& ex) const override {
        equation_->exchangeOil(now, next, it, ex);
    }
    /// The modal Jacobian: the piston's film-change shapes Ψ (constant on the skirt's grid).
    void prepare(const CouplingNeeds& needs) override;
    /// The skirt's film is the run's film (history.csv's film columns, film.pvd).
    bool filmFigures(const ContactIterate& it, FilmFigures& figures) const override;
    bool filmFields(const ContactIterate& it, double pistonVelocity, FilmFields& fields) const override;
    /// The clearance terms and the centred clearance at TDC, mid-stroke and BDC (when the case has
    /// clearance terms).
    std::vector<std::string> startReport() const override;

    const SkirtFilm& film() const { return film_; }
    const lube::FilmGrid& grid() const { return film_.grid(); }
    const lube::Lubricant& lubricant() const { return equation_->lubricant(); }
    /// How the film is solved (lubricant.cavitation).
    const FilmEquation& equation() const { return *equation_; }
    /// The flexible bodies seen from this grid (null when rigid).
    const FlexibleSurface* piston() const { return piston_.get(); }
    const FlexibleSurface* liner() const { return liner_.get(); }
    /// Bore distortion and thermal terms of the film thickness (null when the case has none).
    const ClearanceTerms* clearance() const { return clearance_.get(); }
    /// The centred, undeformed film thickness at the liner offset.
    ClearanceRange centredClearance(double linerOffset) const;

private:
    // The stages of evaluate.
    void filmThickness(const ContactStep& step, const Eigen::Vector2d& x, const Eigen::VectorXd& y,
                       ContactIterate& it, WorkTally& work);
    void contactAndFloor(const ContactStep& step, const ContactState& now, const ContactState& before,
                         ContactIterate& it) const;
    void solveFilm(const ContactStep& step, const ContactState& now, const ContactState& before, ContactIterate& it,
                   WorkTally& work);
    /// Contact pressure at node k of the iterate's unfloored thickness: Greenwood–Tripp asperity
    /// pressure of max(h, 0), and the hard contact of the coating below h = 0, damped with the
    /// node's approach speed and impact speed (docs/lube.md §4); sets it.impactSpeed[k].
    void contactPressure(const ContactStep& step, const ContactState& now, const ContactState& before, int k,
                         ContactIterate& it, double& asperity, double& hard) const;
    /// ∂(asperity + hard)/∂h (Pa/m) at node k of the iterate at a held approach speed, and the
    /// damped hard contact's part through the approach speed's change with h (∂(−ḣ)/∂h = −a0/Δt)
    /// where that h is in the rate (rateSlope, Pa/m; 0 without damping).
    double contactSlope(const ContactStep& step, const ContactIterate& it, int k, double& rateSlope) const;
    /// −ḣ (m/s) at node k: the step's BDF2 rate of the thickness the squeeze term sees (the
    /// unfloored one with coupling.elastic_squeeze or rigid bodies, else the rigid one).
    double approachSpeed(const ContactStep& step, const ContactState& now, const ContactState& before,
                         const ContactIterate& it, int k) const;
    /// ∂h/∂(e, β, y) on the grid into jacobianDh_ (the modal columns Ψ; the liner's per offset).
    void filmChangeColumns(const ContactStep& step, const Eigen::Vector2d& x);
    lube::FilmIntegralOptions integralOptions() const;

    EngineCase case_;
    std::function<double(double)> linerOffset_;
    SkirtFilm film_;
    std::unique_ptr<FilmEquation> equation_;  // Reynolds condition or mass-conserving
    mutable std::shared_ptr<const std::vector<char>> panelColumns_;  // the liner columns its cover reaches
    std::optional<lube::GreenwoodTripp> contact_;
    std::optional<lube::ElasticFoundation> foundation_;  // hard contact below h = 0 (with contact_)
    std::unique_ptr<FlexibleSurface> piston_, liner_;
    std::unique_ptr<ClearanceTerms> clearance_;  // added to h_rigid at the liner offset
    int mp_ = 0, ml_ = 0;  // modal coordinates of piston and liner
    // Elastic Δh of the last y and liner offset evaluated (reused by the Jacobian's evaluations).
    Eigen::VectorXd elasticY_, pistonDh_, linerDh_;
    double elasticOffset_ = std::numeric_limits<double>::quiet_NaN();
    // coupling.method newton: the film-change shapes Ψ (grid × modes)
    Eigen::MatrixXd psiPiston_, psiLiner_;
    Eigen::VectorXd pistonShapeMax_;  // max over the grid of |Ψ_j| per piston mode
    Eigen::MatrixXd jacobianDh_;  // ∂h/∂(e, β, y): grid × (2 + modes), kept between linearisations
    double psiLinerOffset_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace flexehd::cosim
