#include "cosim/study/StudyFile.hpp"
#include "cosim/contact/OilControlRingBand.hpp"
#include "cosim/results/RunSummary.hpp"
#include "cosim/ringpack/RingContact.hpp"
#include "cosim/io/YamlDocument.hpp"
#include "cosim/io/YamlKeys.hpp"
#include "cosim/io/YamlSection.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <set>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "cosim/study/VariantCase.hpp"

namespace flexehd::cosim {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kTopKeys = {"name", "base_case", "directory", "design", "parameters", "variants",
                                           "samples", "seed", "set", "outputs", "run", "reduce"};
const std::vector<std::string> kDesigns = {"full_factorial", "table", "latin_hypercube"};
// `flexehd reduce` options a recipe may give (docs/sweep.md); `mesh` is the mesh file.
const std::vector<std::string> kReduceOptions = {"mesh", "order", "size", "E", "nu", "rho", "interface", "modes",
                                                 "cutoff", "static_correction", "pressure_pattern", "axial_order", "axial_hats",
                                                 "circumferential_order", "damping", "damping_band"};
const auto& joined = joinedKeys;

class Reader {
public:
    explicit Reader(const std::string& file) : src_{file, fs::absolute(fs::path(file)).parent_path()} {}

    [[noreturn]] void fail(const std::string& key, const YAML::Node& at, const std::string& msg) const {
        src_.fail(key, at, msg);
    }

    void checkKeys(const YAML::Node& map, const std::string& where, const std::vector<std::string>& keys) const {
        if (!map.IsMap()) fail(where, map, "expected a mapping with the keys " + joined(keys));
        (void)YamlSection(src_, map, where, keys);  // unknown and repeated keys
    }

    double number(const YAML::Node& n, const std::string& key) const {
        double v = 0;
        const std::string t = n.IsScalar() ? n.Scalar() : "";
        const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
        if (t.empty() || ec != std::errc() || p != t.data() + t.size() || !std::isfinite(v))
            fail(key, n, "expected a number, got " + (n.IsScalar() ? "'" + t + "'" : std::string("a non-scalar")));
        return v;
    }

    long long integer(const YAML::Node& n, const std::string& key, long long min) const {
        long long v = 0;
        const std::string t = n.IsScalar() ? n.Scalar() : "";
        const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
        if (t.empty() || ec != std::errc() || p != t.data() + t.size())
            fail(key, n, "expected an integer, got " + (n.IsScalar() ? "'" + t + "'" : std::string("a non-scalar")));
        if (v < min) fail(key, n, fmt::format("expected an integer >= {}, got {}", min, v));
        return v;
    }

    std::string text(const YAML::Node& n, const std::string& key) const {
        if (!n.IsScalar() || n.Scalar().empty()) fail(key, n, "expected a text value");
        return n.Scalar();
    }

    /// A dotted parameter path: non-empty names separated by dots.
    void checkPath(const std::string& path, const YAML::Node& at, const std::string& where) const {
        if (path.empty() || path.front() == '.' || path.back() == '.' || path.find("..") != std::string::npos)
            fail(where, at, "'" + path + "' is not a dotted case-file key like engine.pin_offset");
    }

private:
    YamlSource src_;
};

std::string flow(const YAML::Node& n) {
    YAML::Emitter e;
    e << YAML::Flow << n;
    return e.c_str();
}

std::string formatNumber(double v) { return fmt::format("{:.12g}", v); }

/// The most variants a study expands (each a case file and a run: counted before any is made).
constexpr long long kMaxVariants = 1000000;

/// The number of values of one full-factorial parameter (list, range or single value), before
/// they are made; a range's count beyond kMaxVariants fails there.
long long factorialCount(const Reader& r, const YAML::Node& spec, const std::string& key) {
    if (spec.IsSequence()) return static_cast<long long>(spec.size());
    if (!spec.IsMap() || !spec["count"]) return 1;
    const long long n = r.integer(spec["count"], key + ".count", 1);
    if (n > kMaxVariants)
        r.fail(key + ".count", spec["count"],
               fmt::format("a range of {} values: a study runs at most {} variants", n, kMaxVariants));
    return n;
}

/// Values of one full-factorial parameter: a list, or a range {start, stop, count}.
std::vector<std::string> factorialValues(const Reader& r, const YAML::Node& spec, const std::string& key) {
    std::vector<std::string> values;
    if (spec.IsSequence()) {
        for (const auto& v : spec) values.push_back(flow(v));
    } else if (spec.IsMap()) {
        r.checkKeys(spec, key, {"start", "stop", "count"});
        if (!spec["start"] || !spec["stop"] || !spec["count"])
            r.fail(key, spec, "a range needs start, stop and count");
        const double a = r.number(spec["start"], key + ".start"), b = r.number(spec["stop"], key + ".stop");
        const long long n = r.integer(spec["count"], key + ".count", 1);
        for (long long i = 0; i < n; ++i)
            values.push_back(formatNumber(n == 1 ? a : a + (b - a) * double(i) / double(n - 1)));
    } else {
        values.push_back(flow(spec));  // a single value
    }
    if (values.empty()) r.fail(key, spec, "expected at least one value");
    return values;
}

/// Uniform number in [0, 1) from 53 random bits (portable, unlike std::uniform_real_distribution).
double unit(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

void expandDesign(const Reader& r, const YAML::Node& top, Study& s) {
    std::vector<std::vector<std::string>> rows;
    const YAML::Node params = top["parameters"];
    if (s.design == "table") {
        if (params) r.fail("parameters", params, "a table design lists its values under 'variants' only");
        if (top["samples"] || top["seed"]) r.fail("samples", top["samples"] ? top["samples"] : top["seed"],
                                                  "samples and seed are for design: latin_hypercube");
        const YAML::Node table = top["variants"];
        if (!table || !table.IsSequence() || table.size() == 0)
            r.fail("variants", table, "expected a list of variants, each a mapping key: value");
        for (std::size_t i = 0; i < table.size(); ++i) {
            const std::string where = fmt::format("variants[{}]", i);
            const YAML::Node row = table[i];
            if (!row.IsMap() || row.size() == 0) r.fail(where, row, "expected a mapping key: value");
            if (i == 0)
                for (const auto& kv : row) {
                    r.checkPath(kv.first.Scalar(), kv.first, where);
                    s.parameters.push_back(kv.first.Scalar());
                }
            std::vector<std::string> values(s.parameters.size());
            std::set<std::string> seen;
            for (const auto& kv : row) {
                const std::string k = kv.first.Scalar();
                const auto at = std::find(s.parameters.begin(), s.parameters.end(), k);
                if (at == s.parameters.end())
                    r.fail(where + "." + k, kv.first, "not in the first variant: every variant gives the same keys (" +
                                                          joined(s.parameters) + ")");
                if (!seen.insert(k).second) r.fail(where + "." + k, kv.first, "key given twice");
                values[std::size_t(at - s.parameters.begin())] = flow(kv.second);
            }
            if (seen.size() != s.parameters.size())
                r.fail(where, row, "every variant gives the same keys (" + joined(s.parameters) + ")");
            rows.push_back(values);
        }
    } else {
        if (top["variants"]) r.fail("variants", top["variants"], "only with design: table");
        if (!params || !params.IsMap() || params.size() == 0)
            r.fail("parameters", params, "expected a mapping of dotted case-file keys to their values");
        for (const auto& kv : params) {
            const std::string k = kv.first.Scalar();
            r.checkPath(k, kv.first, "parameters");
            if (std::find(s.parameters.begin(), s.parameters.end(), k) != s.parameters.end())
                r.fail("parameters." + k, kv.first, "key given twice");
            s.parameters.push_back(k);
        }
        if (s.design == "full_factorial") {
            if (top["samples"] || top["seed"]) r.fail("samples", top["samples"] ? top["samples"] : top["seed"],
                                                      "samples and seed are for design: latin_hypercube");
            // Counted before any value is made: the product of the parameters' value counts.
            double variants = 1.0;
            std::string counts;
            for (const auto& kv : params) {
                const long long n = factorialCount(r, kv.second, "parameters." + kv.first.Scalar());
                variants *= double(n);
                counts += fmt::format("{}{} {}", counts.empty() ? "" : " x ", n, kv.first.Scalar());
            }
            if (variants > double(kMaxVariants))
                r.fail("parameters", params,
                       fmt::format("{:.4g} variants ({}): a study runs at most {} variants", variants, counts,
                                   kMaxVariants));
            std::vector<std::vector<std::string>> axes;
            for (const auto& kv : params)
                axes.push_back(factorialValues(r, kv.second, "parameters." + kv.first.Scalar()));
            std::size_t total = 1;
            for (const auto& a : axes) total *= a.size();
            for (std::size_t i = 0; i < total; ++i) {  // the first parameter varies slowest
                std::vector<std::string> values(axes.size());
                std::size_t rest = i;
                for (std::size_t p = axes.size(); p-- > 0;) {
                    values[p] = axes[p][rest % axes[p].size()];
                    rest /= axes[p].size();
                }
                rows.push_back(values);
            }
        } else {  // latin_hypercube: one stratum of [min, max) per sample and parameter
            if (!top["samples"]) r.fail("samples", top, "design: latin_hypercube needs samples (the variant count)");
            const long long n = r.integer(top["samples"], "samples", 1);
            if (n > kMaxVariants)
                r.fail("samples", top["samples"],
                       fmt::format("{} samples: a study runs at most {} variants", n, kMaxVariants));
            const long long seed = top["seed"] ? r.integer(top["seed"], "seed", 0) : 1;
            std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
            rows.assign(std::size_t(n), std::vector<std::string>(s.parameters.size()));
            std::size_t p = 0;
            for (const auto& kv : params) {
                const std::string key = "parameters." + kv.first.Scalar();
                r.checkKeys(kv.second, key, {"min", "max"});
                if (!kv.second["min"] || !kv.second["max"]) r.fail(key, kv.second, "expected {min: …, max: …}");
                const double lo = r.number(kv.second["min"], key + ".min"), hi = r.number(kv.second["max"], key + ".max");
                if (!(hi > lo)) r.fail(key + ".max", kv.second["max"], "max must exceed min");
                std::vector<long long> strata(static_cast<std::size_t>(n));
                for (long long i = 0; i < n; ++i) strata[std::size_t(i)] = i;
                for (std::size_t i = strata.size(); i > 1; --i) std::swap(strata[i - 1], strata[rng() % i]);  // Fisher–Yates
                for (long long i = 0; i < n; ++i)
                    rows[std::size_t(i)][p] = formatNumber(lo + (hi - lo) * (double(strata[std::size_t(i)]) + unit(rng)) / double(n));
                ++p;
            }
        }
    }
    const std::size_t width = std::max<std::size_t>(4, std::to_string(rows.size() - 1).size());
    for (std::size_t i = 0; i < rows.size(); ++i)
        s.variants.push_back({int(i), fmt::format("v{:0{}}", i, width), rows[i]});
}

void readReduce(const Reader& r, const YAML::Node& node, const fs::path& dir, Study& s) {
    r.checkKeys(node, "reduce", {"piston", "liner"});
    for (const auto& kv : node) {
        const std::string body = kv.first.Scalar(), where = "reduce." + body;
        r.checkKeys(kv.second, where, kReduceOptions);
        if (!kv.second["mesh"]) r.fail(where, kv.second, "a reduced-body recipe needs its mesh");
        BodyRecipe b;
        fs::path mesh(r.text(kv.second["mesh"], where + ".mesh"));
        b.mesh = (mesh.is_relative() ? dir / mesh : mesh).lexically_normal().string();
        if (!fs::is_regular_file(b.mesh)) r.fail(where + ".mesh", kv.second["mesh"], b.mesh + " does not exist");
        for (const auto& o : kv.second)
            if (o.first.Scalar() != "mesh") b.options.emplace_back(o.first.Scalar(), flow(o.second));
        s.reduce[body] = b;
    }
}

}  // namespace

const std::vector<std::string>& defaultStudyOutputs() {
    static const std::vector<std::string> k = {"friction_power_mean_w", "fmep_pa", "slap_kinetic_energy_max_j",
                                               "lateral_min_m", "lateral_max_m", "tilt_min_rad", "tilt_max_rad",
                                               "min_film_m", "max_pressure_pa", "contact_force_max_n", "periodic"};
    return k;
}

bool isReduceParameter(const std::string& path) { return path.rfind("reduce.", 0) == 0; }

Study readStudyFile(const std::string& path, const std::string& directoryOverride) {
    const Reader r(path);
    YAML::Node top = loadYamlDocument(path, "the study file");
    r.checkKeys(top, "", kTopKeys);
    const fs::path dir = fs::absolute(path).parent_path();
    Study s;
    s.path = path;
    s.name = top["name"] ? r.text(top["name"], "name") : fs::path(path).stem().string();
    if (!top["base_case"]) r.fail("base_case", top, "required: the case file the variants start from");
    fs::path base(r.text(top["base_case"], "base_case"));
    s.baseCase = (base.is_relative() ? dir / base : base).lexically_normal().string();
    if (!fs::is_regular_file(s.baseCase)) r.fail("base_case", top["base_case"], s.baseCase + " does not exist");
    if (std::error_code ec; fs::equivalent(s.baseCase, path, ec))
        r.fail("base_case", top["base_case"],
               "base_case points at the study file itself: expected the case file (docs/case-file.md) the variants "
               "start from");
    fs::path out = top["directory"] ? fs::path(r.text(top["directory"], "directory")) : fs::path(path).stem();
    if (!directoryOverride.empty()) out = fs::absolute(directoryOverride);
    s.directory = (out.is_relative() ? dir / out : out).lexically_normal().string();

    s.design = top["design"] ? r.text(top["design"], "design") : "full_factorial";
    if (std::find(kDesigns.begin(), kDesigns.end(), s.design) == kDesigns.end())
        r.fail("design", top["design"], "expected one of " + joined(kDesigns) + ", got '" + s.design + "'");
    if (top["set"]) {
        if (!top["set"].IsMap()) r.fail("set", top["set"], "expected a mapping of dotted case-file keys to values");
        for (const auto& kv : top["set"]) {
            r.checkPath(kv.first.Scalar(), kv.first, "set");
            s.fixed.emplace_back(kv.first.Scalar(), flow(kv.second));
        }
    }
    expandDesign(r, top, s);
    for (const auto& [key, value] : s.fixed)
        if (std::find(s.parameters.begin(), s.parameters.end(), key) != s.parameters.end())
            r.fail("set." + key, top["set"][key],
                   key + " is given both in set and in parameters: a key is the same in every variant (set) or "
                         "varies (parameters), not both");

    if (top["outputs"]) {
        if (!top["outputs"].IsSequence() || top["outputs"].size() == 0)
            r.fail("outputs", top["outputs"], "expected a list of summary.json keys");
        for (const auto& o : top["outputs"]) {
            const std::string k = r.text(o, "outputs");
            const std::vector<std::string>& keys = runSummaryKeys();
            // The contacts' figures: the ring pack's (rings.<name>.<figure>, fmep_total_pa) and the
            // oil-control ring band's.
            const bool contactFigure =
                RingContact::isFigureKey(k) || k == "fmep_total_pa" || k == OilControlRingBand::kDrainFigure;
            if (!contactFigure && std::find(keys.begin(), keys.end(), k) == keys.end())
                r.fail("outputs", o,
                       "'" + k + "' is not a summary.json key; valid: " + joined(keys) +
                           ", fmep_total_pa, " + OilControlRingBand::kDrainFigure +
                           ", " + joined(RingContact::blowByFigures()) +
                           " and rings.<name>.<figure> with a figure of " + joined(RingContact::figureNames()));
            s.outputs.push_back(k);
        }
    } else {
        s.outputs = defaultStudyOutputs();
    }
    if (top["run"]) {
        const YAML::Node run = top["run"];
        r.checkKeys(run, "run", {"cycles", "rigid", "timeout_s"});
        if (run["cycles"]) s.run.cycles = int(r.integer(run["cycles"], "run.cycles", 1));
        if (run["rigid"]) {
            const std::string t = r.text(run["rigid"], "run.rigid");
            if (t != "true" && t != "false") r.fail("run.rigid", run["rigid"], "expected true or false");
            s.run.rigid = t == "true";
        }
        if (run["timeout_s"]) {
            s.run.timeoutSeconds = r.number(run["timeout_s"], "run.timeout_s");
            if (s.run.timeoutSeconds < 0) r.fail("run.timeout_s", run["timeout_s"], "expected >= 0 (0 = none)");
        }
    }
    if (top["reduce"]) readReduce(r, top["reduce"], dir, s);

    // Parameters on reduced-body recipes name an option of a recipe the study gives.
    const YAML::Node where = top["parameters"] ? top["parameters"] : top["variants"];
    for (const auto& p : s.parameters) {
        if (!isReduceParameter(p)) continue;
        const auto dot = p.find('.', 7);
        const std::string body = p.substr(7, dot == std::string::npos ? std::string::npos : dot - 7);
        const std::string option = dot == std::string::npos ? "" : p.substr(dot + 1);
        if (!s.reduce.count(body))
            r.fail(p, where, "the study has no reduced-body recipe reduce." + body + " (piston or liner)");
        if (std::find(kReduceOptions.begin(), kReduceOptions.end(), option) == kReduceOptions.end())
            r.fail(p, where, "'" + option + "' is not an option of a recipe; valid: " + joined(kReduceOptions));
    }
    checkCaseKeys(s);
    return s;
}

}  // namespace flexehd::cosim
