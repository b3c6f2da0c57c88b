#pragma once
// Runs the variants of a study that are not complete yet, in this process alone or, when
// started by an MPI launcher (mpirun, srun), over all ranks: rank 0 hands out variant
// indices one at a time to whichever rank asks (a rank that finishes asks for the next),
// runs variants itself meanwhile, gathers the results and rewrites study.csv and study.json
// after each one. The only part of flexehd that knows MPI (docs/sweep.md).
#include <string>

#include "cosim/study/StudyFile.hpp"

namespace flexehd::cli {

struct SweepReport {
    int rank = 0;   ///< this process's rank; only rank 0's report has the counts
    int ranks = 1;
    int variants = 0, ran = 0, resumed = 0, ok = 0, failed = 0;
    double seconds = 0;
};

/// Runs the study; rank 0 prints a progress line per variant on stderr unless `quiet`.
SweepReport runStudy(const cosim::Study& study, bool quiet);

/// Whether an MPI launcher started this process (Open MPI, PMIx or PMI environment).
bool launchedByMpi();

}  // namespace flexehd::cli
