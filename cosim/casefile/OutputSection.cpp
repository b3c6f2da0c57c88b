// output: the results directory and what goes into it (docs/case-file.md, "output").
#include "cosim/casefile/CaseSections.hpp"

#include <filesystem>
#include <system_error>

#include <fmt/format.h>

namespace flexehd::cosim::casefile {

void readOutput(const YamlSection& top, OutputSpec& o) {
    namespace fs = std::filesystem;
    const YamlSection output(top.source(), top.get("output"), "output", {"directory", "vtk_every_deg", "mode_shapes"});
    const fs::path dir = output.source().resolve(text(output, "directory", "results", "a directory path"));
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        output.fail("directory", fmt::format("{} exists and is not a directory", dir.string()));
    o.directory = dir.string();
    o.vtkEveryDeg = number(output, "vtk_every_deg", {"crank-angle spacing (0 = no VTK)", "deg"}, Sign::NonNegative,
                           o.vtkEveryDeg);
    if (o.vtkEveryDeg > 720.0 || (o.vtkEveryDeg > 0.0 && o.vtkEveryDeg < 0.01))
        output.fail("vtk_every_deg",
                    fmt::format("expected 0 (no VTK) or 0.01 to 720 deg, got {:g}: a snapshot every 0.01 deg is already "
                                "72 000 files per cycle, and snapshots closer than the time steps only shorten them",
                                o.vtkEveryDeg));
    o.modeShapes = boolean(output, "mode_shapes", o.modeShapes);
}

}  // namespace flexehd::cosim::casefile
