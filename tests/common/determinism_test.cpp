// One scene run twice gives byte-identical reports apart from timings: for every built-in
// scene of every chapter, through the latest chapter's pipeline.
#include <catch2/catch.hpp>

#include "support/registry_fixture.h"
#include "app/runner.h"
#include "world/report.h"

#include <nlohmann/json.hpp>

using namespace stepwise;

namespace {

std::string reportWithoutTimings(const Registry& registry, const SceneEntry& entry, long frames) {
    World world = loadSceneOrBuiltin(registry, entry.name);
    Pipeline pipeline = registry.makePipeline(world);
    RunOptions options;
    options.frames = frames;
    const RunStats stats = runHeadless(world, pipeline, registry, options);
    nlohmann::ordered_json report = nlohmann::ordered_json::parse(reportToJson(world, stats, engineVersion()));
    report.erase("timing_ms");
    return report.dump(2);
}

}  // namespace

TEST_CASE("every built-in scene runs deterministically", "[common][determinism]") {
    const Registry& registry = test::chapterRegistry();
    REQUIRE_FALSE(registry.scenes().empty());
    for (const SceneEntry& entry : registry.scenes()) {
        INFO("scene " << entry.name);
        const std::string first = reportWithoutTimings(registry, entry, 90);
        const std::string second = reportWithoutTimings(registry, entry, 90);
        REQUIRE(first == second);
        REQUIRE(first.find("null") == std::string::npos);  // no NaN or Inf made it into the report
    }
}
