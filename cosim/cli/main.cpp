// flexehd: flexible-body elastohydrodynamic co-simulation of a piston in its liner.
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "cosim/cli/CliSupport.hpp"
#include "cosim/cli/Commands.hpp"
#include "lube/LargeArrayAllocator.hpp"

int main(int argc, char** argv) {
    // Freed blocks stay in the heap: the coupled Newton method (coupling.elastic_squeeze) and the
    // sparse factorizations allocate and free blocks of megabytes in every pass (page faults were
    // 40 % of the run time on a virtual machine, docs/coupling.md §4).
    flexehd::lube::retainFreedHeapMemory();
    flexehd::cli::followParentProcess();
    // Progress and diagnostics go to stderr so that stdout stays clean for --json.
    auto logger = spdlog::stderr_color_mt("flexehd");
    spdlog::set_default_logger(logger);
    spdlog::set_pattern("[%T.%e] %v");

    CLI::App app{"flexehd — flexible-body EHD co-simulation of an engine piston in its liner.\n"
                 "All quantities in SI units (m, s, kg, N, Pa, K)."};
    app.require_subcommand(1);
    app.set_version_flag("--version", "flexehd 0.1.0");
    bool quiet = false;
    app.add_flag("-q,--quiet", quiet, "No progress output: only warnings and errors on stderr (as a command's --quiet)");
    app.parse_complete_callback([&] {
        spdlog::set_level(quiet ? spdlog::level::warn : spdlog::level::info);
        flexehd::cli::setGlobalQuiet(quiet);
    });

    flexehd::cli::addModesCommand(app);
    flexehd::cli::addReduceCommand(app);
    flexehd::cli::addInspectCommand(app);
    flexehd::cli::addExportModesCommand(app);
    flexehd::cli::addBearingCommand(app);
    flexehd::cli::addRunCommand(app);
    flexehd::cli::addThermalCommand(app);
    flexehd::cli::addAcousticsCommand(app);
    flexehd::cli::addSweepCommand(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
        std::cerr << "flexehd: error: " << flexehd::cli::commandLineError(app, e, std::vector<std::string>(argv + 1, argv + argc)) << std::endl;
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "flexehd: error: " << e.what() << std::endl;
        return 1;
    }
    return flexehd::cli::exitCode();
}
