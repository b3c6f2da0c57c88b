#pragma once
// Paths of the test geometry in tests/fem/data and a scratch directory per test.
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace flexehd::test {

inline std::string dataPath(const std::string& name) {
    return std::string(FLEXEHD_SOURCE_DIR) + "/tests/fem/data/" + name;
}

inline std::string meshPath(const std::string& name) { return std::string(FLEXEHD_SOURCE_DIR) + "/meshes/" + name; }

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
