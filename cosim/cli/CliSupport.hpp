#pragma once
// Small pieces shared by the subcommands: timing and the JSON / table output conventions.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "fem/Material.hpp"
#include "fem/MeshReader.hpp"
#include "fem/PeakMemory.hpp"
#include "fem/Stopwatch.hpp"

namespace flexehd::cli {

using fem::Stopwatch;

/// Number checks whose messages say what is expected, as people write it ("expected a number
/// > 0, got 'abc'"): non-numbers, NaN and infinities are refused by each.
CLI::Validator positiveNumber();                       ///< > 0
CLI::Validator nonNegativeNumber();                    ///< ≥ 0
CLI::Validator numberFromTo(double lo, double hi);     ///< lo ≤ x ≤ hi
CLI::Validator wholeNumberFromTo(long lo, long hi);    ///< an integer, lo ≤ n ≤ hi
CLI::Validator positiveWholeNumber();                  ///< an integer ≥ 1

/// The message of a command-line error for `flexehd: error: …`: in flexehd's words where CLI11's
/// would puzzle (an unknown or missing command with the list of commands, an option given twice),
/// otherwise CLI11's text with the option first; then the help hint. `args` are the arguments
/// after the program name.
std::string commandLineError(const CLI::App& app, const CLI::ParseError& e, const std::vector<std::string>& args);

/// Creates the output folder `dir` (and its parents) or throws "cannot create the output folder
/// DIR: REASON" with the reason in words (a parent is a file, permission denied, read-only file
/// system, a kernel file system).
void createOutputFolder(const std::string& dir);

/// Before the work of a command that writes the single file `file`: creates its folder (and the
/// folder's parents) or throws "cannot write the output file FILE: REASON" with the reason in
/// words (as createOutputFolder's; also when FILE is a folder).
void prepareOutputFile(const std::string& file);

/// The mesh options every mesh-reading subcommand shares: --mesh, --order, --size.
struct MeshArguments {
    std::string path;
    fem::MeshOptions options;
};
void addMeshOptions(CLI::App* cmd, MeshArguments& mesh);

/// The elastic material options: --E, --nu, --rho (all required, SI).
void addMaterialOptions(CLI::App* cmd, fem::ElasticMaterial& material);

/// The global -q/--quiet: set by main once the command line is parsed; a command with its own
/// --quiet is quiet with either (one meaning everywhere: no progress output).
void setGlobalQuiet(bool quiet);
bool globalQuiet();

/// The exit code of a command that ran to its end but wants to report a partial result (sweep:
/// 2 when some variants failed); errors still exit with 1. main returns it.
void setExitCode(int code);
int exitCode();

/// A process that `flexehd sweep` started (FLEXEHD_PARENT_PID set) ends when its parent does,
/// also when the parent was killed with SIGKILL and could not stop it: it asks the kernel for
/// SIGTERM on the parent's death, and exits at once if the parent is already gone.
void followParentProcess();

/// Peak resident memory of this process so far, MiB (getrusage).
using fem::peakMemoryMiB;

/// Prints a JSON document on stdout (the `--json` convention: nothing else goes there).
void printJson(const nlohmann::json& doc);

}  // namespace flexehd::cli
