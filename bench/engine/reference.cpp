// Sidecar parsing and the metrics of the reference suite: each metric is a closed form or a
// conservation law compared with a recorded run (reference.h).
#include "engine/reference.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace stepwise::engine_bench {

namespace {

using nlohmann::json;

// [engine-bench-metrics]
// Metric -> the keys its check takes besides metric, tolerance and why.
const std::map<std::string, std::vector<std::string>>& metricKeys() {
    static const std::map<std::string, std::vector<std::string>> keys = {
        {"closed_form_position", {"body"}},          // max |x(t) - (x0 + v0 t + g t^2 / 2)|, m
        {"closed_form_rotation", {"body"}},          // max angle between q(t) and exp(w t) q0, rad
        {"bounce_apex", {"body", "expected"}},       // |first apex after the first bounce - expected|, m
        {"final_speed", {"body", "expected"}},       // |speed at the end - expected|, m/s
        {"displacement", {"body", "expected"}},      // |distance moved start to end - expected|, m
        {"period", {"body", "center", "expected"}},  // |mean period of x crossing center - expected|, s
        {"max_distance", {"body", "point", "to", "expected"}},  // max over frames of (|point - to| - expected)+, m
        {"drift", {}},                               // largest sideways move of a dynamic body, m
        {"sag", {}},                                 // largest drop of a dynamic body, m
        {"max_coordinate", {"body", "axis", "limit"}},  // (max over frames of x[axis] - limit)+, m
        {"momentum", {}},                            // |P_end - P_start| of the dynamic bodies, kg m/s
        {"energy_change", {}},                       // |E_end - E_start| / |E_start|
        {"energy_gain", {}},                         // (E_end - E_start)+ / |E_start|
        {"penetration", {}},                         // deepest overlap at the end, m
        {"time_to_rest", {"kinetic_fraction"}},      // s until kinetic energy stays below the fraction of E_start
    };
    return keys;
}
// [engine-bench-metrics]

std::string joinedQuoted(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

/// Reads one sidecar; the first problem throws SidecarError as "SOURCE: PATH: message".
class Reader {
public:
    explicit Reader(std::string source) : source_(std::move(source)) {}
    [[noreturn]] void fail(const std::string& path, const std::string& message) const {
        throw SidecarError(source_ + ": " + (path.empty() ? "" : path + ": ") + message);
    }
    void onlyKeys(const json& object, const std::string& path, const std::vector<std::string>& allowed) const {
        for (const auto& item : object.items())
            if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end())
                fail(path, "unknown key \"" + item.key() + "\" (accepted: " + joinedQuoted(allowed) + ")");
    }
    const json& required(const json& object, const std::string& key, const std::string& path) const {
        if (!object.contains(key)) fail(path, "missing \"" + key + "\"");
        return object.at(key);
    }
    double number(const json& value, const std::string& path) const {
        if (!value.is_number() || !std::isfinite(value.get<double>())) fail(path, "must be a finite number");
        return value.get<double>();
    }
    std::string text(const json& value, const std::string& path) const {
        if (!value.is_string() || value.get<std::string>().empty()) fail(path, "must be a non-empty string");
        return value.get<std::string>();
    }
    Vec3 vector(const json& value, const std::string& path) const {
        if (!value.is_array() || value.size() != 3) fail(path, "must be [x, y, z]");
        return Vec3(Real(number(value[0], path + "[0]")), Real(number(value[1], path + "[1]")),
                    Real(number(value[2], path + "[2]")));
    }

private:
    std::string source_;
};

Check readCheck(const Reader& reader, const json& item, const std::string& path) {
    if (!item.is_object()) reader.fail(path, "must be an object");
    Check check;
    check.metric = reader.text(reader.required(item, "metric", path), path + ".metric");
    const auto found = metricKeys().find(check.metric);
    if (found == metricKeys().end())
        reader.fail(path + ".metric", "unknown metric \"" + check.metric + "\" (known: " + joinedQuoted(metricNames()) + ")");
    std::vector<std::string> allowed = {"metric", "tolerance", "why"};
    allowed.insert(allowed.end(), found->second.begin(), found->second.end());
    reader.onlyKeys(item, path, allowed);
    check.tolerance = reader.number(reader.required(item, "tolerance", path), path + ".tolerance");
    if (check.tolerance <= 0) reader.fail(path + ".tolerance", "must be > 0");
    check.why = reader.text(reader.required(item, "why", path), path + ".why");
    for (const std::string& key : found->second) {
        const std::string at = path + "." + key;
        if (key == "kinetic_fraction") {
            if (item.contains(key)) check.kineticFraction = reader.number(item.at(key), at);
            if (check.kineticFraction <= 0) reader.fail(at, "must be > 0");
            continue;
        }
        const json& value = reader.required(item, key, path);
        if (key == "body") check.body = reader.text(value, at);
        if (key == "expected") check.expected = reader.number(value, at);
        if (key == "center") check.center = reader.number(value, at);
        if (key == "limit") check.limit = reader.number(value, at);
        if (key == "point") check.point = reader.vector(value, at);
        if (key == "to") check.to = reader.vector(value, at);
        if (key == "axis") {
            if (!value.is_number_integer() || value.get<int>() < 0 || value.get<int>() > 2) reader.fail(at, "must be 0, 1 or 2");
            check.axis = value.get<int>();
        }
    }
    return check;
}

}  // namespace

const std::vector<std::string>& metricNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> list;
        for (const auto& [name, keys] : metricKeys()) list.push_back(name);
        return list;
    }();
    return names;
}

const std::vector<std::string>& groupNames() {
    static const std::vector<std::string> names = {"closed-form", "contact", "joint", "stack", "pile"};
    return names;
}

Sidecar parseSidecar(const std::string& jsonText, const std::string& source) {
    const Reader reader(source);
    json root;
    try {
        root = json::parse(jsonText);
    } catch (const json::parse_error& error) {
        reader.fail("", std::string("malformed JSON: ") + error.what());
    }
    if (!root.is_object()) reader.fail("", "must be a JSON object");
    reader.onlyKeys(root, "", {"format", "version", "group", "seconds", "checks"});
    if (reader.text(reader.required(root, "format", ""), "format") != "stepwise-expect")
        reader.fail("format", "must be \"stepwise-expect\"");
    if (reader.number(reader.required(root, "version", ""), "version") != 1) reader.fail("version", "must be 1");
    Sidecar sidecar;
    sidecar.group = reader.text(reader.required(root, "group", ""), "group");
    if (std::find(groupNames().begin(), groupNames().end(), sidecar.group) == groupNames().end())
        reader.fail("group", "must be one of " + joinedQuoted(groupNames()) + " (got \"" + sidecar.group + "\")");
    sidecar.seconds = reader.number(reader.required(root, "seconds", ""), "seconds");
    if (sidecar.seconds <= 0 || sidecar.seconds > 600) reader.fail("seconds", "must be > 0 and <= 600");
    const json& checks = reader.required(root, "checks", "");
    if (!checks.is_array() || checks.empty()) reader.fail("checks", "must be a non-empty array");
    for (std::size_t i = 0; i < checks.size(); ++i)
        sidecar.checks.push_back(readCheck(reader, checks[i], "checks[" + std::to_string(i) + "]"));
    return sidecar;
}

Sidecar loadSidecar(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw SidecarError(path + ": no such file (every reference scene needs its sidecar NAME.expect.json)");
    std::ostringstream text;
    text << file.rdbuf();
    return parseSidecar(text.str(), path);
}

}  // namespace stepwise::engine_bench
