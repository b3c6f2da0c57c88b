#pragma once
// The supply layer of lubricant.supply: liner_layer (docs/case-file.md, `lubricant.supply`): the
// oil layer the liner carries at the start of a run and where the replenishment restores it.
#include "cosim/case/EngineCase.hpp"

namespace flexehd::cosim {

/// The supply layer's thickness (m) at liner-frame z (m; depth = −z), linear between the table's
/// points and constant beyond them; 0 without a table.
double supplyLayerThickness(const OilSupplySpec& supply, double z);

}  // namespace flexehd::cosim
