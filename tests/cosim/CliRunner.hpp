#pragma once
// Runs the `flexehd` executable as a user would and captures what it prints, for the
// command-line tests (FLEXEHD_BINARY is set by tests/cosim/CMakeLists.txt).
#include <unistd.h>
#include <sys/wait.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace flexehd::test {

struct CommandResult {
    int status;       ///< exit code
    std::string out;  ///< stdout
    std::string err;  ///< stderr
};

/// The time a child process of a test may take by default: the test's own budget
/// (FLEXEHD_TEST_TIMEOUT_S, its ctest TIMEOUT) less the 10 s grace of `timeout` and a margin, so
/// that the child is stopped and the test says so before ctest stops the test.
inline int defaultChildTimeout() {
#ifdef FLEXEHD_TEST_TIMEOUT_S
    return FLEXEHD_TEST_TIMEOUT_S > 30 ? FLEXEHD_TEST_TIMEOUT_S - 15 : 15;
#else
    return 120;
#endif
}

/// `command` under coreutils `timeout`: SIGTERM after `seconds`, SIGKILL 10 s later if it is still
/// running. `timeout` runs it in a process group of its own and signals the whole group, so the
/// child's own children (a sweep's variants, mpirun's ranks) end with it.
inline std::string timeLimited(const std::string& command, int seconds) {
    return "timeout --kill-after=10s " + std::to_string(seconds) + " " + command;
}

/// Whether exit status `status` of a timeLimited command says that the limit stopped it (124:
/// ended by SIGTERM, 137: by SIGKILL); if so, a test failure naming `what` and the limit.
inline bool failedByTimeLimit(int status, const std::string& what, int seconds) {
    if (status != 124 && status != 137) return false;
    ADD_FAILURE() << what << " did not finish within " << seconds << " s (stopped, exit status " << status << ")";
    return true;
}

/// Runs `flexehd ARGS` through the shell (arguments must be shell-safe), stopped after
/// `timeoutSeconds` (a test failure then).
inline CommandResult runFlexehd(const std::string& args, int timeoutSeconds = defaultChildTimeout()) {
    const auto dir = std::filesystem::temp_directory_path();
    const std::string errFile = (dir / ("flexehd_cli_err_" + std::to_string(::getpid()))).string();
    const std::string cmd = timeLimited(std::string(FLEXEHD_BINARY) + " " + args, timeoutSeconds) + " 2>" + errFile;
    CommandResult r;
    FILE* p = popen(cmd.c_str(), "r");
    std::array<char, 4096> buf;
    while (std::size_t n = fread(buf.data(), 1, buf.size(), p)) r.out.append(buf.data(), n);
    r.status = WEXITSTATUS(pclose(p));
    std::ifstream e(errFile);
    r.err.assign(std::istreambuf_iterator<char>(e), {});
    std::filesystem::remove(errFile);
    failedByTimeLimit(r.status, "flexehd " + args, timeoutSeconds);
    return r;
}

/// Reduces the example piston on the coarse mesh (8 modes, skirt static correction, pin bore held)
/// into `file`: the flexible body of the small coupled tests (SmallEngineCase.hpp). Needs
/// FLEXEHD_SOURCE_DIR.
inline CommandResult reduceSmallPiston(const std::string& file) {
    return runFlexehd("reduce --mesh " + std::string(FLEXEHD_SOURCE_DIR) +
                      "/meshes/piston.geo --size 0.0065 --E 7.5e10 --nu 0.33 --rho 2700 --interface pin_bore:rbe2@0,0,0 "
                      "--modes 8 --static-correction skirt --axial-order 2 --circumferential-order 4 --out " + file);
}

/// The example engine's piston as scripts/example.sh reduces it (20 modes, skirt and crown patterns).
inline CommandResult reduceExamplePiston(const std::string& file) {
    return runFlexehd("reduce --mesh " + std::string(FLEXEHD_SOURCE_DIR) +
                      "/meshes/piston.geo --size 0.0065 --E 7.5e10 --nu 0.33 --rho 2700 --interface pin_bore:rbe2@0,0,0 "
                      "--modes 20 --static-correction skirt --pressure-pattern crown --out " + file);
}

}  // namespace flexehd::test
