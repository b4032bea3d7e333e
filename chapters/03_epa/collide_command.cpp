// `stepwise collide`: pairs in, one ContactQuery per pair out (see collide_command.h).
#include "03_epa/collide_command.h"

#include "app/bench_util.h"
#include "world/scene.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>
#include <type_traits>

namespace stepwise {

namespace {

using Json = nlohmann::ordered_json;

/// Parses JSON, rejecting duplicate keys (nlohmann would silently keep the last one) with the
/// path of the second, as the scene loader does.
Json parseStrict(const std::string& text, const std::string& source) {
    struct Frame {
        bool isArray = false;
        std::size_t index = 0;
        std::string key;
        std::set<std::string> keys;
    };
    std::vector<Frame> frames;
    // The path of the value being parsed; without the innermost designator, of its container.
    const auto path = [&frames](bool withInnermost) {
        std::string result;
        for (std::size_t i = 0; i + (withInnermost ? 0 : 1) < frames.size(); ++i) {
            const Frame& frame = frames[i];
            result += frame.isArray ? "[" + std::to_string(frame.index) + "]" : (result.empty() ? "" : ".") + frame.key;
        }
        return result;
    };
    using Event = nlohmann::json::parse_event_t;
    const Json::parser_callback_t callback = [&](int, Event event, Json& parsed) {
        if (event == Event::object_start || event == Event::array_start) {
            frames.push_back(Frame{event == Event::array_start, 0, {}, {}});
        } else if (event == Event::object_end || event == Event::array_end || event == Event::value) {
            if (event != Event::value) frames.pop_back();
            if (!frames.empty() && frames.back().isArray) ++frames.back().index;
        } else if (event == Event::key) {
            Frame& frame = frames.back();
            frame.key = parsed.get<std::string>();
            if (!frame.keys.insert(frame.key).second) {
                const std::string where = frames.size() > 1 ? path(false) : source;  // the file, at the top
                throw SceneError(where, "duplicate key \"" + frame.key + "\"");
            }
        }
        return true;
    };
    try {
        return Json::parse(text, callback);
    } catch (const nlohmann::json::parse_error& error) {
        const std::string what = error.what();
        const std::size_t at = what.find("line ");
        throw SceneError(source, "malformed JSON at " + (at == std::string::npos ? what : what.substr(at)));
    } catch (const nlohmann::json::out_of_range&) {
        throw SceneError(path(true), "must be a finite number");
    }
}

/// Rejects keys a pairs file does not define, naming the object they are in (as the loader does).
void expectKeys(const Json& object, const std::string& path, const std::vector<std::string>& accepted) {
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (std::find(accepted.begin(), accepted.end(), it.key()) != accepted.end()) continue;
        std::string list;
        for (const std::string& key : accepted) list += (list.empty() ? "" : ", ") + key;
        throw SceneError(path, "unknown key \"" + it.key() + "\" (accepted: " + list + ")");
    }
}

/// Scene-loader errors name "bodies[k]..."; body k is pair k / 2, side a or b.
SceneError asPairError(const SceneError& error) {
    const std::string& path = error.path();
    const std::string message = std::string(error.what()).substr(path.empty() ? 0 : path.size() + 2);
    const std::string prefix = "bodies[";
    if (path.compare(0, prefix.size(), prefix) != 0) return error;
    const std::size_t close = path.find(']');
    const long index = std::strtol(path.c_str() + prefix.size(), nullptr, 10);
    return SceneError("pairs[" + std::to_string(index / 2) + "]." + (index % 2 ? "b" : "a") + path.substr(close + 1),
                      message);
}

/// The shortest decimal that reads back as the same Real (0.1f prints as 0.1).
double tidy(Real value) {
    if (value == 0) return 0.0;
    if constexpr (std::is_same_v<Real, float>) {
        char text[32];
        for (int digits = 6; digits <= 9; ++digits) {
            std::snprintf(text, sizeof text, "%.*g", digits, double(value));
            const double parsed = std::strtod(text, nullptr);
            if (Real(parsed) == value) return parsed;
        }
    }
    return double(value);
}

Json toJson(const Vec3& v) { return Json::array({tidy(v.x()), tidy(v.y()), tidy(v.z())}); }

std::string readFile(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) throw SceneError(path, "no such file");
    if (std::filesystem::is_directory(path, error)) throw SceneError(path, "is a directory, not a pairs file");
    std::ifstream file(path, std::ios::binary);
    if (!file) throw SceneError(path, "cannot open the file for reading");
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

}  // namespace

// [ch03-collide-parse]
std::vector<CollidePair> parseCollidePairs(const std::string& jsonText, const std::string& source) {
    const Json document = parseStrict(jsonText, source);
    if (!document.is_object()) throw SceneError(source, "must be a JSON object { \"pairs\": [ ... ] }");
    expectKeys(document, source, {"pairs", "description"});
    if (!document.contains("pairs")) throw SceneError(source, "missing required key \"pairs\"");
    const Json& pairs = document["pairs"];
    if (!pairs.is_array()) throw SceneError("pairs", "must be an array of { \"a\": BODY, \"b\": BODY }");

    // Every BODY becomes a body of one scene, so the scene loader validates it with its own
    // rules and messages; only the paths are translated back ("bodies[5]" is "pairs[2].b").
    Json scene = {{"bodies", Json::array()}};
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const std::string path = "pairs[" + std::to_string(i) + "]";
        if (!pairs[i].is_object()) throw SceneError(path, "must be an object { \"a\": BODY, \"b\": BODY }");
        expectKeys(pairs[i], path, {"a", "b"});
        for (const char* side : {"a", "b"}) {
            if (!pairs[i].contains(side)) throw SceneError(path, std::string("missing required key \"") + side + "\"");
            Json body = pairs[i][side];
            if (body.is_object()) body.erase("name");  // names are scene business; keep them unique
            scene["bodies"].push_back(body);
        }
    }
    World world;
    try {
        world = loadSceneFromString(scene.dump(), source);
    } catch (const SceneError& error) {
        throw asPairError(error);
    }
    std::vector<CollidePair> result(pairs.size());
    for (std::size_t i = 0; i < result.size(); ++i) {
        result[i].shapeA = world.bodies[2 * i].shape;
        result[i].poseA = world.bodies[2 * i].transform;
        result[i].shapeB = world.bodies[2 * i + 1].shape;
        result[i].poseB = world.bodies[2 * i + 1].transform;
    }
    return result;
}
// [ch03-collide-parse]

std::string collideResultsToJson(const std::vector<ContactQuery>& results) {
    // One result per line: a batch of thousands stays readable and diffable.
    std::string text = "{\n  \"results\": [";
    for (std::size_t i = 0; i < results.size(); ++i) {
        const ContactQuery& query = results[i];
        const Json entry = {{"intersect", query.intersect},
                            {"depth", tidy(query.depth)},
                            {"normal", toJson(query.normal)},
                            {"point_a", toJson(query.pointA)},
                            {"point_b", toJson(query.pointB)},
                            {"gjk_iterations", query.gjkIterations},
                            {"epa_iterations", query.epaIterations},
                            {"routine", query.routine}};
        text += (i ? ",\n    " : "\n    ") + entry.dump();
    }
    return text + (results.empty() ? "]\n}\n" : "\n  ]\n}\n");
}

int runCollideCommand(const CollideArgs& args, std::ostream& out, std::ostream& err) {
    std::vector<CollidePair> pairs;
    try {
        pairs = parseCollidePairs(readFile(args.inputPath), args.inputPath);
    } catch (const SceneError& error) {
        err << "error: " << error.what() << "\n";
        return 2;
    }
    std::vector<ContactQuery> results(pairs.size());
    const auto runBatch = [&] {
        for (std::size_t i = 0; i < pairs.size(); ++i) {
            results[i] = collideShapes(pairs[i].shapeA, pairs[i].poseA, pairs[i].shapeB, pairs[i].poseB);
        }
    };
    runBatch();
    if (args.time && !pairs.empty()) {
        // The queries alone: repeat the batch until a quarter second has passed, so a timer
        // tick is a negligible part of the measurement even for a single pair.
        long repeats = 0;
        const Stopwatch clock;
        do {
            runBatch();
            ++repeats;
        } while (clock.seconds() < 0.25);
        const double nsPerQuery = clock.seconds() * 1e9 / (double(repeats) * double(pairs.size()));
        // Keep stdout parseable when the results go there.
        std::ostream& report = args.outputPath.empty() ? err : out;
        report << "collide: " << pairs.size() << " pairs x " << repeats << " repeats, " << formatNumber(nsPerQuery)
               << " ns per query\n";
    }
    const std::string text = collideResultsToJson(results);
    if (args.outputPath.empty()) {
        out << text;
        return 0;
    }
    std::ofstream file(args.outputPath, std::ios::binary);
    file << text;
    if (!file) {
        err << "error: " << args.outputPath << ": cannot write the file\n";
        return 2;
    }
    return 0;
}

void installCollideCommand(CLI::App& app, int& exitCode) {
    auto args = std::make_shared<CollideArgs>();
    CLI::App* collide =
        app.add_subcommand("collide", "Contact queries for pairs of shapes: depth, normal and points (JSON in and out)");
    collide->add_option("--input", args->inputPath, "Pairs file: { \"pairs\": [ { \"a\": BODY, \"b\": BODY } ] }")
        ->required();
    collide->add_option("--output", args->outputPath, "Write the results here (default: standard output)");
    collide->add_flag("--time", args->time, "Also print the time per query (parsing and writing excluded)");
    collide->callback([args, &exitCode] { exitCode = runCollideCommand(*args, std::cout, std::cerr); });
}

}  // namespace stepwise
