#include "cosim/cli/CliSupport.hpp"

#include <sys/resource.h>

#include <iostream>

namespace flexehd::cli {

double peakMemoryMiB() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss / 1024.0;  // Linux reports KiB
}

void printJson(const nlohmann::json& doc) { std::cout << doc.dump(2) << std::endl; }

}  // namespace flexehd::cli
