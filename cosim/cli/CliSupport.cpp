#include "cosim/cli/CliSupport.hpp"
#include "cosim/io/JsonText.hpp"

#include <signal.h>
#include <sys/prctl.h>
#include <linux/magic.h>
#include <sys/resource.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <cstdlib>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <iostream>
#include <string>

#include <fmt/format.h>

namespace flexehd::cli {

namespace {

// A validator from a predicate on the parsed value and the words for what it expects.
template <class Accept>
CLI::Validator numberCheck(const std::string& expected, bool whole, Accept accept) {
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            std::size_t used = 0;
            double v = 0.0;
            try {
                v = std::stod(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            const bool number = used == text.size() && !text.empty() && std::isfinite(v);
            if (number && (!whole || v == std::floor(v)) && accept(v)) return {};
            return "expected " + expected + ", got '" + text + "'";
        },
        whole ? "INT" : "NUMBER");
}

// As people write numbers: 0.499, 100, 1e5, 1e-3 (no "e+05").
std::string plain(double v) {
    if (v != 0.0 && (std::abs(v) >= 1e5 || std::abs(v) < 1e-3)) {
        const int e = int(std::floor(std::log10(std::abs(v))));
        const double m = v / std::pow(10.0, e);
        return fmt::format("{:g}e{}", m, e);
    }
    return fmt::format("{:g}", v);
}

}  // namespace

CLI::Validator positiveNumber() {
    return numberCheck("a number > 0", false, [](double v) { return v > 0.0; });
}
CLI::Validator nonNegativeNumber() {
    return numberCheck("a number ≥ 0", false, [](double v) { return v >= 0.0; });
}
CLI::Validator numberFromTo(double lo, double hi) {
    return numberCheck("a number from " + plain(lo) + " to " + plain(hi), false,
                       [=](double v) { return v >= lo && v <= hi; });
}
CLI::Validator wholeNumberFromTo(long lo, long hi) {
    return numberCheck("a whole number from " + std::to_string(lo) + " to " + std::to_string(hi), true,
                       [=](double v) { return v >= double(lo) && v <= double(hi); });
}
CLI::Validator positiveWholeNumber() {
    return numberCheck("a whole number ≥ 1", true, [](double v) { return v >= 1.0 && v <= 2147483647.0; });
}

namespace {

std::string commandNames(const CLI::App& app) {
    std::string names;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        names += (names.empty() ? "" : ", ") + sub->get_name();
    return names;
}

// An option of `cmd` (or of its parsed subcommands) that takes one value but was given more.
const CLI::Option* repeatedOption(const CLI::App& cmd) {
    for (const CLI::Option* o : cmd.get_options())
        if (o->get_items_expected_max() == 1 && o->count() > 1) return o;
    for (const CLI::App* sub : cmd.get_subcommands())
        if (const CLI::Option* o = repeatedOption(*sub)) return o;
    return nullptr;
}

std::string optionName(const CLI::Option& o) {
    if (!o.get_lnames().empty()) return "--" + o.get_lnames().front();
    if (!o.get_snames().empty()) return "-" + o.get_snames().front();
    return o.get_name();
}

}  // namespace

std::string commandLineError(const CLI::App& app, const CLI::ParseError& e, const std::vector<std::string>& args) {
    const std::string help = " (flexehd --help, flexehd COMMAND --help: the commands and their options)";
    if (app.get_subcommands().empty()) {
        // No command was recognised: the first word that is not an option is the command's place.
        for (const std::string& a : args)
            if (!a.empty() && a[0] != '-')
                return fmt::format("unknown command '{}'; commands are: {}{}", a, commandNames(app), help);
        if (dynamic_cast<const CLI::RequiredError*>(&e))
            return fmt::format("no command given; commands are: {}{}", commandNames(app), help);
    }
    if (const CLI::Option* o = repeatedOption(app))
        return fmt::format("option {} given {}; give it once{}", optionName(*o),
                           o->count() == 2 ? std::string("twice") : std::to_string(o->count()) + " times", help);
    return std::string(e.what()) + help;
}

namespace {

// Makes the folder `target` (absolute) and its parents: "" when it exists or was made, else why
// not in words.
std::string folderProblem(const std::filesystem::path& target) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(target, ec)) return {};
    // The nearest part of the path that exists says why it cannot be made.
    fs::path existing = target;
    while (!existing.empty() && existing != existing.root_path() && !fs::exists(existing, ec))
        existing = existing.parent_path();
    std::string reason;
    struct statfs fsInfo {};
    if (existing == target) {
        reason = "it exists and is not a folder";
    } else if (fs::exists(existing, ec) && !fs::is_directory(existing, ec)) {
        reason = fmt::format("a parent is a file ({})", existing.string());
    } else if (::statfs(existing.c_str(), &fsInfo) == 0 &&
               (fsInfo.f_type == PROC_SUPER_MAGIC || fsInfo.f_type == SYSFS_MAGIC)) {
        reason = fmt::format("{} is a kernel file system that holds no folders of files", existing.string());
    } else {
        fs::create_directories(target, ec);
        if (!ec) return {};
        if (ec == std::errc::read_only_file_system) reason = "read-only file system";
        else if (ec == std::errc::permission_denied || ec == std::errc::operation_not_permitted)
            reason = fmt::format("permission denied (in {})", existing.string());
        else if (ec == std::errc::no_space_on_device) reason = "no space left on the device";
        else reason = ec.message();
    }
    return reason;
}

}  // namespace

void createOutputFolder(const std::string& dir) {
    std::error_code ec;
    const std::filesystem::path target = std::filesystem::absolute(std::filesystem::path(dir), ec).lexically_normal();
    if (const std::string reason = folderProblem(target); !reason.empty())
        throw std::runtime_error(fmt::format("cannot create the output folder {}: {}", target.string(), reason));
}

void prepareOutputFile(const std::string& file) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path target = fs::absolute(fs::path(file), ec).lexically_normal();
    std::string reason;
    const fs::path parent = target.parent_path();
    if (target.filename().empty() || fs::is_directory(target, ec))
        reason = "it is a folder, not a file";
    else if (fs::exists(parent, ec) && !fs::is_directory(parent, ec))
        reason = fmt::format("a parent is a file ({})", parent.string());
    else
        reason = folderProblem(parent);
    if (!reason.empty())
        throw std::runtime_error(fmt::format("cannot write the output file {}: {}", target.string(), reason));
}

void addMeshOptions(CLI::App* cmd, MeshArguments& mesh) {
    cmd->add_option("--mesh", mesh.path, "Mesh file: .msh (Gmsh 2.2 or 4.1) or .geo (meshed on load)")->required();
    cmd->add_option("--order", mesh.options.order, "Element order 1 or 2 (default: .geo → 2, .msh → as stored)")
        ->check(CLI::IsMember({1, 2}));
    cmd->add_option("--size", mesh.options.size, "Target element size for .geo files [m]")
        ->check(positiveNumber());
}

void addMaterialOptions(CLI::App* cmd, fem::ElasticMaterial& material) {
    // Physical ranges: from soft foams (0.1 MPa, 10 kg/m³) to diamond (1.2e12 Pa) and the
    // densest metals (22 600 kg/m³); outside them the eigensolvers work with meaningless numbers.
    cmd->add_option("--E", material.E, "Young's modulus [Pa], 1e5 to 1e13")->required()->check(numberFromTo(1e5, 1e13));
    cmd->add_option("--nu", material.nu, "Poisson's ratio [-]")->required()->check(numberFromTo(-0.999, 0.499));
    cmd->add_option("--rho", material.rho, "Density [kg/m^3], 10 to 1e5")->required()->check(numberFromTo(10.0, 1e5));
}

namespace {
bool quietFlag = false;
}  // namespace

void setGlobalQuiet(bool quiet) { quietFlag = quiet; }
bool globalQuiet() { return quietFlag; }

namespace {
int exitCodeValue = 0;
}
void setExitCode(int code) { exitCodeValue = code; }
int exitCode() { return exitCodeValue; }

void followParentProcess() {
    const char* parent = std::getenv("FLEXEHD_PARENT_PID");
    if (!parent) return;
    const long pid = std::strtol(parent, nullptr, 10);
    if (pid <= 1) return;
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != pid) std::_Exit(143);  // the parent died before the request: as SIGTERM would
}

void printJson(const nlohmann::json& doc) { std::cout << cosim::jsonText(doc, 2) << std::endl; }

}  // namespace flexehd::cli
