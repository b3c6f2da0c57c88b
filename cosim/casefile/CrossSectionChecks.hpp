#pragma once
// The checks of the case file that span sections: each fails at the key to change, with the
// sections it needs read.
#include "cosim/case/EngineCase.hpp"
#include "cosim/io/YamlSection.hpp"

namespace flexehd::cosim::casefile {

/// engine.pin_tdc_depth given where the liner's tables (bore distortion, thermal) or a flexible
/// liner need the piston placed on the liner (after engine, liner, thermal and bodies).
void requirePinTdcDepth(const YamlSection& engine, const EngineCase& c);
/// The skirt top below the deck at TDC (after engine, bodies and piston).
void requireSkirtBelowDeck(const YamlSection& engine, const EngineCase& c);
/// The mass-conserving film with a flexible body: the coupled Newton method
/// (docs/coupling.md §6; after bodies, lubricant and coupling).
void requireSupportedMassConserving(const YamlSection& coupling, const EngineCase& c);
/// lubricant.supply.oil_control_ring above piston.skirt_top and, at TDC, below the deck.
void requireOilControlRingOnPiston(const YamlSection& lubricant, const EngineCase& c);
/// lubricant.supply.replenish_below_depth no deeper than the skirt's lower edge reaches at BDC
/// (after engine, piston and lubricant): deeper, the layer would never be replenished.
void requireReplenishWithinReach(const YamlSection& lubricant, const EngineCase& c);

/// bodies.piston.loads' ring_pack with a pack whose gas and ring positions are stepped (rings,
/// ring_gas: {model: lands, ring_lift: true}; after bodies, rings and ring_gas).
void requireRingPackForItsLoads(const YamlSection& top, const EngineCase& c);

}  // namespace flexehd::cosim::casefile
