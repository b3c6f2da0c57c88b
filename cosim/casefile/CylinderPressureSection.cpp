// cylinder_pressure: the pressure table the case names (docs/case-file.md, "cylinder_pressure").
#include "cosim/casefile/CaseSections.hpp"

#include <exception>
#include <filesystem>
#include <string>

#include "cosim/casefile/PressureTable.hpp"

namespace flexehd::cosim::casefile {

void readCylinderPressure(const YamlSection& top, EngineCase& c) {
    const std::string csv =
        text(top, "cylinder_pressure", "",
             "the path of the cylinder-pressure CSV (crank angle in deg, pressure in Pa)", true);
    const std::filesystem::path resolved = top.source().resolve(csv);
    c.cylinderPressureFile = resolved.string();
    try {
        c.cylinderPressure = readPressureTable(c.cylinderPressureFile);
    } catch (const std::exception& e) {
        top.fail("cylinder_pressure", e.what());
    }
}

}  // namespace flexehd::cosim::casefile
