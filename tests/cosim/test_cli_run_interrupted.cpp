// `flexehd run` ended by SIGTERM or SIGINT (docs/results-format.md, summary.json `status`): the run
// stops before its next step, writes summary.json with `status: interrupted`, the signal and the
// cycles it completed, keeps every accepted step in history.csv (each row whole), and exits with
// 128 + the signal, as a shell reports a process ended by it.
#include "CliRunner.hpp"
#include "../TestScratch.hpp"
#include "TestFiles.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using namespace flexehd;

namespace {

// hd.yaml on the coarse grid, 100 cycles at most and never periodic: it runs until the signal
// stops it.
std::string longCase(const fs::path& dir) {
    return test::coarseHdCase(dir, dir / "out",
                              {{"max_cycles: 5", "max_cycles: 100"},
                               {"periodicity_tolerance: 1.0e-6", "periodicity_tolerance: 1.0e-15"}});  // never periodic
}

// The exit status of `flexehd run --quiet CASE` sent `signal` after `seconds` (coreutils timeout
// with --preserve-status: the command's own status).
int runSignalled(const std::string& casePath, const char* signal, int seconds, std::string& err) {
    const fs::path errFile = fs::path(casePath).parent_path() / "stderr.txt";
    const std::string cmd = "timeout --preserve-status --kill-after=20s -s " + std::string(signal) + " " +
                            std::to_string(seconds) + " " + FLEXEHD_BINARY + " run --quiet " + casePath + " 2>" +
                            errFile.string();
    const int status = std::system(cmd.c_str());
    std::ifstream e(errFile);
    err.assign(std::istreambuf_iterator<char>(e), {});
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST(CliRunInterrupted, SigtermAndSigintEndTheRunWithItsSummary) {
    for (const auto& [name, number] : {std::pair{"TERM", SIGTERM}, std::pair{"INT", SIGINT}}) {
        const fs::path dir = test::scratchDir() / name;
        fs::create_directories(dir);
        std::string err;
        const int status = runSignalled(longCase(dir), name, 3, err);
        EXPECT_EQ(status, 128 + number) << name << ": " << err;
        EXPECT_THAT(err, ::testing::HasSubstr("interrupted by signal " + std::to_string(number))) << name;
        std::ifstream s(dir / "out" / "summary.json");
        ASSERT_TRUE(s.good()) << name;
        const nlohmann::json d = nlohmann::json::parse(s);
        EXPECT_EQ(d.at("status").get<std::string>(), "interrupted") << name;
        EXPECT_THAT(d.at("message").get<std::string>(), ::testing::HasSubstr(std::string("SIG") + name)) << name;
        EXPECT_LT(d.at("cycles").get<int>(), 100) << name;
        // history.csv: a header, and every data row whole (as many fields as the header).
        std::ifstream h(dir / "out" / "history.csv");
        std::string line;
        std::getline(h, line);
        const auto fields = std::count(line.begin(), line.end(), ',') + 1;
        int rows = 0;
        while (std::getline(h, line)) {
            if (line.empty() || line[0] == '#') continue;
            EXPECT_EQ(std::count(line.begin(), line.end(), ',') + 1, fields) << name << " row " << rows;
            ++rows;
        }
        EXPECT_GT(rows, 10) << name;
    }
}
