// `stepwise collide`: pairs in, one ContactQuery per pair out (see collide_command.h).
#include "03_epa/collide_command.h"

#include "app/bench_util.h"
#include "world/json_reader.h"
#include "world/scene.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

namespace stepwise {

namespace {

/// One BODY of a pair, read by the scene loader's own body reader (json_reader.h): the same
/// keys, rules and messages as a scene body, so a static body with a mass is rejected here as
/// it is by `run`, and `pairs[2].b.shape.box.half_extents[1]: must be > 0` names the value. A
/// query uses only the shape and the pose; the other keys are checked and then unused.
void readQueryBody(const JsonCursor& body, std::size_t index, Shape& shape, Transform& pose, ErrorList& errors) {
    if (!body.json().is_object()) body.fail("must be an object");
    const BodyDef def = readBodyDef(body, index, errors);
    shape = def.shape;
    pose = def.transform;
}

/// A file in one of the project's other formats, recognised by its "format" key or its keys,
/// is named as such: "unknown key \"format\"" would not tell the user what went wrong.
void rejectOtherFormats(const JsonCursor& root) {
    const Json& document = root.json();
    const std::string format = document.contains("format") && document["format"].is_string()
                                   ? document["format"].get<std::string>()
                                   : "";
    const char* expected = "collide reads a query file: { \"pairs\": [ { \"a\": BODY, \"b\": BODY }, ... ] } "
                           "(docs/scene-format.md, \"Narrow-phase query\")";
    if (format == "stepwise-scene" || (format.empty() && document.contains("bodies")))
        root.fail(std::string("this is a scene file (format \"stepwise-scene\"); ") + expected +
                  "; to simulate a scene use `stepwise run FILE`");
    if (format == "stepwise-report")
        root.fail(std::string("this is a run report (format \"stepwise-report\"); ") + expected);
    if (document.contains("results") && !document.contains("pairs"))
        root.fail(std::string("this looks like collide's own output (it has \"results\"); ") + expected);
}

}  // namespace

// [ch03-collide-parse]
std::vector<CollidePair> parseCollidePairs(const std::string& jsonText, const std::string& source) {
    const Json document = parseStrictJson(jsonText, source);
    const JsonCursor root(document, "");
    if (!document.is_object()) root.fail(source + " must be a JSON object { \"pairs\": [ ... ] }");
    rejectOtherFormats(root);
    ErrorList errors;  // every error of the file at once, up to a limit
    root.expectObject({"pairs", "description"}, &errors);
    std::vector<CollidePair> result;
    errors.attempt([&] {
        const JsonCursor pairs = root.child("pairs");
        result.resize(pairs.arraySizeAtMost(kMaxQueryPairs));
        for (std::size_t i = 0; i < result.size(); ++i) {
            errors.attempt([&] {
                const JsonCursor pair = pairs.element(i);
                pair.expectObject({"a", "b"}, &errors);
                const JsonCursor bodyA = pair.child("a"), bodyB = pair.child("b");  // both present first
                errors.attempt([&] { readQueryBody(bodyA, 0, result[i].shapeA, result[i].poseA, errors); });
                errors.attempt([&] { readQueryBody(bodyB, 1, result[i].shapeB, result[i].poseB, errors); });
            });
        }
    });
    errors.throwIfAny();
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
        printSceneError(err, error);
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

void installCollideCommand(Command program, int& exitCode) {
    auto args = std::make_shared<CollideArgs>();
    Command collide =
        program.addSubcommand("collide", "Contact queries for pairs of shapes: depth, normal and points (JSON in and out)");
    collide.addOption("--input", args->inputPath, "Pairs file: { \"pairs\": [ { \"a\": BODY, \"b\": BODY } ] }").required();
    collide.addOption("--output", args->outputPath, "Write the results here (default: standard output)");
    collide.addFlag("--time", args->time, "Also print the time per query (parsing and writing excluded)");
    collide.onParsed([args, &exitCode] { exitCode = runCollideCommand(*args, std::cout, std::cerr); });
}

}  // namespace stepwise
