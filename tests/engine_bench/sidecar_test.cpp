// Bad sidecars and bad reference folders get one clear error naming the file and the JSON path,
// never a crash; and the bench turns them into exit code 2.
#include "engine/engine_bench.h"
#include "engine/suite.h"
#include "app/bench_util.h"
#include "support/temp_path.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace stepwise;
using namespace stepwise::engine_bench;

namespace {

std::string errorOf(const std::string& text) {
    try {
        parseSidecar(text, "x.expect.json");
    } catch (const SidecarError& error) {
        return error.what();
    }
    return "(no error)";
}

const char* kGood = R"({ "format": "stepwise-expect", "version": 1, "group": "contact", "seconds": 1,
  "checks": [ { "metric": "final_speed", "body": "ball", "expected": 2, "tolerance": 0.1, "why": "5%" } ] })";

std::string withCheck(const std::string& check) {
    return R"({ "format": "stepwise-expect", "version": 1, "group": "contact", "seconds": 1, "checks": [ )" + check + " ] }";
}

/// A folder in the temporary directory holding the given files, removed when the test ends.
struct Folder {
    explicit Folder(const std::string& name) : path(test::tempPath(name)) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~Folder() { std::filesystem::remove_all(path); }
    void write(const std::string& file, const std::string& text) const { std::ofstream(path / file) << text; }
    std::filesystem::path path;
};

const char* kBallScene = R"({ "name": "ball", "bodies": [ { "name": "ball", "shape": { "sphere": { "radius": 0.1 } } } ] })";

}  // namespace

TEST_CASE("a good sidecar reads back", "[engine-bench]") {
    const Sidecar sidecar = parseSidecar(kGood, "x.expect.json");
    REQUIRE(sidecar.checks.size() == 1);
    CHECK(sidecar.checks[0].metric == "final_speed");
    CHECK(sidecar.checks[0].expected == 2);
    CHECK(sidecar.group == "contact");
}

TEST_CASE("bad sidecars: each error names the file and the JSON path", "[engine-bench]") {
    CHECK_THAT(errorOf("{ \"format\": "), Catch::Contains("x.expect.json: malformed JSON") && Catch::Contains("line 1"));
    CHECK_THAT(errorOf(withCheck(R"({ "metric": "speed", "tolerance": 1, "why": "w" })")),
               Catch::StartsWith("x.expect.json: checks[0].metric: unknown metric \"speed\" (known: ") &&
                   Catch::Contains("final_speed"));
    CHECK(errorOf(withCheck(R"({ "metric": "drift", "why": "w" })")) == "x.expect.json: checks[0]: missing \"tolerance\"");
    CHECK(errorOf(withCheck(R"({ "metric": "drift", "tolerance": 0, "why": "w" })")) ==
          "x.expect.json: checks[0].tolerance: must be > 0");
    CHECK(errorOf(withCheck(R"({ "metric": "drift", "tolerance": 1 })")) == "x.expect.json: checks[0]: missing \"why\"");
    CHECK(errorOf(withCheck(R"({ "metric": "drift", "tolerance": 1, "why": "w", "body": "b" })")) ==
          "x.expect.json: checks[0]: unknown key \"body\" (accepted: metric, tolerance, why)");
    CHECK(errorOf(withCheck(R"({ "metric": "final_speed", "tolerance": 1, "why": "w", "body": "b" })")) ==
          "x.expect.json: checks[0]: missing \"expected\"");
    CHECK(errorOf(withCheck(R"({ "metric": "max_coordinate", "tolerance": 1, "why": "w", "body": "b", "axis": 3, "limit": 0 })")) ==
          "x.expect.json: checks[0].axis: must be 0, 1 or 2");
    CHECK(errorOf(R"({ "format": "stepwise-expect", "version": 1, "group": "piles", "seconds": 1, "checks": [] })") ==
          "x.expect.json: group: must be one of closed-form, contact, joint, stack, pile (got \"piles\")");
    CHECK(errorOf("[1, 2]") == "x.expect.json: must be a JSON object");
    CHECK(errorOf(withCheck("")) == "x.expect.json: checks: must be a non-empty array");
}

TEST_CASE("bad reference folders: a missing sidecar, an orphan, a body the scene lacks, a bad scene", "[engine-bench]") {
    CHECK_THROWS_WITH(loadSidecar("/nonexistent/a.expect.json"), Catch::StartsWith("/nonexistent/a.expect.json: no such file"));
    CHECK_THROWS_WITH(loadReferenceScenes("/nonexistent-dir"), "/nonexistent-dir: no such directory of reference scenes");
    {
        Folder folder("engine_bench_missing_sidecar");
        folder.write("ball.json", kBallScene);
        CHECK_THROWS_WITH(loadReferenceScenes(folder.path.string()),
                          Catch::StartsWith((folder.path / "ball.expect.json").string() + ": no such file"));
    }
    {
        Folder folder("engine_bench_orphan");
        folder.write("ball.json", kBallScene);
        folder.write("ball.expect.json", kGood);
        folder.write("rock.expect.json", kGood);
        CHECK_THROWS_WITH(loadReferenceScenes(folder.path.string()),
                          (folder.path / "rock.expect.json").string() + ": no scene rock.json beside it");
    }
    {
        Folder folder("engine_bench_no_body");
        folder.write("ball.json", R"({ "bodies": [ { "name": "rock", "shape": { "sphere": { "radius": 0.1 } } } ] })");
        folder.write("ball.expect.json", kGood);
        CHECK_THROWS_WITH(loadReferenceScenes(folder.path.string()),
                          (folder.path / "ball.expect.json").string() + ": checks[0].body: \"ball\" is not a dynamic body of scene \"ball\"");
    }
    {
        Folder folder("engine_bench_bad_scene");
        folder.write("ball.json", R"({ "bodies": [ { "name": "ball", "shape": { "sphere": { "radius": -1 } } } ] })");
        folder.write("ball.expect.json", kGood);
        CHECK_THROWS_WITH(loadReferenceScenes(folder.path.string()),
                          (folder.path / "ball.json").string() + ": bodies[0].shape.sphere.radius: must be > 0");
    }
}

TEST_CASE("the bench answers a bad folder or peer with exit code 2 and the message", "[engine-bench]") {
    Folder folder("engine_bench_bad_run");
    folder.write("ball.json", kBallScene);
    folder.write("ball.expect.json", withCheck(R"({ "metric": "nonsense", "tolerance": 1, "why": "w" })"));
    const BenchEntry entry = engineBench();
    BenchOptions options;
    options.quick = options.quiet = true;
    std::ostringstream out;
    options.out = &out;
    options.scenesDir = folder.path.string();
    CHECK(runBench(entry, options) == 2);
    options.scenesDir.clear();
    options.peer = "havok";
    CHECK(runBench(entry, options) == 2);
}
