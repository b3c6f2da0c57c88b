#include "cosim/thermal/ThermalCaseFile.hpp"
#include "cosim/io/YamlDocument.hpp"
#include "cosim/io/YamlKeys.hpp"
#include "cosim/io/YamlSection.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <set>
#include <stdexcept>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

namespace flexehd::cosim {
namespace {

namespace fs = std::filesystem;
const auto& joined = joinedKeys;
const auto& describe = describeNode;

double toNumber(const YamlSource& ctx, const std::string& key, const YAML::Node& n, const std::string& what) {
    if (!n.IsScalar()) ctx.fail(key, n, "expected " + what + ", got " + describe(n));
    std::string t = n.Scalar();
    if (!t.empty() && t[0] == '+') t.erase(0, 1);
    double v = 0.0;
    const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty() || ec != std::errc() || p != t.data() + t.size() || !std::isfinite(v))
        ctx.fail(key, n, "expected " + what + ", got " + describe(n));
    return v;
}

/// A number in [lo, hi] (open at an end when the flag says so), described for messages.
struct Range {
    double lo, hi;
    bool loOpen = false, hiOpen = false;
    std::string text;  ///< "a positive temperature in K"
};

double number(const YamlSection& s, const std::string& k, const Range& r, std::optional<double> def) {
    if (!s.hasValue(k)) {
        if (!def) s.missing(k, r.text);
        return *def;
    }
    const double v = toNumber(s.source(), s.keyPath(k), s.get(k), r.text);
    if ((r.loOpen ? v <= r.lo : v < r.lo) || (r.hiOpen ? v >= r.hi : v > r.hi))
        s.source().fail(s.keyPath(k), s.get(k), fmt::format("expected {}, got {}", r.text, s.get(k).Scalar()));
    return v;
}

const Range kTemperature{0.0, 1e4, true, false, "a temperature in K, 0 < T <= 10000"};
const Range kLength{-10.0, 10.0, false, false, "a coordinate in m"};

std::string text(const YamlSection& s, const std::string& k, std::optional<std::string> def) {
    if (!s.hasValue(k)) {
        if (!def) s.missing(k, "a name");
        return *def;
    }
    const YAML::Node n = s.get(k);
    if (!n.IsScalar() || n.Scalar().empty()) s.source().fail(s.keyPath(k), n, "expected a name, got " + describe(n));
    return n.Scalar();
}

std::vector<std::string> names(const YamlSection& s, const std::string& k, std::vector<std::string> def) {
    if (!s.hasValue(k)) return def;
    const YAML::Node n = s.get(k);
    std::vector<std::string> out;
    if (n.IsScalar()) return {n.Scalar()};
    if (!n.IsSequence()) s.source().fail(s.keyPath(k), n, "expected a group name or a list of names, got " + describe(n));
    for (std::size_t i = 0; i < n.size(); ++i) {
        if (!n[i].IsScalar()) s.source().fail(fmt::format("{}[{}]", s.keyPath(k), i), n[i], "expected a group name");
        out.push_back(n[i].Scalar());
    }
    return out;
}

std::vector<double> numbers(const YamlSource& ctx, const std::string& key, const YAML::Node& n, const std::string& what) {
    if (!n.IsSequence()) ctx.fail(key, n, "expected a list of " + what + ", got " + describe(n));
    std::vector<double> out;
    for (std::size_t i = 0; i < n.size(); ++i) out.push_back(toNumber(ctx, fmt::format("{}[{}]", key, i), n[i], what));
    return out;
}

std::string existingFile(const YamlSection& s, const std::string& k) {
    const std::string p = text(s, k, std::nullopt);
    fs::path path(p);
    if (path.is_relative()) path = s.source().dir / path;
    path = path.lexically_normal();
    if (!fs::is_regular_file(path)) s.source().fail(s.keyPath(k), s.get(k), "file not found: " + path.string());
    return path.string();
}

ThermalBodyMesh bodyMesh(const YamlSection& s) {
    ThermalBodyMesh m;
    m.path = existingFile(s, "mesh");
    m.size = number(s, "mesh_size", {0.0, 1.0, true, false, "a positive length in m"}, 0.0);
    const double order = number(s, "element_order", {1, 2, false, false, "1 or 2"}, 0.0);
    if (s.hasValue("element_order") && order != 1.0 && order != 2.0)
        s.source().fail(s.keyPath("element_order"), s.get("element_order"), "expected 1 or 2");
    m.order = int(order);
    return m;
}

fem::ElasticMaterial elastic(const YamlSection& m) {
    fem::ElasticMaterial e;
    e.E = number(m, "youngs_modulus", {0.0, 1e13, true, false, "a positive Young's modulus in Pa"}, std::nullopt);
    e.nu = number(m, "poisson_ratio", {-1.0, 0.5, true, true, "a Poisson's ratio in (-1, 0.5)"}, std::nullopt);
    e.rho = 1.0;  // statics: unused
    return e;
}

const Range kExpansion{0.0, 1e-3, false, false, "a thermal expansion coefficient in 1/K, 0 <= alpha <= 1e-3"};

PistonThermalCase piston(const YamlSource& ctx, const YAML::Node& node) {
    const YamlSection s(ctx, node, "piston",
                        {"mesh", "mesh_size", "element_order", "material", "convection", "support", "surface",
                         "ring_belt", "calibration"});
    PistonThermalCase p;
    p.mesh = bodyMesh(s);
    const YamlSection mat(ctx, s.get("material"), "piston.material",
                      {"youngs_modulus", "poisson_ratio", "conductivity", "expansion"});
    if (!s.hasValue("material")) s.missing("material", "a mapping with youngs_modulus, poisson_ratio, conductivity, expansion");
    p.material = elastic(mat);
    p.conductivity = number(mat, "conductivity", {0.0, 1e4, true, false, "a positive conductivity in W/(m K)"}, std::nullopt);
    p.expansion = number(mat, "expansion", kExpansion, std::nullopt);

    if (!s.hasValue("convection")) s.missing("convection", "a mapping GROUP: {h: W/(m^2 K), fluid_temperature: K}");
    const YAML::Node conv = s.get("convection");
    if (!conv.IsMap()) ctx.fail("piston.convection", conv, "expected a mapping GROUP: {h, fluid_temperature}, got " + describe(conv));
    for (const auto& kv : conv) {
        const std::string group = kv.first.Scalar();
        const YamlSection c(ctx, kv.second, "piston.convection." + group, {"h", "fluid_temperature"});
        if (!kv.second.IsMap())
            ctx.fail("piston.convection." + group, kv.second, "expected a mapping with h and fluid_temperature");
        p.convection.push_back(
            {group, number(c, "h", {0.0, 1e7, false, false, "a heat-transfer coefficient in W/(m^2 K), >= 0"}, std::nullopt),
             number(c, "fluid_temperature", kTemperature, std::nullopt)});
    }
    if (p.convection.empty()) ctx.fail("piston.convection", conv, "at least one convection boundary is needed");
    p.support = text(s, "support", std::string("pin_bore"));
    p.surface = names(s, "surface", p.surface);
    p.ringBeltGiven = s.has("ring_belt");
    if (p.ringBeltGiven && !s.hasValue("ring_belt")) p.ringBelt.clear();  // `ring_belt:` or `[]`: no profile
    else p.ringBelt = names(s, "ring_belt", p.ringBelt);

    if (s.hasValue("calibration")) {
        const YamlSection cal(ctx, s.get("calibration"), "piston.calibration",
                          {"fit_h", "fit_fluid_temperature", "tolerance", "templugs"});
        auto inConvection = [&](const std::string& key, const std::string& g) {
            if (std::none_of(p.convection.begin(), p.convection.end(), [&](const auto& c) { return c.group == g; })) {
                std::vector<std::string> all;
                for (const auto& c : p.convection) all.push_back(c.group);
                ctx.fail(cal.keyPath(key), cal.get(key),
                         fmt::format("'{}' has no convection boundary; groups in piston.convection: {}", g, joined(all)));
            }
        };
        for (const auto& g : names(cal, "fit_h", {})) {
            inConvection("fit_h", g);
            p.parameters.push_back({g, fem::CalibrationParameter::Kind::HeatTransferScale});
        }
        for (const auto& g : names(cal, "fit_fluid_temperature", {})) {
            inConvection("fit_fluid_temperature", g);
            p.parameters.push_back({g, fem::CalibrationParameter::Kind::FluidTemperature});
        }
        if (p.parameters.empty())
            ctx.fail("piston.calibration", cal.node(), "nothing to fit: give fit_h and/or fit_fluid_temperature");
        p.tolerance = number(cal, "tolerance", {0.0, 1e3, true, false, "a positive temperature difference in K"}, 5.0);
        if (!cal.hasValue("templugs")) cal.missing("templugs", "a list of {name, position: [x, y, z] m, temperature: K}");
        const YAML::Node tp = cal.get("templugs");
        if (!tp.IsSequence() || tp.size() == 0)
            ctx.fail("piston.calibration.templugs", tp, "expected a non-empty list of templugs, got " + describe(tp));
        std::set<std::string> seen;
        for (std::size_t i = 0; i < tp.size(); ++i) {
            const std::string key = fmt::format("piston.calibration.templugs[{}]", i);
            const YamlSection t(ctx, tp[i], key, {"name", "position", "temperature"});
            if (!tp[i].IsMap()) ctx.fail(key, tp[i], "expected a mapping with name, position, temperature");
            fem::TemperatureMeasurement m;
            m.name = text(t, "name", std::nullopt);
            if (!seen.insert(m.name).second) ctx.fail(t.keyPath("name"), t.get("name"), "templug name '" + m.name + "' used twice");
            if (!t.hasValue("position")) t.missing("position", "[x, y, z] in m");
            const auto x = numbers(ctx, t.keyPath("position"), t.get("position"), "coordinates in m");
            if (x.size() != 3) ctx.fail(t.keyPath("position"), t.get("position"), "expected [x, y, z] in m (3 numbers)");
            m.position = {x[0], x[1], x[2]};
            m.temperature = number(t, "temperature", kTemperature, std::nullopt);
            p.templugs.push_back(m);
        }
    }
    return p;
}

LinerThermalCase liner(const YamlSource& ctx, const YAML::Node& node) {
    const YamlSection s(ctx, node, "liner",
                    {"mesh", "mesh_size", "element_order", "material", "support", "surface", "thermocouples"});
    LinerThermalCase l;
    l.mesh = bodyMesh(s);
    if (!s.hasValue("material")) s.missing("material", "a mapping with youngs_modulus, poisson_ratio, expansion");
    const YamlSection mat(ctx, s.get("material"), "liner.material", {"youngs_modulus", "poisson_ratio", "expansion"});
    l.material = elastic(mat);
    l.expansion = number(mat, "expansion", kExpansion, std::nullopt);
    if (s.hasValue("support")) {
        const YamlSection sup(ctx, s.get("support"), "liner.support", {"held", "reference"});
        l.held.clear();
        for (const auto& h : names(sup, "held", {"top_seat:z"})) {
            try {
                l.held.push_back(fem::parseFixedGroup(h));
            } catch (const std::exception& e) {
                ctx.fail(sup.keyPath("held"), sup.get("held"), e.what());
            }
        }
        l.reference = text(sup, "reference", std::string("top_seat"));
    }
    l.surface = names(s, "surface", l.surface);

    if (!s.hasValue("thermocouples")) s.missing("thermocouples", "a mapping with radii and stations");
    const YamlSection tc(ctx, s.get("thermocouples"), "liner.thermocouples", {"radii", "stations"});
    if (!tc.hasValue("radii")) tc.missing("radii", "a list of 1 or 2 radii in m");
    l.radii = numbers(ctx, tc.keyPath("radii"), tc.get("radii"), "radii in m");
    if (l.radii.empty() || l.radii.size() > 2 || l.radii.front() <= 0.0 ||
        (l.radii.size() == 2 && !(l.radii[1] > l.radii[0])))
        ctx.fail(tc.keyPath("radii"), tc.get("radii"), "expected 1 or 2 positive, increasing radii in m");
    if (!tc.hasValue("stations")) tc.missing("stations", "a list of [z m, temperature K per radius]");
    const YAML::Node st = tc.get("stations");
    if (!st.IsSequence() || st.size() == 0)
        ctx.fail(tc.keyPath("stations"), st, "expected a non-empty list of [z, T...], got " + describe(st));
    for (std::size_t i = 0; i < st.size(); ++i) {
        const std::string key = fmt::format("{}[{}]", tc.keyPath("stations"), i);
        const auto v = numbers(ctx, key, st[i], "numbers ([z m, T K ...])");
        if (v.size() != 1 + l.radii.size())
            ctx.fail(key, st[i], fmt::format("expected [z, {} temperature(s) in K] (one per radius)", l.radii.size()));
        ThermocoupleStation station{v[0], {v.begin() + 1, v.end()}};
        for (double T : station.temperatures)
            if (!(T > 0.0 && T <= 1e4)) ctx.fail(key, st[i], fmt::format("temperature {} K out of range (0, 10000]", T));
        for (const auto& other : l.stations)
            if (other.z == station.z) ctx.fail(key, st[i], fmt::format("a second station at z = {} m", station.z));
        l.stations.push_back(std::move(station));
    }
    std::sort(l.stations.begin(), l.stations.end(), [](const auto& a, const auto& b) { return a.z < b.z; });
    return l;
}

}  // namespace

ThermalCase readThermalCaseFile(const std::string& path) {
    YamlSource ctx{path, fs::absolute(fs::path(path)).parent_path()};
    if (!fs::is_regular_file(path)) throw std::runtime_error(path + ": thermal case file not found");
    const YAML::Node root = loadYamlDocument(path, "the thermal case file");
    const YamlSection top(ctx, root, "", {"name", "reference_temperature", "grid", "output", "piston", "liner"});
    ThermalCase c;
    c.file = path;
    c.name = top.hasValue("name") ? text(top, "name", std::nullopt) : fs::path(path).stem().string();
    c.referenceTemperature = number(top, "reference_temperature", kTemperature, 293.15);
    const YamlSection grid(ctx, top.get("grid"), "grid", {"axial_nodes", "circumferential_nodes"});
    c.axialNodes = int(number(grid, "axial_nodes", {2, 100000, false, false, "an integer >= 2"}, 64.0));
    c.circumferentialNodes = int(number(grid, "circumferential_nodes", {4, 100000, false, false, "an integer >= 4"}, 96.0));
    for (const char* k : {"axial_nodes", "circumferential_nodes"})
        if (grid.hasValue(k) && std::floor(toNumber(ctx, grid.keyPath(k), grid.get(k), "an integer")) !=
                               toNumber(ctx, grid.keyPath(k), grid.get(k), "an integer"))
            ctx.fail(grid.keyPath(k), grid.get(k), "expected an integer");
    const YamlSection out(ctx, top.get("output"), "output", {"directory"});
    if (out.hasValue("directory")) {
        fs::path d(text(out, "directory", std::nullopt));
        if (d.is_relative()) d = ctx.dir / d;
        c.outputDirectory = d.lexically_normal().string();
    }
    if (top.hasValue("piston")) c.piston = piston(ctx, top.get("piston"));
    if (top.hasValue("liner")) c.liner = liner(ctx, top.get("liner"));
    if (!c.piston && !c.liner) ctx.fail("", root, "neither 'piston' nor 'liner' given: nothing to compute");
    return c;
}

}  // namespace flexehd::cosim
