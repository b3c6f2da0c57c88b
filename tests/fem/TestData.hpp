#pragma once
// Paths of the test geometry in tests/fem/data (and, from TestScratch.hpp, a scratch directory per test).
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../TestScratch.hpp"

namespace flexehd::test {

inline std::string dataPath(const std::string& name) {
    return std::string(FLEXEHD_SOURCE_DIR) + "/tests/fem/data/" + name;
}

inline std::string meshPath(const std::string& name) { return std::string(FLEXEHD_SOURCE_DIR) + "/meshes/" + name; }

}  // namespace flexehd::test
