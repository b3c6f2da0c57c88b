#pragma once
// The study file of `flexehd sweep`: a base case, the case-file keys to vary and how
// (full-factorial lists and ranges, a table of variants, or a Latin hypercube), the outputs
// to collect, and optionally the recipes of reduced bodies built per variant. Read into a
// Study with every variant expanded. Every key: docs/sweep.md.
//
// Errors are std::runtime_error messages "STUDY.yaml: key (line N): reason"; a parameter
// that names no case-file key is an error before anything runs.
#include <map>
#include <string>
#include <vector>

namespace flexehd::cosim {

/// One variant: a value for every parameter of the study, as YAML text in flow style.
struct StudyVariant {
    int index = 0;
    std::string id;                   ///< directory name, "v0000", "v0001", …
    std::vector<std::string> values;  ///< aligned with Study::parameters
};

/// `flexehd reduce` options of a body built per variant (`reduce.piston`, `reduce.liner`).
struct BodyRecipe {
    std::string mesh;                                          ///< absolute path
    std::vector<std::pair<std::string, std::string>> options;  ///< option → value (YAML text)
};

struct StudyRunOptions {
    int cycles = 0;              ///< `flexehd run --cycles`; 0 = the case's max_cycles
    bool rigid = false;          ///< `flexehd run --rigid`
    double timeoutSeconds = 0;   ///< a variant running longer is stopped and failed; 0 = none
};

struct Study {
    std::string path;       ///< the study file as given (for messages)
    std::string name;
    std::string baseCase;   ///< absolute
    std::string directory;  ///< absolute results directory of the study
    std::string design;     ///< full_factorial, table or latin_hypercube
    std::vector<std::string> parameters;                     ///< dotted keys, in file order
    std::vector<std::pair<std::string, std::string>> fixed;  ///< `set`: key → value for every variant
    std::vector<StudyVariant> variants;
    std::vector<std::string> outputs;                        ///< summary.json keys, dotted for nested
    StudyRunOptions run;
    std::map<std::string, BodyRecipe> reduce;                ///< "piston" / "liner"
};

/// The summary.json keys collected when the study names no `outputs`.
const std::vector<std::string>& defaultStudyOutputs();

/// Reads, expands and validates a study file. Relative paths resolve against its directory.
/// `directoryOverride` (if not empty) replaces the study's `directory`.
Study readStudyFile(const std::string& path, const std::string& directoryOverride = "");

/// Whether a parameter path addresses a reduced-body recipe (`reduce.piston.size`).
bool isReduceParameter(const std::string& path);

}  // namespace flexehd::cosim
