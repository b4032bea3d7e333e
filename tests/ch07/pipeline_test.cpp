// Chapter 7's pipeline: planned from the scene, named in the run report, bit-identical to
// chapter 6's without a fast body, and bounded in the events it takes.
#include "07_ccd/chapter.h"
#include "07_ccd/scenes.h"
#include "07_ccd/shots.h"
#include "app/registry.h"
#include "app/runner.h"
#include "world/report.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace stepwise;

namespace {

bool hasStage(const Pipeline& pipeline, const std::string& name) {
    const std::vector<std::string> names = pipeline.enabledStageNames();
    return std::find(names.begin(), names.end(), name) != names.end();
}

std::string ccdNote(const Pipeline& pipeline) {
    const auto note = pipeline.planNotes().find(stage_group::kCcd);
    return note == pipeline.planNotes().end() ? "" : note->second;
}

/// The report without its timings and without chapter 7's "ccd" entry.
std::string reportWithoutCcd(const World& world, RunStats stats) {
    stats.planNotes.clear();
    stats.stepMs.assign(stats.stepMs.size(), 0);
    stats.stageMeanMs.clear();
    return reportToJson(world, stats, "test");
}

}  // namespace

TEST_CASE("the planner adds CCD for bullets and fast bodies, leaves it out otherwise and says why", "[ch07][pipeline]") {
    Shot slow;
    slow.speed = 1;  // 1.7 cm a step against a 6 cm sphere
    Pipeline quiet = makeChapter07Pipeline(buildShot(slow, CcdMode::Auto));
    CHECK_FALSE(hasStage(quiet, "ccd:toi"));
    CHECK(ccdNote(quiet).find("off: auto, no bullet and no body faster than 0.50 of its smallest extent per step") == 0);
    CHECK(ccdNote(quiet).find("\"shot\"") != std::string::npos);

    Shot fast;
    fast.speed = 100;
    const Pipeline planned = makeChapter07Pipeline(buildShot(fast, CcdMode::Auto));
    CHECK(hasStage(planned, "ccd:sweep_start"));
    CHECK(hasStage(planned, "ccd:toi"));
    CHECK(planned.enabledStageNames().front() == "ccd:sweep_start");
    CHECK(planned.enabledStageNames().back() == "ccd:toi");
    CHECK(ccdNote(planned).find("auto: \"shot\" travels") == 0);

    CHECK(ccdNote(makeChapter07Pipeline(buildShot(fast, CcdMode::Off))) == "off: settings.ccd is \"off\"");
    CHECK(hasStage(makeChapter07Pipeline(buildShot(slow, CcdMode::On)), "ccd:toi"));
    CHECK(ccdNote(makeChapter07Pipeline(buildHeadOnBullets())) == "auto: 2 bullet bodies");
    CHECK(chapterRegistry().makePipeline(buildHeadOnBullets()).enabledStageNames() ==
          makeChapter07Pipeline(buildHeadOnBullets()).enabledStageNames());
}

TEST_CASE("the run report says whether CCD ran, why, and how many impacts it resolved", "[ch07][pipeline]") {
    for (bool fast : {false, true}) {
        Shot shot;
        shot.speed = fast ? 300 : 1;
        World world = buildShot(shot, CcdMode::Auto);
        Pipeline pipeline = makeChapter07Pipeline(world);
        RunOptions options;
        options.frames = kShotSteps;
        const RunStats stats = runHeadless(world, pipeline, chapterRegistry(), options);
        const std::string report = reportToJson(world, stats, "test");
        INFO(report);
        CHECK(report.find(fast ? "\"ran\": true" : "\"ran\": false") != std::string::npos);
        CHECK(report.find(fast ? "\"toi_events\": 1" : "\"toi_events\": 0") != std::string::npos);
        CHECK(report.find("\"plan\": \"" + std::string(fast ? "auto" : "off: auto")) != std::string::npos);
    }
}

TEST_CASE("scenes without fast bodies: the same reports with and without chapter 7", "[ch07][pipeline]") {
    const Registry& registry = chapterRegistry();
    int compared = 0;
    for (const SceneEntry& scene : registry.scenes()) {
        if (scene.chapter > 6) continue;
        World world6 = scene.build();
        if (world6.bodies.size() > 60) continue;  // the big stress and pyramid scenes: the goldens cover them
        World world7 = world6;
        Pipeline pipeline6 = registry.makePipeline(world6, 6);
        Pipeline pipeline7 = makeChapter07Pipeline(world7, registry.makePipeline(world7, 6));
        INFO(scene.name << ": " << ccdNote(pipeline7));
        if (hasStage(pipeline7, "ccd:toi")) continue;
        REQUIRE(pipeline7.enabledStageNames() == pipeline6.enabledStageNames());
        RunOptions options;
        options.frames = 120;
        const RunStats stats6 = runHeadless(world6, pipeline6, registry, options);
        const RunStats stats7 = runHeadless(world7, pipeline7, registry, options);
        CHECK(reportWithoutCcd(world7, stats7) == reportWithoutCcd(world6, stats6));
        ++compared;
    }
    CHECK(compared >= 20);
}

TEST_CASE("a pathological scene hits the event bound, reports it, and still does not tunnel", "[ch07][pipeline]") {
    // A bullet bouncing (restitution 1) between two walls 7 cm apart at 400 m/s: a hundred
    // impacts a step if nothing bounded them.
    World world;
    world.settings.gravity = Vec3::Zero();
    for (Real x : {Real(-0.06), Real(0.06)}) {
        BodyDef wall;
        wall.type = BodyType::Static;
        wall.name = x < 0 ? "left" : "right";
        wall.shape = Shape::box(Vec3(kWallHalfThickness, 1, 1));
        wall.transform.position = Vec3(x, 0, 0);
        wall.material.restitution = 1;
        addBody(world, wall);
    }
    BodyDef ball;
    ball.name = "ball";
    ball.shape = Shape::sphere(Real(0.01));
    ball.bullet = true;
    ball.material.restitution = 1;
    ball.linearVelocity = Vec3(400, 0, 0);
    const int index = addBody(world, ball);
    Pipeline pipeline = makeChapter07Pipeline(world);
    for (int step = 0; step < 5; ++step) {
        pipeline.step(world);
        CHECK(world.step.ccd.toiEvents <= kMaxToiEventsPerStep);
        CHECK(std::abs(world.bodies[std::size_t(index)].transform.position.x()) < Real(0.035));
    }
    CHECK(world.step.ccd.stepsBoundHit > 0);
    RunStats stats;
    stats.planNotes = pipeline.planNotes();
    CHECK(reportToJson(world, stats, "test").find("bound on time-of-impact events was hit") != std::string::npos);
}
