// `stepwise collide`: the narrow-phase query contract, good input and bad.
#include "03_epa/collide_command.h"
#include "support/temp_path.h"

#include <CLI/CLI.hpp>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace stepwise;
using Json = nlohmann::json;

namespace {

std::string writeTemp(const std::string& name, const std::string& text) {
    const std::string path = test::tempPath("ch03_collide_" + name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

struct Run {
    int code = -1;
    std::string out, err;
};

Run collide(const std::string& inputText, bool time = false, const std::string& outputPath = "") {
    CollideArgs args;
    args.inputPath = writeTemp("input.json", inputText);
    args.outputPath = outputPath;
    args.time = time;
    std::ostringstream out, err;
    Run run;
    run.code = runCollideCommand(args, out, err);
    run.out = out.str();
    run.err = err.str();
    return run;
}

const char* const kPairs = R"({ "pairs": [
  { "a": { "shape": { "box": { "half_extents": [0.5, 0.5, 0.5] } }, "position": [0, 0, 0] },
    "b": { "shape": { "box": { "half_extents": [0.5, 0.5, 0.5] } }, "position": [0, 0.9, 0],
           "orientation": [0, 0, 0, 1] } },
  { "a": { "shape": { "sphere": { "radius": 0.5 } }, "position": [0, 0, 0] },
    "b": { "shape": { "sphere": { "radius": 0.25 } }, "position": [2, 0, 0] } },
  { "a": { "shape": { "capsule": { "radius": 0.25, "half_height": 0.5 } } },
    "b": { "shape": { "sphere": { "radius": 0.5 } }, "position": [0.5, 0.2, 0] } },
  { "a": { "shape": { "convex": { "vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]] } }, "position": [0, 0, 0] },
    "b": { "shape": { "box": { "half_extents": [1, 1, 1] } }, "position": [3, 0, 0] } }
] })";

}  // namespace

TEST_CASE("collide answers one result per pair, in order", "[ch03][collide]") {
    const Run run = collide(kPairs);
    REQUIRE(run.code == 0);
    CHECK(run.err.empty());
    const Json document = Json::parse(run.out);
    const Json& results = document.at("results");
    REQUIRE(results.size() == 4);

    const Json& boxes = results[0];
    CHECK(boxes.at("intersect") == true);
    CHECK(boxes.at("depth").get<double>() == Approx(0.1).epsilon(1e-4));
    CHECK(boxes.at("normal")[1].get<double>() == Approx(1).epsilon(1e-5));
    CHECK(boxes.at("point_a")[1].get<double>() == Approx(0.5).epsilon(1e-4));
    CHECK(boxes.at("point_b")[1].get<double>() == Approx(0.4).epsilon(1e-4));
    CHECK(boxes.at("gjk_iterations").get<int>() > 0);
    CHECK(boxes.at("epa_iterations").get<int>() >= 0);
    CHECK(boxes.at("routine") == "gjk_epa");

    const Json& spheres = results[1];  // 1.25 m apart: depth is minus the distance
    CHECK(spheres.at("intersect") == false);
    CHECK(spheres.at("depth").get<double>() == Approx(-1.25));
    CHECK(spheres.at("normal")[0].get<double>() == Approx(1));
    CHECK(spheres.at("routine") == "sphere_sphere");

    CHECK(results[2].at("routine") == "capsule_sphere");
    CHECK(results[2].at("intersect") == true);
    CHECK(results[2].at("depth").get<double>() == Approx(0.25).epsilon(1e-5));

    const Json& hull = results[3];  // hull reaches x = 1, the box starts at x = 2
    CHECK(hull.at("intersect") == false);
    CHECK(hull.at("depth").get<double>() == Approx(-1).epsilon(1e-4));
    CHECK(hull.at("routine") == "gjk_epa");
}

TEST_CASE("collide writes to --output and times the queries with --time", "[ch03][collide]") {
    const std::string output = test::tempPath("ch03_collide_results.json").string();
    std::filesystem::remove(output);
    const Run run = collide(kPairs, true, output);
    REQUIRE(run.code == 0);
    CHECK(run.out.find("ns per query") != std::string::npos);  // results are in the file, so stdout
    std::ifstream file(output);
    const Json document = Json::parse(file);
    CHECK(document.at("results").size() == 4);

    const Run toStdout = collide(kPairs, true);
    CHECK(toStdout.err.find("ns per query") != std::string::npos);  // stdout stays pure JSON
    CHECK(Json::parse(toStdout.out).at("results").size() == 4);
}

TEST_CASE("collide rejects bad input with the JSON path and exit code 2", "[ch03][collide]") {
    const auto expectError = [](const std::string& text, const std::string& message) {
        const Run run = collide(text);
        INFO("stderr: " << run.err);
        CHECK(run.code == 2);
        CHECK(run.out.empty());
        CHECK(run.err.rfind("error: ", 0) == 0);
        CHECK(run.err.find(message) != std::string::npos);
    };
    expectError("{ \"pairs\": [ ", "malformed JSON");
    expectError("[1, 2]", "must be a JSON object");
    expectError("{}", "missing required key \"pairs\"");
    expectError("{ \"pairs\": {} }", "pairs: must be an array");
    expectError("{ \"pairs\": [], \"extra\": 1 }", "unknown key \"extra\"");
    expectError("{ \"pairs\": [ 3 ] }", "pairs[0]: must be an object");
    expectError("{ \"pairs\": [ { \"a\": {} } ] }", "pairs[0]: missing required key \"b\"");
    expectError(R"({ "pairs": [ { "a": { "shape": { "sphere": { "radius": 1 } } }, "b": { "shape": { "sphere": { "radius": 1 } } }, "c": 1 } ] })",
                "pairs[0]: unknown key \"c\"");
    expectError(R"({ "pairs": [ { "a": { "shape": { "sphere": { "radius": 1 } } },
                                  "b": { "shape": { "box": { "half_extents": [1, 0, 1] } } } } ] })",
                "pairs[0].b.shape.box.half_extents[1]: must be > 0");
    expectError(R"({ "pairs": [ { "a": { "shape": { "sphere": { "radius": 1 } } }, "b": { "shape": { "sphere": { "radius": 1 } } } },
                                { "a": { "shape": { "sphere": { "radius": 1 } }, "orientation": [0, 0, 0, 2] },
                                  "b": { "shape": { "sphere": { "radius": 1 } } } } ] })",
                "pairs[1].a.orientation: must be a unit quaternion");
    expectError(R"({ "pairs": [ { "a": { "position": [0, 0, 0] }, "b": { "shape": { "sphere": { "radius": 1 } } } } ] })",
                "pairs[0].a: missing required key \"shape\"");
    expectError(R"({ "pairs": [ { "a": { "shape": { "sphere": { "radius": 1 } }, "shape": { "sphere": { "radius": 2 } } },
                                  "b": { "shape": { "sphere": { "radius": 1 } } } } ] })",
                "pairs[0].a: duplicate key \"shape\"");

    CollideArgs missing;
    missing.inputPath = "/nonexistent/pairs.json";
    std::ostringstream out, err;
    CHECK(runCollideCommand(missing, out, err) == 2);
    CHECK(err.str() == "error: /nonexistent/pairs.json: no such file\n");
}

TEST_CASE("collide is a stepwise subcommand", "[ch03][collide]") {
    const std::string input = writeTemp("cli.json", kPairs);
    const std::string output = test::tempPath("ch03_collide_cli.json").string();
    CLI::App app{"test"};
    int exitCode = -1;
    installCollideCommand(app, exitCode);
    std::vector<std::string> args = {"stepwise", "collide", "--input", input, "--output", output};
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    app.parse(static_cast<int>(argv.size()), argv.data());
    CHECK(exitCode == 0);
    std::ifstream file(output);
    CHECK(Json::parse(file).at("results").size() == 4);

    CLI::App withoutInput{"test"};
    installCollideCommand(withoutInput, exitCode);
    std::vector<std::string> bare = {"stepwise", "collide"};
    std::vector<char*> bareArgv;
    for (std::string& arg : bare) bareArgv.push_back(arg.data());
    CHECK_THROWS_AS(withoutInput.parse(static_cast<int>(bareArgv.size()), bareArgv.data()), CLI::RequiredError);
}
