// `flexehd sweep STUDY.yaml`: a design study — the variants of a base case that a study file
// describes, each run by `flexehd run` into its own results directory, gathered into
// study.csv and study.json; distributed over MPI ranks under mpirun or srun (docs/sweep.md).
#include <memory>

#include <fmt/format.h>

#include "cosim/study/StudyFile.hpp"
#include "cosim/cli/CliSupport.hpp"
#include "cosim/cli/Commands.hpp"
#include "cosim/cli/SweepScheduler.hpp"

namespace flexehd::cli {
namespace {

struct SweepArgs {
    std::string studyPath;
    std::string out;
    bool dryRun = false;
    bool json = false;
    bool quiet = false;
};

void runSweep(const SweepArgs& a) {
    const cosim::Study study = cosim::readStudyFile(a.studyPath, a.out);
    if (a.dryRun) {
        fmt::print("study {}: {} design, {} variants, base case {} -> {}\n", study.name, study.design,
                   study.variants.size(), study.baseCase, study.directory);
        for (const auto& v : study.variants) {
            fmt::print("{}", v.id);
            for (std::size_t p = 0; p < study.parameters.size(); ++p)
                fmt::print("  {}={}", study.parameters[p], v.values[p]);
            fmt::print("\n");
        }
        return;
    }
    createOutputFolder(study.directory);
    const SweepReport r = runStudy(study, a.quiet);
    if (r.rank != 0) return;
    if (r.failed > 0) setExitCode(2);
    if (a.json) {
        printJson({{"study", study.name},
                   {"directory", study.directory},
                   {"ranks", r.ranks},
                   {"variants", r.variants},
                   {"ran", r.ran},
                   {"resumed", r.resumed},
                   {"ok", r.ok},
                   {"failed", r.failed},
                   {"seconds", r.seconds}});
    } else if (!a.quiet) {
        fmt::print("{} variants: {} ok, {} failed ({} run now, {} complete before) on {} rank{} in {:.1f} s\n"
                   "results: {}/study.csv\n",
                   r.variants, r.ok, r.failed, r.ran, r.resumed, r.ranks, r.ranks > 1 ? "s" : "", r.seconds,
                   study.directory);
    }
}

}  // namespace

void addSweepCommand(CLI::App& app) {
    auto a = std::make_shared<SweepArgs>();
    CLI::App* cmd = app.add_subcommand(
        "sweep", "Run a design study: variants of a case, one process or distributed with mpirun/srun");
    cmd->add_option("study", a->studyPath, "Study file (YAML, docs/sweep.md)")->required()->check(CLI::ExistingFile);
    cmd->add_option("--out", a->out, "Study results directory (default: the study's directory key)");
    cmd->add_flag("--dry-run", a->dryRun, "Check the study and list its variants; run nothing");
    cmd->add_flag("--json", a->json, "Print the study's counts as one JSON object on stdout");
    cmd->add_flag("--quiet", a->quiet, "No progress output");
    cmd->callback([a] {
        a->quiet = a->quiet || globalQuiet();
        runSweep(*a);
    });
}

}  // namespace flexehd::cli
