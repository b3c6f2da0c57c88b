#pragma once
// The thermal case of `flexehd thermal` as plain data (docs/thermal.md §5): the piston's
// steady conduction with convective boundaries and optional templug calibration, the
// liner's temperature from thermocouples, materials, supports and the output grid.
// SI units: m, K, Pa, W/(m K), W/(m² K), 1/K.
#include <optional>
#include <string>
#include <vector>

#include "fem/Material.hpp"
#include "fem/ModalAnalysis.hpp"
#include "fem/SteadyHeatConduction.hpp"
#include "fem/ThermalCalibration.hpp"

namespace flexehd::cosim {

struct ThermalBodyMesh {
    std::string path;      ///< absolute
    double size = 0.0;     ///< m, 0 = the .geo's default
    int order = 0;         ///< 0 = .geo → 2, .msh as stored
};

struct PistonThermalCase {
    ThermalBodyMesh mesh;
    fem::ElasticMaterial material;           ///< rho unused (set to 1)
    double conductivity = 0.0;               ///< W/(m K)
    double expansion = 0.0;                  ///< 1/K
    std::vector<fem::ConvectionBoundary> convection;
    std::string support = "pin_bore";        ///< group whose mean rigid motion is held
    std::vector<std::string> surface{"skirt", "skirt_taper"};  ///< sampled for thermal.h5
    /// The outer surface across the ring belt whose temperature profile over z goes to thermal.h5
    /// (/piston/ring_belt); empty: none. The default is skipped when the mesh has no such group.
    std::vector<std::string> ringBelt{"ring_lands"};
    bool ringBeltGiven = false;              ///< `piston.ring_belt` given: its groups must exist
    // Calibration (none if `parameters` is empty).
    std::vector<fem::CalibrationParameter> parameters;
    std::vector<fem::TemperatureMeasurement> templugs;
    double tolerance = 5.0;                  ///< K, RMS residual accepted as a match
};

/// Thermocouple temperatures at one axial position, one per radius of LinerThermalCase::radii.
struct ThermocoupleStation {
    double z = 0.0;                    ///< m, liner frame
    std::vector<double> temperatures;  ///< K
};

struct LinerThermalCase {
    ThermalBodyMesh mesh;
    fem::ElasticMaterial material;
    double expansion = 0.0;                   ///< 1/K
    std::vector<double> radii;                ///< m, 1 or 2 thermocouple depths (increasing)
    std::vector<ThermocoupleStation> stations;  ///< sorted by increasing z
    std::vector<fem::FixedGroup> held{{"top_seat", fem::kZ}};
    std::string reference = "top_seat";
    std::vector<std::string> surface{"bore"};
};

struct ThermalCase {
    std::string file;                        ///< the case file as given (messages)
    std::string name;
    double referenceTemperature = 293.15;    ///< K, stress-free (assembly) temperature
    int axialNodes = 64, circumferentialNodes = 96;
    std::string outputDirectory;             ///< absolute; "" = not given
    std::optional<PistonThermalCase> piston;
    std::optional<LinerThermalCase> liner;
};

}  // namespace flexehd::cosim
