// Chapter 6's pipeline: its stages and what the settings switch.
#include "06_manifolds/chapter.h"
#include "06_manifolds/scenes.h"
#include "app/registry.h"
#include "support/fixture.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace stepwise;

namespace {

bool hasStage(const Pipeline& pipeline, const std::string& name) {
    const std::vector<std::string> names = pipeline.enabledStageNames();
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

TEST_CASE("chapter 6's pipeline: manifolds as the narrowphase, the stabilisation named, no drop rule", "[ch06][pipeline]") {
    World world = buildBoxStack(2);
    const Pipeline pipeline = makeChapter06Pipeline(world);
    CHECK(hasStage(pipeline, "narrowphase:manifold"));
    CHECK(hasStage(pipeline, "solve:relax"));
    CHECK(hasStage(pipeline, "broadphase:brute"));
    CHECK_FALSE(hasStage(pipeline, "contacts:drop_unloaded"));
    ManifoldOptions onePoint;
    onePoint.multiPoint = false;
    CHECK(hasStage(makeChapter06Pipeline(world, onePoint), "narrowphase:one_point"));
    for (Stabilisation stabilisation :
         {Stabilisation::Baumgarte, Stabilisation::Relax, Stabilisation::SplitImpulse, Stabilisation::SoftStep}) {
        world.settings.stabilisation = stabilisation;
        CHECK(hasStage(makeChapter06Pipeline(world), std::string("solve:") + toString(stabilisation)));
    }
    CHECK(chapterRegistry().makePipeline(buildBoxStack(2)).enabledStageNames() == pipeline.enabledStageNames());
}

TEST_CASE("manifolds keep a box flat on the ground, and one point per pair lets it rock", "[ch06][pipeline]") {
    double tilt[2] = {0, 0};
    for (int multi = 0; multi < 2; ++multi) {
        World world = buildBoxStack(3);
        ManifoldOptions options;
        options.multiPoint = multi == 1;
        Pipeline pipeline = makeChapter06Pipeline(world, options);
        test::simulate(world, pipeline, 3.0, [&](const World& w) {
            for (const Motion& motion : w.motions)
                tilt[multi] = std::max(tilt[multi], 1 - static_cast<double>(w.bodies[motion.bodyIndex].transform.rotate(Vec3::UnitY()).y()));
        });
        for (const Contact& contact : world.contacts) CHECK(contact.pointCount == (multi == 1 ? 4 : 1));
    }
    INFO("largest 1 - cos(tilt): one point " << tilt[0] << ", manifold " << tilt[1]);
    CHECK(tilt[1] < 1e-6);
    CHECK(tilt[0] > 100 * tilt[1]);
}

TEST_CASE("the stabilisation is read every step: switching it mid-run takes effect at once", "[ch06][pipeline]") {
    World world = buildBoxStack(4);
    Pipeline pipeline = makeChapter06Pipeline(world);
    test::simulate(world, pipeline, 1.0);
    for (Stabilisation stabilisation : {Stabilisation::Baumgarte, Stabilisation::SplitImpulse, Stabilisation::SoftStep}) {
        world.settings.stabilisation = stabilisation;
        test::simulate(world, pipeline, 1.0);
        for (const Motion& motion : world.motions) {
            CHECK(motion.linearVelocity.norm() < 0.05);
            CHECK(world.bodies[motion.bodyIndex].transform.position.y() > 0.4);
        }
    }
}

TEST_CASE("every chapter 6 scene stays finite and above the ground for 2 s", "[ch06][pipeline]") {
    for (const SceneEntry& entry : chapterRegistry().scenes()) {
        if (entry.chapter != 6) continue;
        INFO(entry.name);
        World world = entry.build();
        Pipeline pipeline = chapterRegistry().makePipeline(world);
        test::simulate(world, pipeline, 2.0);
        for (const Motion& motion : world.motions) {
            CHECK(motion.linearVelocity.allFinite());
            CHECK(world.bodies[motion.bodyIndex].transform.position.y() > -0.1);
        }
    }
}
