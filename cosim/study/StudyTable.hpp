#pragma once
// The results of a study: one row per variant (parameters, status, error message, the
// collected summary.json outputs, run time), written as study.csv and study.json in the
// study directory, atomically, so a partial table is always a valid file (docs/sweep.md).
#include <string>
#include <vector>

#include "cosim/study/StudyFile.hpp"

namespace flexehd::cosim {

struct VariantResult {
    std::string status;                ///< "ok" or "failed"; empty: not run (yet)
    std::string message;               ///< why it failed
    std::vector<std::string> outputs;  ///< each of Study::outputs as text ("" if absent)
    double runSeconds = 0;             ///< wall time of the variant (its processes)
    int rank = 0;                      ///< MPI rank that ran it
    bool resumed = false;              ///< found complete in its directory, not run again
};

/// STUDY_DIR/variants/ID: the results directory of a variant.
std::string variantDirectory(const Study& study, const StudyVariant& variant);

/// The result recorded in a variant's summary.json: status "ok" or "failed" with its message
/// and outputs; status empty if the file is missing or not a complete JSON document.
VariantResult readVariantResult(const Study& study, const std::string& summaryPath);

/// Rewrites study.csv (the finished variants, by index) and study.json (all variants, with
/// status "pending" for those not finished), each atomically. `results` is indexed like
/// Study::variants.
void writeStudyTables(const Study& study, const std::vector<VariantResult>& results);

/// A result as one line of text and back (how ranks send results to rank 0).
std::string serializeResult(const VariantResult& r);
VariantResult deserializeResult(const std::string& text);

}  // namespace flexehd::cosim
