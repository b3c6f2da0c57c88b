#include "cosim/run/OutputEstimate.hpp"
#include "cosim/coupling/RunProgress.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include "cosim/case/EngineCase.hpp"
#include "cosim/contact/SkirtContact.hpp"
#include "cosim/coupling/MemoryBudget.hpp"  // formatBytes
#include "cosim/coupling/PistonSimulation.hpp"
#include "cosim/results/HistoryWriter.hpp"

namespace flexehd::cosim {
namespace {

// What LZ4 leaves of the raw arrays, measured on engine86 (docs/results-format.md): a film
// snapshot 0.31 (the 48 x 144 grid, 142 kB), a piston snapshot 0.75 (12484 TET10 nodes, 1.09 MB),
// a mode shape 0.68 (787 kB); rounded up.
constexpr double kFilmShare = 0.4;
constexpr double kBodyShare = 0.8;
constexpr double kModeShare = 0.75;

// Raw bytes of a body mesh file: the points, the vector fields, the connectivity (Int64), the
// offsets (Int64) and the cell types (UInt8).
double bodyBytes(const OutputLayout::Body& b, int vectors) {
    return double(b.nodes) * 3 * 8 * (1 + vectors) + double(b.cells) * (b.nodesPerCell * 8 + 8 + 1);
}

}  // namespace

OutputEstimate estimateOutput(const OutputLayout& l) {
    OutputEstimate e;
    e.maxCycles = std::max(1, l.maxCycles);
    e.stepsPerCycle = 720.0 / l.maxStepDeg;
    e.historyRowBytes = l.historyColumns * kHistoryBytesPerValue;
    e.historyBytesPerCycle = e.stepsPerCycle * e.historyRowBytes;
    if (l.vtkEveryDeg > 0.0) {
        e.snapshotsPerCycle = std::floor(720.0 / l.vtkEveryDeg + 1e-9);
        // The film: points (3 doubles), the scalar fields and node_kind (a byte) per point.
        e.snapshotBytes = kFilmShare * double(l.filmPoints) * (3 * 8 + l.filmFields * 8 + 1);
        e.snapshotBytes += kFilmShare * double(l.linerOilCells) * (3 * 8 + 8);
        for (const OutputLayout::Body& b : l.bodies) e.snapshotBytes += kBodyShare * bodyBytes(b, b.vectorFields);
    }
    e.vtkBytesPerCycle = e.snapshotsPerCycle * e.snapshotBytes;
    for (const OutputLayout::Body& b : l.bodies) e.modeShapeBytes += kModeShare * b.modes * bodyBytes(b, 1);
    e.bytesPerCycle = e.historyBytesPerCycle + e.vtkBytesPerCycle;
    e.totalBytes = e.maxCycles * e.historyBytesPerCycle + std::min(e.maxCycles, 2) * e.vtkBytesPerCycle +
                   e.modeShapeBytes;
    return e;
}

OutputLayout outputLayout(const EngineCase& c, const PistonSimulation& sim) {
    OutputLayout l;
    l.maxStepDeg = c.time.maxStepDeg;
    l.vtkEveryDeg = c.output.vtkEveryDeg;
    l.maxCycles = c.time.maxCycles;
    l.historyColumns = int(HistoryWriter::columns(sim.carriesOil()).size() + sim.contactColumns().size());
    const SkirtContact& skirt = sim.contact<SkirtContact>();
    const lube::FilmGrid& g = skirt.film().grid();
    l.filmPoints = long(g.nTheta() + (g.periodic() ? 1 : 0)) * g.nAxial();
    // pressure, film thickness, contact pressure, shear stress, cavitation; the film fraction of
    // the mass-conserving film
    l.filmFields = 5 + (sim.carriesOil() ? 1 : 0);
    if (c.lubricant.supply.model == OilSupplyModel::LinerLayer) l.linerOilCells = l.filmPoints;  // about the grid's
    for (const FlexibleSurface* body : {skirt.piston(), skirt.liner()}) {
        if (!body) continue;
        const fem::Mesh& mesh = body->body().mesh;
        OutputLayout::Body b;
        b.nodes = mesh.numNodes();
        b.cells = mesh.volume.size();
        b.nodesPerCell = int(mesh.volume.nodes.rows());
        b.vectorFields = body == skirt.piston() ? 2 : 1;  // the piston's elastic part too
        b.modes = c.output.modeShapes ? body->body().numModes() : 0;
        l.bodies.push_back(b);
    }
    return l;
}

OutputVerdict judgeOutput(const OutputLayout& l, const OutputEstimate& e, std::optional<double> freeBytes) {
    OutputVerdict v;
    const std::string history = fmt::format(
        "history.csv ~{} per cycle (at least 720 / time.max_step_deg {:g} = {:.3g} rows of {} columns, ~{:.0f} bytes "
        "each)",
        formatBytes(e.historyBytesPerCycle), l.maxStepDeg, e.stepsPerCycle, l.historyColumns, e.historyRowBytes);
    const std::string vtk =
        e.snapshotsPerCycle > 0
            ? fmt::format("the VTK series ~{} per cycle (output.vtk_every_deg {:g}: {:.0f} snapshots of ~{})",
                          formatBytes(e.vtkBytesPerCycle), l.vtkEveryDeg, e.snapshotsPerCycle,
                          formatBytes(e.snapshotBytes))
            : std::string("no VTK series (output.vtk_every_deg 0)");
    const std::string sizes = fmt::format("estimated output: {}, {}; ~{} for time.max_cycles {}", history, vtk,
                                          formatBytes(e.totalBytes), e.maxCycles);
    // What the user could set instead: the keys whose share is large.
    std::vector<std::string> remedies;
    if (e.historyBytesPerCycle >= e.vtkBytesPerCycle || e.stepsPerCycle >= kManyStepsPerCycle)
        remedies.push_back(fmt::format("a larger time.max_step_deg (the examples use 0.5; the step control shortens "
                                       "steps where the motion needs it, down to time.min_step_deg)"));
    if (e.vtkBytesPerCycle > e.historyBytesPerCycle)
        remedies.push_back("a larger output.vtk_every_deg (the examples use 10; 0 writes no series)");
    if (e.maxCycles > 2) remedies.push_back("fewer time.max_cycles (or --cycles)");
    std::string instead;
    for (std::size_t k = 0; k < remedies.size(); ++k)
        instead += (k == 0 ? "" : k + 1 == remedies.size() ? " or " : ", ") + remedies[k];
    instead = "; set " + instead;

    std::vector<std::string> reasons;
    if (e.stepsPerCycle >= kMaxStepsPerCycle)
        reasons.push_back(fmt::format(
            "time.max_step_deg {:g} forces at least {:.3g} steps per cycle (no step may exceed max_step_deg; the "
            "refusal starts at {:.0e} steps, max_step_deg <= {:g}): at ~{:g} ms per step that is at least {} per cycle",
            l.maxStepDeg, e.stepsPerCycle, kMaxStepsPerCycle, 720.0 / kMaxStepsPerCycle, kMinSecondsPerStep * 1e3,
            formatDuration(e.stepsPerCycle * kMinSecondsPerStep)));
    if (freeBytes && e.bytesPerCycle > *freeBytes)
        reasons.push_back(fmt::format("one cycle's output (~{}) exceeds the {} free on the output folder's file system",
                                      formatBytes(e.bytesPerCycle), formatBytes(*freeBytes)));
    if (std::max(e.bytesPerCycle, e.totalBytes) > kOutputCeilingBytes)
        reasons.push_back(fmt::format("the output (~{}) exceeds the ceiling of {} a run may write",
                                      formatBytes(std::max(e.bytesPerCycle, e.totalBytes)),
                                      formatBytes(kOutputCeilingBytes)));
    if (!reasons.empty()) {
        std::string why;
        for (std::size_t k = 0; k < reasons.size(); ++k) why += (k ? "; " : "") + reasons[k];
        v.refusal = fmt::format("refusing to run: {}. {}{}", why, sizes, instead);
        return v;
    }
    if (e.stepsPerCycle >= kManyStepsPerCycle)
        v.warnings.push_back(fmt::format("time.max_step_deg {:g} forces at least {:.3g} steps per cycle: at ~{:g} ms per "
                                         "step at least {} per cycle{}",
                                         l.maxStepDeg, e.stepsPerCycle, kMinSecondsPerStep * 1e3,
                                         formatDuration(e.stepsPerCycle * kMinSecondsPerStep), instead));
    if (freeBytes && e.totalBytes > *freeBytes)
        v.warnings.push_back(fmt::format("the run may fill its file system: {} free, {}{}", formatBytes(*freeBytes),
                                         sizes, instead));
    else if (e.totalBytes > kLargeOutputBytes)
        v.warnings.push_back(fmt::format("a large run: {}{}", sizes, instead));
    return v;
}

void checkOutputEstimate(const EngineCase& c, const PistonSimulation& sim, const std::string& directory,
                         const std::function<void(const std::string&)>& warn) {
    const OutputLayout layout = outputLayout(c, sim);
    const OutputEstimate e = estimateOutput(layout);
    std::optional<double> freeBytes;
    std::error_code ec;
    const std::filesystem::space_info space = std::filesystem::space(directory, ec);
    if (!ec && space.available != static_cast<std::uintmax_t>(-1)) freeBytes = double(space.available);
    const OutputVerdict v = judgeOutput(layout, e, freeBytes);
    if (!v.refusal.empty()) throw std::runtime_error(v.refusal);
    if (warn)
        for (const std::string& w : v.warnings) warn(w);
}

}  // namespace flexehd::cosim
