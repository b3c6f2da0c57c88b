#include "cosim/cli/VariantJob.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>

#include <fmt/format.h>

#include "cosim/study/BodyCache.hpp"
#include "cosim/study/VariantCase.hpp"
#include "fem/AtomicFile.hpp"

namespace flexehd::cli {

namespace fs = std::filesystem;

VariantJob::VariantJob(const cosim::Study& study, const cosim::StudyVariant& variant, int rank, std::string executable)
    : study_(study), dir_(cosim::variantDirectory(study, variant)), log_(dir_ + "/run.log") {
    result_.rank = rank;
    try {
        fs::create_directories(dir_);
        fs::remove(dir_ + "/summary.json");  // an old one must not pass for this run's
        std::ofstream(log_, std::ios::trunc) << fmt::format("# flexehd sweep: variant {} on rank {}\n", variant.id, rank);
        std::map<std::string, std::string> files;
        for (const auto& b : cosim::variantBodies(study, variant)) {
            files[b.body] = b.file;
            if (fs::exists(b.file)) continue;  // cached
            fs::create_directories(fs::path(b.file).parent_path());
            Step s{{executable}, "building the " + b.body + " body", "", b.file};
            s.tmp = fmt::format("{}.building-{}-{}.h5", b.file, rank, ::getpid());
            s.argv.insert(s.argv.end(), b.args.begin(), b.args.end());
            s.argv.insert(s.argv.end(), {"--out", s.tmp});
            steps_.push_back(std::move(s));
        }
        const std::string text = cosim::variantCaseText(study, variant, files);
        fem::writeTextAtomically(dir_ + "/case.yaml", text);
        Step run{{executable, "run", dir_ + "/case.yaml", "--out", dir_, "--quiet"}, "the run", "", ""};
        if (study.run.rigid) run.argv.push_back("--rigid");
        if (study.run.cycles > 0) run.argv.insert(run.argv.end(), {"--cycles", std::to_string(study.run.cycles)});
        steps_.push_back(std::move(run));
    } catch (const std::exception& e) {
        finish("failed", e.what());
    }
}

void VariantJob::finish(const std::string& status, const std::string& message) {
    if (status == "ok") {
        const int rank = result_.rank;
        result_ = cosim::readVariantResult(study_, dir_ + "/summary.json");
        result_.rank = rank;
    } else {
        result_.status = status;
        result_.message = message;
        result_.outputs.assign(study_.outputs.size(), "");
    }
    result_.runSeconds = start_.seconds();
    done_ = true;
}

std::string VariantJob::lastError() const {
    std::ifstream f(log_);
    std::string line, error, last;
    const std::string tag = "flexehd: error: ";
    while (std::getline(f, line)) {
        if (line.rfind(tag, 0) == 0) error = line.substr(tag.size());
        if (!line.empty() && line[0] != '#') last = line;
    }
    return error.empty() ? last : error;
}

bool VariantJob::poll() {
    if (done_) return true;
    if (study_.run.timeoutSeconds > 0 &&
        start_.seconds() > study_.run.timeoutSeconds) {
        stop();
        finish("failed", fmt::format("timed out after {} s ({})", study_.run.timeoutSeconds, current_.what));
        return true;
    }
    if (child_) {
        const auto status = child_->poll();
        if (!status) return false;
        child_.reset();
        const bool exited0 = WIFEXITED(*status) && WEXITSTATUS(*status) == 0;
        if (current_.what == "the run") {
            // A run that ends writes summary.json, failed or not; its message is the clean one.
            const cosim::VariantResult s = cosim::readVariantResult(study_, dir_ + "/summary.json");
            if (exited0 && s.status == "ok") finish("ok", "");
            else if (s.status == "failed") finish("failed", s.message);
            else {
                // An error message of flexehd says it all; a crash or kill is told by the wait status.
                const std::string e = lastError();
                finish("failed", exited0                          ? "the run wrote no complete summary.json"
                                 : WIFEXITED(*status) && !e.empty() ? e
                                                                    : fmt::format("{} ({})", e, describeWaitStatus(*status)));
            }
            return true;
        }
        if (!exited0) {
            fs::remove(current_.tmp);
            finish("failed", fmt::format("{} failed: {} ({})", current_.what, lastError(), describeWaitStatus(*status)));
            return true;
        }
        std::error_code ec;
        fs::rename(current_.tmp, current_.to, ec);  // atomic: a concurrent build of the same body is harmless
        if (ec) {
            finish("failed", fmt::format("{}: cannot rename {}: {}", current_.what, current_.tmp, ec.message()));
            return true;
        }
    }
    if (steps_.empty()) return done_;
    current_ = steps_.front();
    steps_.pop_front();
    if (!current_.to.empty() && fs::exists(current_.to)) return poll();  // built meanwhile by another rank
    try {
        child_ = std::make_unique<ChildProcess>(current_.argv, log_);
    } catch (const std::exception& e) {
        finish("failed", e.what());
        return true;
    }
    return false;
}

void VariantJob::stop() {
    if (child_) child_->terminate();
    child_.reset();
}

}  // namespace flexehd::cli
