#pragma once
// Shared by the test programs: a fresh scratch directory per test and the message of an
// exception.
#include <gtest/gtest.h>

#include <exception>
#include <filesystem>
#include <string>

namespace flexehd::test {

/// A fresh directory under the system temp dir, named after the running test.
inline std::filesystem::path scratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    auto dir = std::filesystem::temp_directory_path() /
               ("flexehd_" + std::string(info->test_suite_name()) + "_" + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

/// Runs `f` and returns the message of the std::exception it throws ("" if none).
template <typename F>
std::string errorOf(F&& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

}  // namespace flexehd::test
