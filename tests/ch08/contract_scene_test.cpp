// The scene contract's own example, scenes/two-box-stack.json, through the whole engine: its
// distance joint (ignored before this chapter, with a warning) now holds the 65 kg ball 2.25 m from
// the 1 kg box, and the run report's max_penetration stays under twice the slop, as chapter 6's
// issue asks (docs/ch06_manifolds.md gave the numbers without the joint).
#include "08_joints/builders.h"
#include "08_joints/chapter.h"
#include "08_joints/joint_frame.h"
#include "app/registry.h"
#include "app/runner.h"
#include "world/report.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

using namespace stepwise;

TEST_CASE("the contract's two-box-stack: the joint holds and the deepest overlap stays under twice the slop",
          "[ch08][contract]") {
    World world = loadSceneFile("scenes/two-box-stack.json");
    REQUIRE(world.joints.size() == 1);
    const Registry& registry = chapterRegistry();
    Pipeline pipeline = registry.makePipeline(world);
    REQUIRE(pipeline.find(stage_group::kJoints));
    RunOptions options;
    options.frames = 600;
    const RunStats stats = runHeadless(world, pipeline, registry, options);
    const JointErrorSummary error = largestJointError(world, {0});
    INFO("max penetration " << stats.maxPenetration << " m; joint error " << error.position << " m");
    CHECK(stats.warnings.empty());
    CHECK(stats.maxPenetration < 2 * world.settings.slop);
    CHECK(error.position < Real(1e-3));
}
