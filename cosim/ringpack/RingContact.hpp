#pragma once
// RingContact: one piston ring as a film contact of the master (docs/ring-pack.md, "The rings in
// the run"): the axisymmetric film across the ring's running face (lube::RingFilm, flooded) and
// the ring's radial balance with it in each step (RingRadialMotion: tension and the gas pressure
// behind the ring against the film and the asperities, the ring's radial squeeze in the film,
// backward Euler), and its friction on the piston:
//
//   F_z = πD (f_hydro − μ_b W_asperity sign(v_p)),
//
// f_hydro the film's shear on the ring per unit circumference, W_asperity the asperity load per
// unit circumference, v_p the piston's axial velocity. Round the bore its radial loads and its
// friction's moments cancel: it adds F_z to the piston's axial equation and nothing to the
// lateral force or the tilt moment. The top ring has the cylinder's gauge pressure above its
// face and behind it, the rings below the crankcase's (the lands' gas is not modelled here).
// The oil-control ring runs on its two lands, alike: each a barrel film carrying half its
// tension at the same minimum gap (the groove between them at the crankcase's pressure), their
// loads summed. Flooded, or on the liner's oil layer (RingOilExchange): then each face's film is
// mass-conserving, the lands in series (the second meets what the first leaves; what it does not
// take in drains through the ring to the crankcase: the ring's side flow). A rigid or flexible
// piston (the pack's loads on its ring belt: RingBeltLoads); a rigid or flexible liner: on a
// flexible one the ring's film and asperity pressure, lumped onto a load grid of kLoadRows rows
// across the ring's height round the bore, is a modal load on the liner, and the ring's film does
// not see the liner's deformation (the ring, free to move radially, follows the bore's local
// radius; its conformability to the bore's distortion round it is not modelled).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cosim/case/EngineCase.hpp"
#include "cosim/contact/FilmContact.hpp"
#include "cosim/mapping/FlexibleBody.hpp"
#include "cosim/mapping/FlexibleSurface.hpp"
#include "lube/FilmGrid.hpp"
#include "cosim/ringpack/InterRingGas.hpp"
#include "cosim/ringpack/RingOilExchange.hpp"
#include "cosim/ringpack/RingRadialMotion.hpp"

namespace flexehd::cosim {

class RingContact final : public FilmContact {
public:
    /// ring: its spec; top: the pack's top ring (the cylinder's pressure above and behind it);
    /// faceNodes: the film's nodes across the face (0: 101 on a barrel face, on a tabulated one at
    /// least 8 per its shortest interval: docs/ring-pack.md). Throws std::invalid_argument for an
    /// oil-control ring without lands or without asperity contact (contact.composite_modulus 0:
    /// nothing would carry the ring at the dead centres).
    /// layer: on the liner's oil layer, its θ columns (widths round the whole bore) and the
    /// liner offsets' range over a revolution as zLow, zHigh (null: a flooded liner).
    /// liner: the flexible liner (null: rigid), its load grid sliding over the liner offsets
    /// [offsetLow, offsetHigh] (m) of a revolution.
    RingContact(const EngineCase& c, const RingSpec& ring, bool top, int faceNodes = 0,
                const LinerFootprint* layer = nullptr, std::shared_ptr<const FlexibleBody> liner = nullptr,
                double offsetLow = 0.0, double offsetHigh = 0.0);
    ~RingContact() override;

    ContactState initialState(double linerOffset) const override;
    void evaluate(const ContactStep& step, const ContactState& now, const ContactState& before,
                  const Eigen::Vector2d& x, const Eigen::VectorXd& y, ContactIterate& it, WorkTally& work) override;
    /// On a flexible liner: the ring's pressure on the liner's rows of f.
    void addModalLoad(const ContactStep& step, const ContactIterate& it, Eigen::VectorXd& f,
                      WorkTally& work) const override;
    double filmChange(const ContactStep&, const Eigen::VectorXd&, WorkTally&) const override { return 0.0; }
    double filmChangeBound(const Eigen::VectorXd&) const override { return 0.0; }
    /// Its loads change neither with y nor with the rigid motion: the motion columns are given, empty.
    void linearize(const ContactStep& step, const ContactState& now, const Eigen::Vector2d& x, const ContactIterate& it,
                   ContactJacobian& J, WorkTally& work) override;
    ContactState accepted(const ContactStep& step, const ContactState& now, const ContactIterate& it) const override;

    /// ring_<name>_min_film_m, _friction_force_n, _friction_power_w (the power the ring's friction
    /// takes from the piston, −F_z v_p), _boundary_friction_power_w; summary.json
    /// rings.<name>.min_film_m, the powers' cycle means and the ring's fmep_pa; on the liner's
    /// oil layer also _oil_left_m, the layer its trailing edge leaves (outflow / |U|); with
    /// ring_gas its gas columns and, with ring lift, _axial_position_m, _gas_behind_pa and
    /// _face_opening_m (its lifts per cycle and their crank angles, the largest face opening in
    /// summary.json).
    std::vector<ContactColumn> columns() const override;
    void columnValues(const ContactIterate& it, std::vector<double>& values) const override;

    /// The minimum gap (m) where the asperities alone carry the ring's tension (the ring at rest).
    double restingGap() const;

    /// The rows of the load grid on a flexible liner across the ring's height.
    static constexpr int kLoadRows = 9;
    /// The load grid (piston-frame z rows, θ columns round the bore; null on a rigid liner).
    const lube::FilmGrid* loadGrid() const { return loadGrid_.get(); }

    int packRing() const override { return gasIndex_; }
    bool carriesOil() const override { return oil_.has_value(); }
    std::optional<LinerFootprint> linerFootprint() const override;
    LinerCover linerCover(double linerOffset) const override { return oil_ ? oil_->cover(linerOffset) : LinerCover{}; }
    void exchangeOil(const ContactState& now, const ContactState& next, const ContactIterate& it,
                     LinerOilExchange& ex) const override;

    /// The summary.json figures of every ring, under rings.<name>.<figure>.
    static const std::vector<std::string>& figureNames();
    /// With ring_gas, the last ring's gas flow's cycle means as the blow-by: blow_by.mean_kg_per_s,
    /// blow_by.mean_l_per_min.
    static const std::vector<std::string>& blowByFigures();
    /// Whether `key` names a ring's figure: rings.<name>.<one of figureNames()>, or the blow-by's.
    static bool isFigureKey(const std::string& key);

private:
    /// The radial step from h_min,n for the step's conditions; the last one is kept, since the
    /// ring's film does not depend on the master's unknowns and every pass of a step asks it again.
    const RingRadialStep& radialStep(const ContactStep& step, const ContactState& now, double guess);
    /// On the liner's oil layer: the iterate's film fractions, oil and flows.
    void oilFlows(const ContactStep& step, const ContactState& now, const RingRadialStep& r, ContactIterate& it) const;
    /// On a flexible liner: the faces' film and asperity pressure lumped onto the load grid's rows
    /// (each row the force of its part of the ring's height over its width), round the bore.
    void linerLoad(const RingRadialStep& r, Eigen::VectorXd& load) const;

    RingSpec ring_;
    bool top_;
    int faces_;             // running faces: 1, or the oil-control ring's 2 lands
    double circumference_;  // πD (m)
    double boundaryFriction_;
    lube::GreenwoodTripp asperity_;
    RingRadialMotion radial_;
    std::optional<RingOilExchange> oil_;
    OilSupplySpec supply_;
    int nodes_;  // the film's nodes across each face
    std::unique_ptr<lube::FilmGrid> loadGrid_;      // on a flexible liner
    std::unique_ptr<FlexibleSurface> linerSurface_;
    int gasIndex_ = -1;               // its place in the pack with ring_gas (-1: no gas model)
    bool lastInPack_ = false;         // with ring_gas: the last ring (its gas flow is the blow-by)
    bool lift_ = false;               // with ring_gas.ring_lift: the ring moves in its groove
    double crankcasePressure_ = 0.0;  // Pa, absolute
    RingGas gas_;                     // round the ring at the last evaluated step
    struct Cached {
        double gapNow, dt, velocity, above, behind, below, supply, opening, openingBefore;
        bool operator==(const Cached&) const = default;
    };
    std::optional<Cached> cachedFor_;
    RingRadialStep cached_;
};

}  // namespace flexehd::cosim
