// `stepwise collide`: pairs in, one ContactQuery per pair out (see collide_command.h).
#include "03_epa/collide_command.h"

#include "app/bench_util.h"
#include "world/json_reader.h"
#include "world/scene.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

namespace stepwise {

namespace {

/// One BODY of a pair: a shape and a pose, read with the scene loader's rules and messages
/// (json_reader.h), so `pairs[2].b.shape.box.half_extents[1]: must be > 0` names the value.
/// The other keys of a scene body are accepted and ignored: a query has no dynamics.
void readQueryBody(const JsonCursor& body, Shape& shape, Transform& pose) {
    body.expectObject({"name", "type", "shape", "position", "orientation", "velocity", "angular_velocity", "mass",
                       "density", "friction", "restitution", "bullet", "integrator"});
    shape = readShape(body.child("shape"));
    pose = Transform{};
    if (auto position = body.optional("position")) pose.position = position->vec3Within(kMaxCoordinate);
    if (auto orientation = body.optional("orientation")) pose.rotation = orientation->unitQuaternion();
}

}  // namespace

// [ch03-collide-parse]
std::vector<CollidePair> parseCollidePairs(const std::string& jsonText, const std::string& source) {
    const Json document = parseStrictJson(jsonText, source);
    const JsonCursor root(document, "");
    if (!document.is_object()) root.fail(source + " must be a JSON object { \"pairs\": [ ... ] }");
    root.expectObject({"pairs", "description"});
    const JsonCursor pairs = root.child("pairs");
    std::vector<CollidePair> result(pairs.arraySizeAtMost(kMaxQueryPairs));
    for (std::size_t i = 0; i < result.size(); ++i) {
        const JsonCursor pair = pairs.element(i);
        pair.expectObject({"a", "b"});
        const JsonCursor bodyA = pair.child("a"), bodyB = pair.child("b");  // both present first
        readQueryBody(bodyA, result[i].shapeA, result[i].poseA);
        readQueryBody(bodyB, result[i].shapeB, result[i].poseB);
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
                            {"depth", tidyNumber(query.depth)},
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
        pairs = parseCollidePairs(readInputFile(args.inputPath, "a pairs file"), args.inputPath);
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
