// liner: the bore distortion, from a table file or inline Fourier orders (docs/case-file.md,
// "liner").
#include "cosim/casefile/CaseSections.hpp"

#include <exception>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "cosim/clearance/BoreDistortion.hpp"
#include "cosim/io/YamlKeys.hpp"

namespace flexehd::cosim::casefile {

/// liner.bore_distortion: {format: fourier, file: CSV} | {format: fourier, orders: [...]} |
/// {format: nodal, file: CSV}. Tables are read and checked here; errors name the key.
void readLiner(const YamlSection& top, const EngineSpec& engine, LinerSpec& l) {
    const YamlSection s(top.source(), top.get("liner"), "liner", {"bore_distortion"});
    if (!s.has("bore_distortion")) return;
    const YamlSection d(s.source(), s.get("bore_distortion"), s.keyPath("bore_distortion"),
                    {"format", "file", "orders", "field"});
    BoreDistortionSpec& b = l.boreDistortion;
    if (!d.has("format")) d.missing("format", "fourier (orders per axial position) or nodal (an FE result)");
    const bool fourier = choice(d, "format", {"fourier", "nodal"}, 0) == 0;
    if (d.has("file") && d.has("orders"))
        d.fail("orders", "give either file (a CSV table) or orders (an inline table), not both");
    if (!fourier && d.has("orders"))
        d.fail("orders", "an inline table needs format: fourier; a nodal FE result is read from a file");
    if (!d.has("file") && !d.has("orders"))
        d.missing("file", fourier ? "the Fourier table (CSV), or an inline table under orders"
                                  : "the FE result on the bore (CSV: x, y, z, ux, uy, uz or ur; or a .vtu)");
    if (d.has("file")) {
        b.file = d.source().resolve(text(d, "file", "", "a file path")).string();
        if (d.has("field") && (fourier || !isVtuFile(b.file)))
            d.fail("field", "names the point-data array of a nodal result in a .vtu file; this table is a CSV");
        const std::string field = text(d, "field", "displacement", "the point-data array of the .vtu file");
        try {
            if (fourier)
                b.fourier = readFourierTable(b.file, engine.bore);
            else
                b.nodes = readBoreNodes(b.file, engine.bore, field);
        } catch (const std::exception& e) {
            d.fail("file", e.what());
        }
        b.format = fourier ? BoreDistortionFormat::Fourier : BoreDistortionFormat::Nodal;
        return;
    }
    const YAML::Node list = d.get("orders");
    const std::string expected = "a list of {z or depth, order, amplitude, phase or phase_deg} mappings";
    if (!list.IsSequence() || list.size() == 0) d.fail("orders", "expected " + expected + ", got " + describeNode(list));
    std::vector<std::string> paths;
    for (std::size_t i = 0; i < list.size(); ++i) {
        paths.push_back(fmt::format("{}[{}]", d.keyPath("orders"), i));
        const YamlSection e(d.source(), list[i], paths.back(), {"z", "depth", "order", "amplitude", "phase", "phase_deg"});
        if (!list[i].IsMap())
            d.source().fail(paths.back(), list[i], "expected " + expected + ", got " + describeNode(list[i]));
        FourierTerm t;
        if (e.has("z") == e.has("depth"))
            e.fail(e.has("z") ? "depth" : "z", "give exactly one of z (m, liner frame) and depth (m below the liner top)");
        t.z = e.has("z") ? number(e, "z", kLength, Sign::Any, 0.0) : -number(e, "depth", kLength, Sign::Any, 0.0);
        if (!e.has("order")) e.missing("order", "a whole number from 0 to 100 (the Fourier order)");
        t.order = integer(e, "order", 0, 100, 0, "");
        t.amplitude = number(e, "amplitude", {"radial amplitude", "m"}, Sign::Any, 0.0, true);
        if (e.has("phase") == e.has("phase_deg"))
            e.fail(e.has("phase") ? "phase_deg" : "phase", "give exactly one of phase (rad) and phase_deg (deg)");
        t.phase = e.has("phase") ? number(e, "phase", {"angle", "rad"}, Sign::Any, 0.0)
                                 : number(e, "phase_deg", {"angle", "deg"}, Sign::Any, 0.0) * kDeg;
        b.fourier.push_back(t);
    }
    if (const auto problem = checkFourierTerms(b.fourier, engine.bore))
        d.source().fail(paths[problem->index], list[problem->index],
             problem->message + (problem->first != problem->index ? " (first at " + paths[problem->first] + ")" : ""));
    sortFourierTerms(b.fourier);
    b.format = BoreDistortionFormat::Fourier;
}

}  // namespace flexehd::cosim::casefile
