#include "cosim/cli/CliSupport.hpp"

#include <iostream>

namespace flexehd::cli {

void printJson(const nlohmann::json& doc) { std::cout << doc.dump(2) << std::endl; }

}  // namespace flexehd::cli
