#include "cosim/cli/SweepScheduler.hpp"
#include "fem/Stopwatch.hpp"
#include "fem/AtomicFile.hpp"

#define OMPI_SKIP_MPICXX 1  // the C API only (Open MPI's mpi.h pulls in the deprecated C++ bindings)
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "cosim/study/BodyCache.hpp"
#include "cosim/study/StudyTable.hpp"
#include "cosim/study/VariantCase.hpp"
#include "cosim/cli/VariantJob.hpp"

namespace flexehd::cli {
namespace {

namespace fs = std::filesystem;

constexpr int kTagResult = 1;  // rank → 0: "INDEX\nRESULT" (INDEX −1: first request)
constexpr int kTagAssign = 2;  // 0 → rank: the next variant index, −1 = no more
constexpr auto kPollInterval = std::chrono::milliseconds(5);

volatile std::sig_atomic_t g_signal = 0;
extern "C" void onSignal(int sig) { g_signal = sig; }

/// MPI_Init / MPI_Finalize when an MPI launcher started us; otherwise one process, no MPI.
class MpiSession {
public:
    MpiSession() {
        if (!launchedByMpi()) return;
        MPI_Init(nullptr, nullptr);
        active_ = true;
        MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
        MPI_Comm_size(MPI_COMM_WORLD, &size_);
    }
    ~MpiSession() {
        if (active_) MPI_Finalize();
    }
    int rank() const { return rank_; }
    int size() const { return size_; }

private:
    bool active_ = false;
    int rank_ = 0, size_ = 1;
};

/// Interrupted (SIGINT, SIGTERM from the launcher): stop the running child and leave at once;
/// study.csv and study.json already hold every finished variant.
void leaveIfInterrupted(VariantJob* job) {
    if (!g_signal) return;
    if (job) job->stop();
    std::_Exit(128 + g_signal);
}

/// Whether a variant's directory holds the complete results of this very variant: the same
/// case file (so the study was not edited since) and a summary.json with status ok.
bool complete(const cosim::Study& study, const cosim::StudyVariant& v, cosim::VariantResult& result) {
    try {
        std::map<std::string, std::string> files;
        for (const auto& b : cosim::variantBodies(study, v)) files[b.body] = b.file;
        const std::string dir = cosim::variantDirectory(study, v);
        std::ifstream f(dir + "/case.yaml");
        const std::string old(std::istreambuf_iterator<char>(f), {});
        if (!f || old != cosim::variantCaseText(study, v, files)) return false;
        result = cosim::readVariantResult(study, dir + "/summary.json");
        result.resumed = true;
        return result.status == "ok";
    } catch (const std::exception&) {
        return false;  // the variant will fail with this error when it runs
    }
}

std::string valuesText(const cosim::Study& s, const cosim::StudyVariant& v) {
    std::string t;
    for (std::size_t p = 0; p < s.parameters.size(); ++p)
        t += fmt::format("{}{}={}", p ? ", " : "", s.parameters[p], v.values[p]);
    return t;
}

void sendText(const std::string& text, int to, int tag) {
    MPI_Send(text.data(), int(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

/// Ranks > 0: ask for a variant, run it, send its result with the next request.
void worker(const cosim::Study& study, int rank, const std::string& exe) {
    sendText("-1\n", 0, kTagResult);
    while (true) {
        int flag = 0;
        while (!flag) {
            leaveIfInterrupted(nullptr);
            MPI_Iprobe(0, kTagAssign, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE);
            if (!flag) std::this_thread::sleep_for(kPollInterval);
        }
        int index = -1;
        MPI_Recv(&index, 1, MPI_INT, 0, kTagAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (index < 0) return;
        VariantJob job(study, study.variants[std::size_t(index)], rank, exe);
        while (!job.poll()) {
            leaveIfInterrupted(&job);
            std::this_thread::sleep_for(kPollInterval);
        }
        sendText(fmt::format("{}\n{}", index, cosim::serializeResult(job.result())), 0, kTagResult);
    }
}

}  // namespace

bool launchedByMpi() {
    for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
        if (std::getenv(v)) return true;
    return false;
}

SweepReport runStudy(const cosim::Study& study, bool quiet) {
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    const fem::Stopwatch start;
    MpiSession mpi;
    SweepReport rep;
    rep.rank = mpi.rank();
    rep.ranks = mpi.size();
    const std::string exe = currentExecutable();
    if (mpi.rank() > 0) {
        worker(study, mpi.rank(), exe);
        return rep;
    }
    auto log = [&](const std::string& s) {
        if (!quiet) fmt::print(stderr, "{}\n", s);
    };

    // Rank 0: what is already complete (resume), then the dispatch loop.
    const std::size_t n = study.variants.size();
    rep.variants = int(n);
    std::vector<cosim::VariantResult> results(n);
    std::deque<int> queue;
    for (std::size_t i = 0; i < n; ++i) {
        if (complete(study, study.variants[i], results[i])) {
            ++rep.resumed;
            ++rep.ok;
        } else {
            results[i] = {};
            queue.push_back(int(i));
        }
    }
    fs::create_directories(study.directory);
    fem::removeStaleTemporaries(study.directory);
    cosim::writeStudyTables(study, results);
    log(fmt::format("flexehd sweep {}: {} variants ({} complete already), {} rank{} -> {}", study.path, n, rep.resumed,
                    mpi.size(), mpi.size() > 1 ? "s" : "", study.directory));

    auto record = [&](int index, const cosim::VariantResult& r) {
        results[std::size_t(index)] = r;
        ++rep.ran;
        ++(r.status == "ok" ? rep.ok : rep.failed);
        cosim::writeStudyTables(study, results);
        const auto& v = study.variants[std::size_t(index)];
        log(fmt::format("[{}/{}] {} ({}): {} in {:.1f} s on rank {}{}", rep.ok + rep.failed, n, v.id,
                        valuesText(study, v), r.status, r.runSeconds, r.rank,
                        r.message.empty() ? "" : ": " + r.message));
    };

    std::unique_ptr<VariantJob> own;
    int ownIndex = -1;
    int workers = mpi.size() - 1;  // ranks not yet told to stop
    while (own || !queue.empty() || workers > 0) {
        leaveIfInterrupted(own.get());
        bool busy = false;
        if (own && own->poll()) {
            record(ownIndex, own->result());
            own.reset();
            busy = true;
        }
        if (!own && !queue.empty()) {
            ownIndex = queue.front();
            queue.pop_front();
            own = std::make_unique<VariantJob>(study, study.variants[std::size_t(ownIndex)], 0, exe);
            busy = true;
        }
        int flag = 0;
        MPI_Status st;
        if (mpi.size() > 1) MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &flag, &st);
        if (flag) {
            int count = 0;
            MPI_Get_count(&st, MPI_CHAR, &count);
            std::string msg(std::size_t(count), '\0');
            MPI_Recv(msg.data(), count, MPI_CHAR, st.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            const auto nl = msg.find('\n');
            const int index = std::stoi(msg.substr(0, nl));
            if (index >= 0) record(index, cosim::deserializeResult(msg.substr(nl + 1)));
            int next = -1;
            if (!queue.empty()) {
                next = queue.front();
                queue.pop_front();
            } else {
                --workers;
            }
            MPI_Send(&next, 1, MPI_INT, st.MPI_SOURCE, kTagAssign, MPI_COMM_WORLD);
            busy = true;
        }
        if (!busy) std::this_thread::sleep_for(kPollInterval);
    }
    rep.seconds = start.seconds();
    return rep;
}

}  // namespace flexehd::cli
