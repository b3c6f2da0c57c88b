// thermal: the thermal-displacement file of `flexehd thermal` (docs/case-file.md, "thermal").
#include "cosim/casefile/CaseSections.hpp"

#include <exception>
#include <string>

#include "cosim/clearance/ThermalDisplacementFile.hpp"

namespace flexehd::cosim::casefile {

/// thermal: {file: thermal.h5}. With options.checkBodyFiles the file is read and validated.
void readThermal(const YamlSection& top, const CaseFileOptions& options, ThermalSpec& t) {
    if (!top.has("thermal")) return;
    const YamlSection s(top.source(), top.get("thermal"), "thermal", {"file"});
    const std::string file =
        text(s, "file", "", "the thermal-displacement file (HDF5, from `flexehd thermal`)", true);
    t.file = s.source().resolve(file).string();
    if (options.checkBodyFiles) {
        try {
            (void)readThermalDisplacementFile(t.file);
        } catch (const std::exception& e) {
            s.fail("file", e.what());
        }
    }
}

}  // namespace flexehd::cosim::casefile
