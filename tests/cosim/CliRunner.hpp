#pragma once
// Runs the `flexehd` executable as a user would and captures what it prints, for the
// command-line tests (FLEXEHD_BINARY is set by tests/cosim/CMakeLists.txt).
#include <unistd.h>
#include <sys/wait.h>

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

/// Runs `flexehd ARGS` through the shell (arguments must be shell-safe).
inline CommandResult runFlexehd(const std::string& args) {
    const auto dir = std::filesystem::temp_directory_path();
    const std::string errFile = (dir / ("flexehd_cli_err_" + std::to_string(::getpid()))).string();
    const std::string cmd = std::string(FLEXEHD_BINARY) + " " + args + " 2>" + errFile;
    CommandResult r;
    FILE* p = popen(cmd.c_str(), "r");
    std::array<char, 4096> buf;
    while (std::size_t n = fread(buf.data(), 1, buf.size(), p)) r.out.append(buf.data(), n);
    r.status = WEXITSTATUS(pclose(p));
    std::ifstream e(errFile);
    r.err.assign(std::istreambuf_iterator<char>(e), {});
    std::filesystem::remove(errFile);
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

/// The example engine's piston as scripts/example.sh reduces it (20 modes + skirt correction).
inline CommandResult reduceExamplePiston(const std::string& file) {
    return runFlexehd("reduce --mesh " + std::string(FLEXEHD_SOURCE_DIR) +
                      "/meshes/piston.geo --size 0.0065 --E 7.5e10 --nu 0.33 --rho 2700 --interface pin_bore:rbe2@0,0,0 "
                      "--modes 20 --static-correction skirt --out " + file);
}

}  // namespace flexehd::test
