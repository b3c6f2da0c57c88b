#include "cosim/run/ThermalLandTemperatures.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "cosim/clearance/ThermalDisplacementFile.hpp"

namespace flexehd::cosim {

std::optional<ThermalLandTemperatures> thermalLandTemperatures(const EngineCase& c) {
    if (c.ringGas.model != RingGasModel::Lands || c.rings.size() < 2 || c.thermal.file.empty() ||
        !c.ringGas.landTemperatures.empty())
        return std::nullopt;
    const ThermalDisplacement file = readThermalDisplacementFile(c.thermal.file);
    ThermalLandTemperatures out;
    const std::string where = c.path.empty() ? std::string("ring_gas") : c.path + ": ring_gas";
    if (!file.pistonRingBelt) {
        out.message = fmt::format("{}: the thermal file {} has no piston ring-belt temperature profile "
                                  "(/piston/ring_belt; written by `flexehd thermal` of this build): the lands' gas "
                                  "stays at {:g} K; give ring_gas.land_temperatures or write the file again",
                                  where, c.thermal.file, RingGasSpec::kLandTemperature);
        return out;
    }
    const SurfaceTemperatureProfile& profile = *file.pistonRingBelt;
    std::string values;
    for (std::size_t i = 0; i + 1 < c.rings.size(); ++i) {
        const RingSpec& upper = c.rings[i];
        const RingSpec& lower = c.rings[i + 1];
        const double zLow = lower.grooveTop(), zHigh = upper.groove.lowerFlank;
        if (!(zHigh > zLow) || zLow < profile.z.front() - 1e-9 || zHigh > profile.z.back() + 1e-9)
            throw std::runtime_error(fmt::format(
                "{}: land {} (between rings '{}' and '{}', z = {:g} … {:g} m) is not covered by the thermal file's "
                "ring-belt temperature profile {}/z_m ({:g} … {:g} m); give ring_gas.land_temperatures",
                where, i + 1, upper.name, lower.name, zLow, zHigh, profile.where, profile.z.front(),
                profile.z.back()));
        out.temperatures.push_back(profile.mean(zLow, zHigh));
        values += fmt::format("{}{:.1f}", values.empty() ? "" : ", ", out.temperatures.back());
    }
    out.message = fmt::format("ring_gas: land temperatures {} K (top first), the piston's ring-belt surface "
                              "temperature of {} averaged over each land",
                              values, c.thermal.file);
    return out;
}

}  // namespace flexehd::cosim
