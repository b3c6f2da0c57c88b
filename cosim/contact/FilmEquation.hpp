#pragma once
// FilmEquation: how a contact's film is solved at an iterate, chosen once from the case
// (lubricant.cavitation) and applied at every iterate: the Reynolds (Swift–Stieber) condition
// (ReynoldsFilm) or the mass-conserving JFO film with its film fraction and oil supply
// (MassConservingFilm). The contact gives it the film thickness; the equation gives back the
// pressure, the squeeze rate it used and, mass-conserving, the film fraction and the flows
// through the film's edges (docs/coupling.md §6).
#include "cosim/contact/FilmContact.hpp"
#include "lube/FilmState.hpp"

#include <Eigen/Core>
#include "lube/Lubricant.hpp"
#include "lube/NodeColumns.hpp"

#include <optional>

namespace flexehd::cosim {

class FilmEquation {
public:
    virtual ~FilmEquation() = default;

    /// Completes the run's initial state (thickness set) with what the equation carries.
    virtual void initialize(ContactState& s) const = 0;
    /// Solves the film of the iterate (h, hRigid, hTotal set) with the liner sliding at
    /// −step.pistonVelocity: fills it.dhdt, it.p and the mass-conserving fields; fs receives the
    /// film state the loads integrate. Throws std::runtime_error when the solve fails.
    virtual void solve(const ContactStep& step, const ContactState& now, const ContactState& before,
                       ContactIterate& it, lube::FilmState& fs, WorkTally& work) = 0;
    /// Completes the state kept from an accepted iterate (film fraction, its oil balance).
    virtual void accept(const ContactStep& step, const ContactState& now, const ContactIterate& it,
                        ContactState& s) const = 0;
    /// coupling.method newton: linearises the film at the iterate's solution (its cavitated set
    /// or partition held), for the step from `now`.
    virtual void linearize(const ContactStep& step, const ContactState& now, const ContactIterate& it) = 0;
    /// δp (grid × k, Pa) at the last linearisation for k columns of film-thickness changes δh (m).
    virtual Eigen::MatrixXd pressureChange(const Eigen::Ref<const Eigen::MatrixXd>& dh) const = 0;
    /// pressureChange on the nodes where it is not zero.
    virtual lube::NodeColumns pressureChangeOnNodes(const Eigen::Ref<const Eigen::MatrixXd>& dh) const {
        return lube::NodeColumns::fromDense(pressureChange(dh));
    }
    /// δp (grid × k, Pa) per unit a0/Δt of the master's BDF2 rate for k columns of the squeeze
    /// thickness's change δh_s (m): the part of the film's dependence on h that goes through its
    /// squeeze term (coupling.elastic_squeeze; zero where the film's content term is its own).
    virtual Eigen::MatrixXd rateChange(const ContactStep& step, const Eigen::MatrixXd& dhs) const = 0;
    /// rateChange is zero whatever δh_s (the film's content term is in its thickness dependence):
    /// the caller may skip it and the products of it.
    virtual bool rateChangeIsZero() const { return false; }
    /// pressureChange of a rigid motion's δh equals differences of full solves (the partition held
    /// includes what the pressure depends on; no rate part): the contact gives the master its
    /// motion columns.
    virtual bool linearizationFollowsRigidMotion() const { return false; }
    virtual const lube::Lubricant& lubricant() const = 0;
    /// The equation conserves the film's oil (its iterates carry the film fraction and edge flows).
    virtual bool conservesOil() const { return false; }
    /// A film fed by the liner's oil layer: what it needs of the layer (FilmContact::linerFootprint);
    /// none by default.
    virtual std::optional<LinerFootprint> linerFootprint() const { return std::nullopt; }
    /// Its trade with the liner's layer over the accepted step from `now` to `next`
    /// (FilmContact::exchangeOil).
    virtual void exchangeOil(const ContactState& /*now*/, const ContactState& /*next*/, const ContactIterate& /*it*/,
                             LinerOilExchange& /*ex*/) const {}
};

}  // namespace flexehd::cosim
