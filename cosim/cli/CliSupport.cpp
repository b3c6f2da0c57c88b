#include "cosim/cli/CliSupport.hpp"

#include <sys/resource.h>

#include <cmath>
#include <iostream>
#include <string>

namespace flexehd::cli {

const CLI::Validator kFinite(
    [](std::string& text) -> std::string {
        try {
            std::size_t used = 0;
            const double v = std::stod(text, &used);
            if (used == text.size() && std::isfinite(v)) return {};
        } catch (const std::exception&) {
        }
        return "'" + text + "' is not a finite number";
    },
    "FINITE");

void addMeshOptions(CLI::App* cmd, MeshArguments& mesh) {
    cmd->add_option("--mesh", mesh.path, "Mesh file: .msh (Gmsh 2.2 or 4.1) or .geo (meshed on load)")->required();
    cmd->add_option("--order", mesh.options.order, "Element order 1 or 2 (default: .geo → 2, .msh → as stored)")
        ->check(CLI::IsMember({1, 2}));
    cmd->add_option("--size", mesh.options.size, "Target element size for .geo files [m]")
        ->check(kFinite & CLI::PositiveNumber);
}

void addMaterialOptions(CLI::App* cmd, fem::ElasticMaterial& material) {
    cmd->add_option("--E", material.E, "Young's modulus [Pa]")->required()->check(kFinite & CLI::PositiveNumber);
    cmd->add_option("--nu", material.nu, "Poisson's ratio [-]")->required()->check(kFinite & CLI::Range(-0.999, 0.499));
    cmd->add_option("--rho", material.rho, "Density [kg/m^3]")->required()->check(kFinite & CLI::PositiveNumber);
}

namespace {
bool quietFlag = false;
}  // namespace

void setGlobalQuiet(bool quiet) { quietFlag = quiet; }
bool globalQuiet() { return quietFlag; }

double peakMemoryMiB() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss / 1024.0;  // Linux reports KiB
}

void printJson(const nlohmann::json& doc) { std::cout << doc.dump(2) << std::endl; }

}  // namespace flexehd::cli
