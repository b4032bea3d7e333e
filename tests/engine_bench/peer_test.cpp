// Scenes the peer cannot play are listed as refused, with the peer's reason, never dropped.
// Only where the program has the Bullet peer (libbullet-dev found).
#include "engine/engine_bench.h"
#include "engine/runs.h"
#include "app/bench_util.h"
#include "world/scene.h"
#include "support/temp_path.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace stepwise;
using namespace stepwise::engine_bench;

namespace {
const char* kRodScene = R"({ "name": "rod", "bodies": [
  { "name": "post", "type": "static", "shape": { "box": { "half_extents": [0.1, 0.1, 0.1] } }, "position": [0, 2, 0] },
  { "name": "bob", "shape": { "sphere": { "radius": 0.1 } }, "position": [1, 2, 0] } ],
  "joints": [ { "type": "distance", "a": "post", "b": "bob" } ] })";
const char* kRodSidecar = R"({ "format": "stepwise-expect", "version": 1, "group": "joint", "seconds": 0.5,
  "checks": [ { "metric": "max_distance", "body": "bob", "point": [0, 0, 0], "to": [0, 2, 0], "expected": 1,
                "tolerance": 0.01, "why": "1% of the rod" } ] })";
}  // namespace

TEST_CASE("a scene the peer refuses is listed as refused with its reason", "[engine-bench]") {
    if (!havePeer()) {
        WARN("this program has no Bullet peer (libbullet-dev not found): nothing to refuse");
        return;
    }
    const RunResult refused = runPeer(loadSceneFromString(kRodScene, "rod.json"), 0.5, {});
    CHECK_THAT(refused.failure, Catch::StartsWith("refused: joints[0] (distance"));

    const std::filesystem::path folder = test::tempPath("engine_bench_refused");
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "rod.json") << kRodScene;
    std::ofstream(folder / "rod.expect.json") << kRodSidecar;
    BenchOptions options;
    options.quick = options.quiet = true;
    std::ostringstream out;
    options.out = &out;
    options.scenesDir = folder.string();
    options.peer = "bullet";
    options.csvPath = (folder / "runs.csv").string();
    REQUIRE(runBench(engineBench(), options) == 0);
    CHECK_THAT(out.str(), Catch::Contains("rod: Bullet refused: joints[0] (distance"));
    std::ifstream csv(options.csvPath);
    std::string text((std::istreambuf_iterator<char>(csv)), std::istreambuf_iterator<char>());
    CHECK_THAT(text, Catch::Contains("bullet default,bullet default") && Catch::Contains(",refused,no,"));
    std::filesystem::remove_all(folder);
}
