#pragma once
// One variant of a study run to completion without blocking the caller: writes its case
// file, builds the reduced bodies it needs that are not in the cache yet (`flexehd reduce`),
// then runs it (`flexehd run`), each as a child process logging to VARIANT_DIR/run.log.
// Every failure — bad values, a crashed or timed-out process — ends in a failed result.
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "cosim/study/StudyFile.hpp"
#include "fem/Stopwatch.hpp"
#include "cosim/study/StudyTable.hpp"
#include "cosim/cli/ChildProcess.hpp"

namespace flexehd::cli {

class VariantJob {
public:
    VariantJob(const cosim::Study& study, const cosim::StudyVariant& variant, int rank, std::string executable);

    /// Starts the next process when one has finished; true once the variant is done.
    bool poll();
    const cosim::VariantResult& result() const { return result_; }
    /// Stops the running process (interrupted study).
    void stop();

private:
    struct Step {
        std::vector<std::string> argv;
        std::string what;     ///< for messages: "building the piston body", "the run"
        std::string tmp, to;  ///< rename tmp → to after success (cached bodies)
    };
    void finish(const std::string& status, const std::string& message);
    std::string lastError() const;

    const cosim::Study& study_;
    std::string dir_, log_;
    std::deque<Step> steps_;
    std::unique_ptr<ChildProcess> child_;
    Step current_;
    fem::Stopwatch start_;
    cosim::VariantResult result_;
    bool done_ = false;
};

}  // namespace flexehd::cli
