#include "cosim/coupling/CouplingAccelerator.hpp"

#include "cosim/coupling/AitkenAccelerator.hpp"
#include "cosim/coupling/IqnIlsAccelerator.hpp"

namespace flexehd::cosim {

std::unique_ptr<CouplingAccelerator> makeCouplingAccelerator(CouplingAcceleration method, double initialRelaxation,
                                                             int maxColumns) {
    if (method == CouplingAcceleration::Aitken) return std::make_unique<AitkenAccelerator>(initialRelaxation);
    return std::make_unique<IqnIlsAccelerator>(initialRelaxation, maxColumns);
}

}  // namespace flexehd::cosim
