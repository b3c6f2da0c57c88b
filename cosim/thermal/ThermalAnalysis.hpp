#pragma once
// The `flexehd thermal` pipeline on a ThermalCase (docs/thermal.md): piston — steady
// conduction with convective boundaries, optional templug calibration, thermoelastic
// solve supported at the pin, skirt table, the ring belt's surface temperature over z; liner — temperature from thermocouples,
// thermoelastic solve on its seat, bore table. Writes nothing; reports progress through
// a callback.
#include <functional>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "cosim/thermal/CylindricalSurfaceSampler.hpp"
#include "cosim/thermal/ThermalCase.hpp"
#include "fem/Mesh.hpp"
#include "fem/SteadyHeatConduction.hpp"
#include "fem/ThermalCalibration.hpp"
#include "fem/ThermalDeformation.hpp"

namespace flexehd::cosim {

struct ThermalBodyResult {
    fem::Mesh mesh;
    Eigen::VectorXd temperature;  ///< K, nodal
    fem::ThermalDeformation deformation;
    SurfaceTable table;           ///< radial displacement of the sampled surface
    double seconds = 0.0;
};

struct PistonThermalResult : ThermalBodyResult {
    fem::ConvectionParameters parameters;            ///< as used (fitted if calibrated)
    Eigen::VectorXd heatFlow;                        ///< W into the piston per convection boundary
    std::optional<fem::CalibrationResult> calibration;
    /// The circumferential mean temperature (K) over z of the ring belt's outer surface
    /// (PistonThermalCase::ringBelt), rows at most kRingBeltRowSpacing apart; none without it.
    std::optional<AxialProfile> ringBelt;
};

/// m: the largest spacing of the ring-belt profile's rows (a tenth of a millimetre resolves lands
/// and grooves of a millimetre and more).
inline constexpr double kRingBeltRowSpacing = 0.1e-3;

struct ThermalResult {
    std::optional<PistonThermalResult> piston;
    std::optional<ThermalBodyResult> liner;
};

/// Throws std::runtime_error starting with the case file and key path for groups that are
/// not in the mesh, points outside it and under-determined calibrations.
ThermalResult runThermalAnalysis(const ThermalCase& c, const std::function<void(const std::string&)>& progress = {});

}  // namespace flexehd::cosim
