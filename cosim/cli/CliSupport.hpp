#pragma once
// Small pieces shared by the subcommands: timing and the JSON / table output conventions.
#include <chrono>
#include <string>

#include <nlohmann/json.hpp>

namespace flexehd::cli {

/// Wall-clock stopwatch for the timings every subcommand reports.
class Stopwatch {
public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
private:
    std::chrono::steady_clock::time_point start_;
};

/// Peak resident memory of this process so far, MiB (getrusage).
double peakMemoryMiB();

/// Prints a JSON document on stdout (the `--json` convention: nothing else goes there).
void printJson(const nlohmann::json& doc);

}  // namespace flexehd::cli
