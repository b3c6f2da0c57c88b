#pragma once
// Small helpers of the co-simulation tests: writing a text file, plus TestScratch.hpp's scratch
// directory and exception message.
#include "../TestScratch.hpp"

#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

namespace flexehd::test {

inline void writeFile(const std::filesystem::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary);
    out << text;
}

}  // namespace flexehd::test
