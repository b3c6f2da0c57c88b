#include "cosim/study/StudyTable.hpp"
#include "cosim/io/JsonText.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "fem/AtomicFile.hpp"

namespace flexehd::cosim {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string q(1, '"');
    for (const char c : s) {
        q += c;
        if (c == '"') q += c;
    }
    q += '"';
    return q;
}

/// A summary.json value as table text: numbers in the shortest form that reads back exactly.
std::string valueText(const json& v) {
    if (v.is_number_float()) return fmt::format("{}", v.get<double>());
    if (v.is_number_integer()) return fmt::format("{}", v.get<long long>());
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    if (v.is_string()) return v.get<std::string>();
    return v.is_null() ? "" : jsonText(v);
}

/// Table text back to JSON: a number, a boolean or a string.
json textValue(const std::string& t) {
    if (t == "true" || t == "false") return t == "true";
    double d = 0;
    const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), d);
    if (!t.empty() && ec == std::errc() && p == t.data() + t.size() && std::isfinite(d)) return d;
    if (t.size() >= 2 && t.front() == '"' && t.back() == '"') return t.substr(1, t.size() - 2);
    return t;
}

const json* lookup(const json& doc, const std::string& dotted) {
    const json* cur = &doc;
    std::size_t from = 0;
    while (true) {
        const std::size_t dot = dotted.find('.', from);
        const std::string k = dotted.substr(from, dot == std::string::npos ? std::string::npos : dot - from);
        if (!cur->is_object() || !cur->contains(k)) return nullptr;
        cur = &(*cur)[k];
        if (dot == std::string::npos) return cur;
        from = dot + 1;
    }
}

}  // namespace

std::string variantDirectory(const Study& study, const StudyVariant& variant) {
    return (fs::path(study.directory) / "variants" / variant.id).string();
}

VariantResult readVariantResult(const Study& study, const std::string& summaryPath) {
    VariantResult r;
    std::ifstream f(summaryPath);
    if (!f) return r;
    json doc;
    try {
        doc = json::parse(f);
    } catch (const json::exception&) {
        return r;
    }
    if (!doc.is_object() || !doc.contains("status") || !doc["status"].is_string()) return r;
    r.status = doc["status"] == "ok" ? "ok" : "failed";
    r.message = doc.value("message", std::string());
    if (r.status == "failed" && r.message.empty()) r.message = "the run produced no complete cycle";
    for (const auto& key : study.outputs) {
        const json* v = lookup(doc, key);
        r.outputs.push_back(v ? valueText(*v) : "");
    }
    if (const json* t = lookup(doc, "timings_s.total"); t && t->is_number()) r.runSeconds = t->get<double>();
    return r;
}

void writeStudyTables(const Study& study, const std::vector<VariantResult>& results) {
    std::string csv = "variant,id";
    for (const auto& p : study.parameters) csv.append(",").append(csvField(p));
    csv += ",status";
    for (const auto& o : study.outputs) csv.append(",").append(csvField(o));
    csv += ",run_time_s,error\n";
    json rows = json::array();
    int ok = 0, failed = 0;
    for (std::size_t i = 0; i < study.variants.size(); ++i) {
        const StudyVariant& v = study.variants[i];
        const VariantResult& r = results[i];
        json row = {{"index", v.index}, {"id", v.id}, {"directory", variantDirectory(study, v)}};
        json params = json::object();
        for (std::size_t p = 0; p < study.parameters.size(); ++p) params[study.parameters[p]] = textValue(v.values[p]);
        row["parameters"] = params;
        row["status"] = r.status.empty() ? "pending" : r.status;
        if (r.status.empty()) {
            rows.push_back(row);
            continue;
        }
        (r.status == "ok" ? ok : failed) += 1;
        if (!r.message.empty()) row["message"] = r.message;
        json outs = json::object();
        for (std::size_t o = 0; o < study.outputs.size() && o < r.outputs.size(); ++o)
            if (!r.outputs[o].empty()) outs[study.outputs[o]] = textValue(r.outputs[o]);
        row["outputs"] = outs;
        row["run_time_s"] = r.runSeconds;
        row["rank"] = r.rank;
        row["resumed"] = r.resumed;
        rows.push_back(row);

        csv += fmt::format("{},{}", v.index, v.id);
        for (const auto& value : v.values) csv.append(",").append(csvField(value));
        csv.append(",").append(r.status);
        for (std::size_t o = 0; o < study.outputs.size(); ++o)
            csv.append(",").append(csvField(o < r.outputs.size() ? r.outputs[o] : ""));
        csv += fmt::format(",{:.3f},{}\n", r.runSeconds, csvField(r.message));
    }
    const int n = int(study.variants.size());
    const json doc = {{"study", study.name},
                      {"study_file", fs::absolute(study.path).string()},
                      {"base_case", study.baseCase},
                      {"directory", study.directory},
                      {"design", study.design},
                      {"parameters", study.parameters},
                      {"outputs", study.outputs},
                      {"counts", {{"variants", n}, {"ok", ok}, {"failed", failed}, {"pending", n - ok - failed}}},
                      {"variants", rows}};
    fs::create_directories(study.directory);
    fem::writeTextAtomically((fs::path(study.directory) / "study.csv").string(), csv);
    fem::writeTextAtomically((fs::path(study.directory) / "study.json").string(), jsonText(doc, 2) + "\n");
}

std::string serializeResult(const VariantResult& r) {
    return jsonText(json{{"status", r.status},   {"message", r.message}, {"outputs", r.outputs},
                         {"run_time_s", r.runSeconds}, {"rank", r.rank},  {"resumed", r.resumed}});
}

VariantResult deserializeResult(const std::string& text) {
    const json j = json::parse(text);
    VariantResult r;
    r.status = j.at("status").get<std::string>();
    r.message = j.at("message").get<std::string>();
    r.outputs = j.at("outputs").get<std::vector<std::string>>();
    r.runSeconds = j.at("run_time_s").get<double>();
    r.rank = j.at("rank").get<int>();
    r.resumed = j.at("resumed").get<bool>();
    return r;
}

}  // namespace flexehd::cosim
