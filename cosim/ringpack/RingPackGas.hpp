#pragma once
// RingPackGas: the ring pack's gas in a run (docs/ring-pack.md, "The pack's gas in a run"). The
// lands between the rings are InterRingGas's volumes, each ring's end gap an orifice:
//
//   cylinder → gap of ring 0 → land 0 → gap of ring 1 → … → land n−2 → gap of ring n−1 → crankcase.
//
// Land i (between ring i and ring i + 1) holds the annulus between the piston's land and the bore
// and, ring i + 1 resting on its groove's lower flank, that ring's groove space above and behind
// it. With ring_gas.ring_lift each ring moves axially in its groove (RingAxialMotion, "Ring lift in
// a run") and each groove is a volume of its own, joined to the space above the ring through its
// upper flank's clearance and to the space below through its lower flank's, each opening as the
// ring leaves that flank. With lift a ring also leaves the liner when the gas on its face
// outweighs its tension and the gas behind it (radial collapse, "Ring collapse in a run"): per
// unit circumference the ring of mass m moves inwards across its groove's back clearance under
//
//   m g̈ = −n_f b [T/(n_f b) + p_behind − ½ (p_above + p_below)]
//
// (g its face's opening off the liner, T its tension per unit circumference, n_f b its running
// faces' width, the bracket its collapse margin: the gas balance of a face far from the liner),
// stepped as its axial motion (RingAxialMotion across [0, back clearance], held on the liner while
// the margin is ≥ 0), and its face is an orifice of C_d πD g from the space above it to the space
// below. A step's pressures follow from the cylinder pressure at its end (backward Euler, from the
// last accepted step's); they are kept when the step is accepted.
#include <optional>
#include <utility>
#include <vector>

#include "cosim/case/EngineCase.hpp"
#include "cosim/contact/FilmContact.hpp"
#include "cosim/ringpack/InterRingGas.hpp"
#include "cosim/ringpack/RingAxialMotion.hpp"

namespace flexehd::cosim {

class RingPackGas {
public:
    /// The case's pack and `ring_gas` (model Lands, at least one ring); starts at the crankcase
    /// pressure, every ring on its lower flank. Throws std::invalid_argument when a land has no
    /// height (rings' grooves overlap).
    explicit RingPackGas(const EngineCase& c);

    /// The gas round each ring at the end of a step of dt (s) to the cylinder pressure there
    /// (Pa, absolute), from the last accepted state; the step's trial until accept(). With ring
    /// lift the rings first move in their grooves under the gas at the step's start (the
    /// cylinder's at its end), their inertia at the piston's axial acceleration A = Z̈ + g
    /// (m/s², +z towards the head) and `friction` (N per ring, top first, the liner film's axial
    /// force on each ring at the last accepted step; empty: none). openGaps: per ring, the gap its
    /// oil left open to the gas at the last accepted step (a ring on the liner's oil layer; empty:
    /// none): a laminar channel past its face in parallel with it (channelFlow; none while the
    /// gas holds the ring off the liner, whose face's orifice then takes the flow).
    const std::vector<RingGas>& trial(double dt, double cylinderPressure, double acceleration = 0.0,
                                      const std::vector<double>& friction = {},
                                      const std::vector<RingOpenGap>& openGaps = {});
    /// The last trial becomes the accepted state.
    void accept();

    /// m³, the volume of each land (top first); with ring lift without the grooves.
    const std::vector<double>& landVolumes() const { return volumes_; }
    /// m³, with ring lift the volume of each ring's groove behind and beside it (empty without).
    const std::vector<double>& grooveVolumes() const { return grooves_; }
    /// m², C_d A of each ring's end gap (top first).
    const std::vector<double>& gapAreas() const { return gaps_; }
    /// Pa, absolute, the accepted state's land pressures.
    std::vector<double> landPressures() const;
    /// kg/s at the last trial: from the cylinder into the pack, and out of it into the crankcase.
    double inflow() const;
    double blowBy() const;
    /// kg, the gas in the lands and grooves at the accepted state.
    double mass() const { return accepted_ ? accepted_->mass() : 0.0; }

private:
    // The network's ends round ring i: the space above it, below it, and behind it (its groove).
    int above(std::size_t i) const;
    int below(std::size_t i) const;
    int behind(std::size_t i) const;
    // its face's orifice (after the end gaps and, with lift, the flanks' clearances)
    int face(std::size_t i) const { return static_cast<int>((lift_ ? 3 : 1) * rings_.size() + i); }
    /// Each face's open-gap channel for the coming step.
    void setFaceChannels(const std::vector<RingOpenGap>& openGaps);
    /// Ring i's open-gap channel: G = πD/∫dx/h_o³ (m³) and C_d πD min h_o (m²); 0 while collapsed.
    std::pair<double, double> faceChannel(std::size_t i, const std::vector<RingOpenGap>& openGaps) const;
    double pressure(int node, const InterRingGas* gas, double cylinder) const;
    /// Each ring's step in its groove and its flanks' openings (ring lift).
    void moveRings(double dt, double cylinderPressure, double acceleration, const std::vector<double>& friction);
    /// Ring i's collapse margin (Pa) in `gas` with the cylinder at cylinderPressure (Pa).
    double margin(std::size_t i, const InterRingGas& gas, double cylinderPressure) const;

    struct Ring {
        double faceArea;       // m², the ring's side face π (D − w) w
        double flankLength;    // m, the flank clearance's circumference π (D − w)
        double mass;           // kg
        double sideClearance;  // m
        double faceMargin;     // Pa, T/(n_f b): the gas excess on the face its tension holds
        double runningWidth;   // m, n_f b
    };
    double crankcase_, circumference_, dischargeCoefficient_;
    bool lift_;
    std::vector<Ring> rings_;
    std::vector<double> volumes_, grooves_, temperatures_, gaps_;
    std::optional<InterRingGas> accepted_, trial_;  // lands and grooves (none: a single ring without lift)
    std::vector<RingAxialMotion> motion_, trialMotion_;
    std::vector<RingAxialMotion> collapse_, trialCollapse_;  // each face's opening off the liner
    std::vector<RingGas> around_;
};

}  // namespace flexehd::cosim
