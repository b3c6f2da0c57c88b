#pragma once
// RingPackGas: the ring pack's gas in a run (docs/ring-pack.md, "The pack's gas in a run"). The
// lands between the rings are InterRingGas's volumes, each ring's end gap its orifice:
//
//   cylinder → gap of ring 0 → land 0 → gap of ring 1 → … → land n−2 → gap of ring n−1 → crankcase.
//
// Land i (between ring i and ring i + 1) holds the annulus between the piston's land and the bore
// and, ring i + 1 resting on its groove's lower flank, that ring's groove space above and behind
// it. A step's land pressures follow from the cylinder pressure at its end (backward Euler, from
// the last accepted step's); they are kept when the step is accepted.
#include <optional>
#include <vector>

#include "cosim/case/EngineCase.hpp"
#include "cosim/contact/FilmContact.hpp"
#include "cosim/ringpack/InterRingGas.hpp"

namespace flexehd::cosim {

class RingPackGas {
public:
    /// The case's pack and `ring_gas` (model Lands, at least one ring); starts at the crankcase
    /// pressure. Throws std::invalid_argument when a land has no height (rings' grooves overlap).
    explicit RingPackGas(const EngineCase& c);

    /// The gas round each ring at the end of a step of dt (s) to the cylinder pressure there
    /// (Pa, absolute), from the last accepted state; the step's trial until accept().
    const std::vector<RingGas>& trial(double dt, double cylinderPressure);
    /// The last trial becomes the accepted state.
    void accept();

    /// m³, the volume of each land (top first).
    const std::vector<double>& landVolumes() const { return volumes_; }
    /// m², C_d A of each ring's end gap (top first).
    const std::vector<double>& gapAreas() const { return gaps_; }
    /// Pa, absolute, the accepted state's land pressures.
    std::vector<double> landPressures() const;

private:
    double crankcase_;
    std::vector<double> volumes_, temperatures_, gaps_;
    std::optional<InterRingGas> accepted_, trial_;  // lands (none with a single ring)
    std::vector<RingGas> around_;
};

}  // namespace flexehd::cosim
