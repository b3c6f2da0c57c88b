#pragma once
// OutputEstimate: how much a run will write, judged before it starts (docs/results-format.md,
// "How much a run writes"). history.csv grows by one row per accepted step, and a step never
// exceeds time.max_step_deg, so a cycle has at least 720 / max_step_deg rows; the VTK series adds
// 720 / output.vtk_every_deg snapshots per cycle. The bytes per row and per snapshot come from the
// run's real column count, film grid and body meshes, calibrated against the files a run writes
// (the VTK files are LZ4-compressed). runCase refuses a run whose steps or files cannot fit
// (std::runtime_error naming the keys) and warns about one that may not.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace flexehd::cosim {

struct EngineCase;
class PistonSimulation;

/// What a run writes, as counts: the inputs of the estimate.
struct OutputLayout {
    double maxStepDeg = 0.5;   ///< time.max_step_deg
    double vtkEveryDeg = 0.0;  ///< output.vtk_every_deg (0: no series)
    int maxCycles = 1;         ///< time.max_cycles
    int historyColumns = 0;    ///< history.csv's columns (HistoryWriter's + the contacts')
    long filmPoints = 0;       ///< points of a film snapshot (the grid, closed at the seam)
    int filmFields = 0;        ///< scalar fields of a film snapshot
    long linerOilCells = 0;    ///< points of a liner-oil snapshot (0: none)
    struct Body {
        long nodes = 0, cells = 0;
        int nodesPerCell = 4;
        int vectorFields = 1;  ///< displacement (and the elastic part) per snapshot
        int modes = 0;         ///< mode shapes written once (0: none)
    };
    std::vector<Body> bodies;  ///< the flexible bodies, written with every snapshot
};

/// The estimate, in bytes (doubles: a 1e-6° step gives numbers beyond any integer file size).
struct OutputEstimate {
    double stepsPerCycle = 0.0;        ///< at least 720 / max_step_deg
    double historyRowBytes = 0.0;
    double historyBytesPerCycle = 0.0;
    double snapshotsPerCycle = 0.0;
    double snapshotBytes = 0.0;        ///< film + bodies + liner oil, one snapshot
    double vtkBytesPerCycle = 0.0;
    double modeShapeBytes = 0.0;       ///< once per run
    double bytesPerCycle = 0.0;        ///< history + VTK of one cycle
    /// On disk at the end of max_cycles: the whole history, the series of at most two cycles (the
    /// last complete one and the one being written; older ones are deleted) and the mode shapes.
    double totalBytes = 0.0;
    int maxCycles = 1;
};

/// Bytes of history.csv per value (9 significant digits, sign, exponent, comma; zeros and the
/// integer columns are shorter): engine86 writes 8.7 on average, 12 keeps a margin.
inline constexpr double kHistoryBytesPerValue = 12.0;
/// Steps per cycle from which a run is refused: time.max_step_deg ≤ 7.2e-5°.
inline constexpr double kMaxStepsPerCycle = 1e7;
/// Steps per cycle from which a run is warned about: time.max_step_deg ≤ 7.2e-4°.
inline constexpr double kManyStepsPerCycle = 1e6;
/// A run estimated to write more than this is refused, whatever the free space.
inline constexpr double kOutputCeilingBytes = 1e12;
/// A run estimated to write more than this is warned about.
inline constexpr double kLargeOutputBytes = 10e9;
/// The least wall time a step takes, for the run time a step count implies: the coarse rigid
/// engine86 grid (24 x 72) takes ~0.17 ms per step of 0.001° (~2 ms per 0.5° step).
inline constexpr double kMinSecondsPerStep = 1e-4;

OutputEstimate estimateOutput(const OutputLayout& layout);

/// The layout of a run of `c` by `sim` (its contacts added).
OutputLayout outputLayout(const EngineCase& c, const PistonSimulation& sim);

/// The verdict on an estimate against the free bytes of the output folder's file system (empty:
/// unknown): a refusal (empty: none) and warnings, each naming the keys that drive it.
struct OutputVerdict {
    std::string refusal;
    std::vector<std::string> warnings;
};
OutputVerdict judgeOutput(const OutputLayout& layout, const OutputEstimate& e, std::optional<double> freeBytes);

/// Estimates the run of `c` by `sim` into `directory` (existing), passes the warnings to `warn`
/// and throws std::runtime_error with the refusal.
void checkOutputEstimate(const EngineCase& c, const PistonSimulation& sim, const std::string& directory,
                         const std::function<void(const std::string&)>& warn);

}  // namespace flexehd::cosim
