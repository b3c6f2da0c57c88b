#pragma once
// Subcommands of the `flexehd` command line; each lives in its own file and registers
// itself on the application. Conventions shared by all: `--json` prints one JSON object
// on stdout, progress goes to stderr, errors give a message on stderr and exit code 1.
#include <CLI/CLI.hpp>

namespace flexehd::cli {

void addModesCommand(CLI::App& app);
void addReduceCommand(CLI::App& app);
void addInspectCommand(CLI::App& app);
void addExportModesCommand(CLI::App& app);
void addBearingCommand(CLI::App& app);
void addRunCommand(CLI::App& app);
void addThermalCommand(CLI::App& app);
void addAcousticsCommand(CLI::App& app);
void addSweepCommand(CLI::App& app);

}  // namespace flexehd::cli
