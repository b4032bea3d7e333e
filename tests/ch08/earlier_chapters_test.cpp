// Every earlier promise through chapter 8's pipeline: the promises of chapters 1 to 4
// (tests/promises) directly, and every registered scene of chapters 1 to 7 (none has a joint or a
// kinematic path) giving the same run report as chapter 7's pipeline, bit for bit.
#include "08_joints/chapter.h"
#include "app/registry.h"
#include "app/runner.h"
#include "promises/promises.h"
#include "support/report_compare.h"
#include "support/registry_fixture.h"
#include "world/report.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

std::vector<test::PipelineVariant> throughChapter8() {
    return {{"chapter 8", [](World& world, ContactSearch search) {
                 return makeChapter08Pipeline(
                     world, JointOptions{},
                     makeChapter07Pipeline(world, makeChapter06Pipeline(world, ManifoldOptions{}, chooseStepOrder(world), search)));
             }}};
}


}  // namespace

TEST_CASE("through chapter 8: the promises of chapters 1 to 4 hold", "[ch08][earlier]") {
    const int chapter = GENERATE(1, 2, 3, 4);
    test::checkPromisesOfChapter(chapter, throughChapter8());
}

TEST_CASE("scenes of chapters 1 to 7: the same reports with and without chapter 8", "[ch08][earlier]") {
    const Registry& registry = chapterRegistry();
    const int compared = test::forEachSmallScene(7, [&](const SceneEntry&, World world7) {
        REQUIRE(world7.joints.empty());
        World world8 = world7;
        Pipeline pipeline7 = registry.makePipeline(world7, 7);
        Pipeline pipeline8 = makeChapter08Pipeline(world8, JointOptions{}, registry.makePipeline(world8, 7));
        REQUIRE(pipeline8.enabledStageNames() == pipeline7.enabledStageNames());
        CHECK(pipeline8.planNotes().at(stage_group::kJoints) == "off: the scene has no joints");
        RunOptions options;
        options.frames = 120;
        const RunStats stats7 = runHeadless(world7, pipeline7, registry, options);
        const RunStats stats8 = runHeadless(world8, pipeline8, registry, options);
        CHECK(test::reportWithoutTimingsAndNotes(world8, stats8) == test::reportWithoutTimingsAndNotes(world7, stats7));
        return true;
    });
    CHECK(compared >= 15);
}
