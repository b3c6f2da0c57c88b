// bodies: rigid or flexible piston and liner, their reduced-body files and the response
// (docs/case-file.md, "bodies").
#include "cosim/casefile/CaseSections.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "cosim/io/YamlKeys.hpp"

namespace flexehd::cosim::casefile {

namespace {

namespace fs = std::filesystem;

// bodies.piston.loads: a list of gas_pressure, inertia and ring_pack (docs/case-file.md, "bodies").
PistonLoadSpec readLoads(const YamlSection& s, bool piston) {
    PistonLoadSpec l;
    if (!s.has("loads") && !s.has("gas_surface")) return l;
    if (!piston)
        s.fail(s.has("loads") ? "loads" : "gas_surface",
               "loads act on the piston only (the cylinder's gas pressure on its crown, its inertia); the liner takes "
               "its films' loads");
    if (s.has("loads")) {
        const YAML::Node n = s.get("loads");
        const YamlSource& ctx = s.source();
        const std::string expected = "a list of gas_pressure, inertia, ring_pack";
        if (!n.IsSequence()) s.fail("loads", "expected " + expected + ", got " + describeNode(n));
        for (std::size_t i = 0; i < n.size(); ++i) {
            const std::string path = fmt::format("{}[{}]", s.keyPath("loads"), i);
            const std::string v = n[i].IsScalar() ? std::string(trim(n[i].Scalar())) : std::string();
            bool& on = v == "gas_pressure" ? l.gasPressure : v == "ring_pack" ? l.ringPack : l.inertia;
            if (v != "gas_pressure" && v != "inertia" && v != "ring_pack")
                ctx.fail(path, n[i], "expected gas_pressure, inertia or ring_pack, got " +
                                         (v.empty() ? describeNode(n[i]) : "'" + v + "'"));
            if (on) ctx.fail(path, n[i], "'" + v + "' listed twice");
            on = true;
        }
    }
    l.gasSurface = text(s, "gas_surface", l.gasSurface, "the name of a physical surface");
    if (s.has("gas_surface") && !l.gasPressure)
        s.fail("gas_surface", "gas_surface is the surface of the gas_pressure load, which bodies.piston.loads does not list");
    return l;
}

BodySpec readBody(const YamlSection& bodies, const std::string& key, const std::string& defSurface,
                  const std::vector<std::string>& defInterfaces, const CaseFileOptions& options) {
    BodySpec b;
    if (!bodies.has(key)) return b;  // rigid
    const YAML::Node n = bodies.get(key);
    const std::string path = bodies.keyPath(key);
    const YamlSource& ctx = bodies.source();
    if (n.IsScalar()) {
        const std::string v(trim(n.Scalar()));
        if (v == "rigid") return b;
        ctx.fail(path, n,
             fmt::format("expected 'rigid' or a mapping {{file: ..., surface: ..., interface: ...}} for a flexible "
                         "body, got '{}'",
                         v));
    }
    if (!n.IsMap())
        ctx.fail(path, n,
             "expected 'rigid' or a mapping {file: ..., surface: ..., interface: ...}, got " + describeNode(n));
    const YamlSection s(ctx, n, path, {"file", "surface", "interface", "loads", "gas_surface"});
    b.model = BodyModel::Flexible;
    const std::string file = text(s, "file", "", "the reduced-body file (HDF5, from `flexehd reduce`)", true);
    const fs::path resolved = ctx.resolve(file);
    b.file = resolved.string();
    if (options.checkBodyFiles) {
        std::error_code ec;
        if (!fs::exists(resolved, ec))
            s.fail("file", fmt::format("reduced-body file {} does not exist (make it with `flexehd reduce`)", b.file));
        if (fs::is_directory(resolved, ec))
            s.fail("file", fmt::format("{} is a directory, not a reduced-body file", b.file));
        if (!std::ifstream(resolved, std::ios::binary))
            s.fail("file", fmt::format("reduced-body file {} cannot be opened for reading", b.file));
        if (!looksLikeHdf5(resolved))
            s.fail("file",
                   fmt::format("{} is not an HDF5 file (expected a reduced body from `flexehd reduce`)", b.file));
    }
    b.surface = text(s, "surface", defSurface, "the name of a physical surface");
    b.interfaces = defInterfaces;
    if (s.has("interface")) {
        const YAML::Node itf = s.get("interface");
        const std::string expected = "an interface name or a list of them";
        b.interfaces.clear();
        if (itf.IsScalar() && !trim(itf.Scalar()).empty()) {
            b.interfaces.emplace_back(trim(itf.Scalar()));
        } else if (itf.IsSequence() && itf.size() > 0) {
            for (std::size_t i = 0; i < itf.size(); ++i) {
                if (!itf[i].IsScalar() || trim(itf[i].Scalar()).empty())
                    ctx.fail(fmt::format("{}[{}]", s.keyPath("interface"), i), itf[i],
                         "expected an interface name, got " + describeNode(itf[i]));
                const std::string name(trim(itf[i].Scalar()));
                if (std::find(b.interfaces.begin(), b.interfaces.end(), name) != b.interfaces.end())
                    ctx.fail(fmt::format("{}[{}]", s.keyPath("interface"), i), itf[i], "interface listed twice");
                b.interfaces.push_back(name);
            }
        } else {
            s.fail("interface", "expected " + expected + ", got " + describeNode(itf));
        }
    }
    b.interface = b.interfaces.empty() ? std::string() : b.interfaces.front();
    b.loads = readLoads(s, key == "piston");
    return b;
}

}  // namespace

void readBodies(const YamlSection& top, const CaseFileOptions& options, EngineCase& c) {
    const YamlSection bodies(top.source(), top.get("bodies"), "bodies", {"piston", "liner", "response"});
    c.pistonBody = readBody(bodies, "piston", "skirt", {"pin_bore"}, options);
    c.linerBody = readBody(bodies, "liner", "bore", {"top_seat", "bottom_seat"}, options);
    if (options.rigidBodies) c.pistonBody.model = c.linerBody.model = BodyModel::Rigid;
    c.coupling.response = choice(bodies, "response", {"quasi_static", "dynamic"}, 0) == 0 ? ElasticResponse::QuasiStatic
                                                                                          : ElasticResponse::Dynamic;
}

}  // namespace flexehd::cosim::casefile
