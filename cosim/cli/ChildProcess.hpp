#pragma once
// A child process of the sweep (`flexehd run` or `flexehd reduce` of one variant), started with
// posix_spawn, its stdout and stderr appended to a log file, polled without blocking.
#include <sys/types.h>

#include <optional>
#include <string>
#include <vector>

namespace flexehd::cli {

class ChildProcess {
public:
    /// Starts argv[0] with the arguments argv[1…], stdin from /dev/null, stdout and stderr
    /// appended to `logPath`. Throws std::runtime_error if it cannot be started.
    ChildProcess(const std::vector<std::string>& argv, const std::string& logPath);
    ~ChildProcess();  ///< terminates a process still running
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    /// The wait status once the process has ended, nothing while it runs.
    std::optional<int> poll();
    /// SIGTERM, then SIGKILL after `graceSeconds`; waits for the end.
    void terminate(double graceSeconds = 2.0);

private:
    pid_t pid_ = -1;
    std::optional<int> status_;
};

/// "exit code 3", "killed by signal 9 (Killed)".
std::string describeWaitStatus(int status);

/// The path of the running executable (/proc/self/exe).
std::string currentExecutable();

}  // namespace flexehd::cli
