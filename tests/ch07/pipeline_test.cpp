// Chapter 7's pipeline: planned from the scene, named in the run report, bit-identical to
// chapter 6's without a fast body, and bounded in the events it takes.
#include "07_ccd/chapter.h"
#include "07_ccd/scenes.h"
#include "07_ccd/shots.h"
#include "app/registry.h"
#include "app/runner.h"
#include "support/report_compare.h"
#include "support/registry_fixture.h"
#include "world/report.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

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

/// The report without its timings and without chapter 7's "ccd" entry (a plan note).
std::string reportWithoutCcd(const World& world, const RunStats& stats) {
    return test::reportWithoutTimingsAndNotes(world, stats);
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

    World alone = emptyWorld("alone", Vec3::Zero());  // as fast as the shot, and nothing to hit
    BodyDef shot;
    shot.name = "shot";
    shot.shape = Shape::sphere(Real(0.03));
    shot.linearVelocity = Vec3(100, 0, 0);
    addBody(alone, shot);
    CHECK_FALSE(hasStage(makeChapter07Pipeline(alone), "ccd:toi"));
    CHECK(ccdNote(makeChapter07Pipeline(alone)) == "off: auto, one body: nothing to collide with");

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
        shot.direction = Vec3(Real(0.94), Real(0.342), 0).normalized();  // 20 degrees off the normal
        World world = buildShot(shot, CcdMode::Auto);
        Pipeline pipeline = makeChapter07Pipeline(world);
        RunOptions options;
        options.frames = kShotSteps;
        const RunStats stats = runHeadless(world, pipeline, chapterRegistry(), options);
        const std::string report = reportToJson(world, stats, "test");
        INFO(report);
        CHECK(report.find(fast ? "\"ran\": true" : "\"ran\": false") != std::string::npos);
        CHECK(world.step.ccd.totalToiEvents == (fast ? 1 : 0));
        CHECK(report.find("\"toi_events\": " + std::to_string(world.step.ccd.totalToiEvents)) != std::string::npos);
        CHECK(report.find("\"plan\": \"" + std::string(fast ? "auto" : "off: auto")) != std::string::npos);
    }
}

TEST_CASE("scenes without fast bodies: the same reports with and without chapter 7", "[ch07][pipeline]") {
    const Registry& registry = chapterRegistry();
    const int compared = test::forEachSmallScene(6, [&](const SceneEntry&, World world6) {
        World world7 = world6;
        Pipeline pipeline6 = registry.makePipeline(world6, 6);
        Pipeline pipeline7 = makeChapter07Pipeline(world7, registry.makePipeline(world7, 6));
        INFO(ccdNote(pipeline7));
        if (hasStage(pipeline7, "ccd:toi")) return false;
        REQUIRE(pipeline7.enabledStageNames() == pipeline6.enabledStageNames());
        RunOptions options;
        options.frames = 120;
        const RunStats stats6 = runHeadless(world6, pipeline6, registry, options);
        const RunStats stats7 = runHeadless(world7, pipeline7, registry, options);
        CHECK(reportWithoutCcd(world7, stats7) == reportWithoutCcd(world6, stats6));
        return true;
    });
    CHECK(compared >= 15);
}

TEST_CASE("a pathological scene hits the event bound, reports it, and still does not tunnel", "[ch07][pipeline]") {
    // Eight bullets converging on one box from all round and above, all arriving in the same step: the box
    // may take kMaxToiEventsPerBody impacts, the others wait where they would have hit it.
    World world;
    world.settings.gravity = Vec3::Zero();
    BodyDef box;
    box.name = "box";
    box.shape = Shape::box(Vec3::Constant(Real(0.2)));
    const int target = addBody(world, box);
    for (int k = 0; k < 8; ++k) {
        const Real angle = Real(2) * kPi * Real(k) / 8;
        // Aimed at the box's centre from 25 degrees above: oblique to every face it meets.
        const Real tilt = Real(0.436);
        const Vec3 inward(-std::cos(angle) * std::cos(tilt), -std::sin(tilt), -std::sin(angle) * std::cos(tilt));
        BodyDef bullet;
        bullet.name = "bullet" + std::to_string(k);
        bullet.shape = Shape::sphere(Real(0.01));
        bullet.bullet = true;
        bullet.transform.position = -inward * Real(3);
        bullet.linearVelocity = inward * Real(300) * (1 + Real(k) / 100);  // a total order of arrivals
        addBody(world, bullet);
    }
    Pipeline pipeline = makeChapter07Pipeline(world);
    // The speculative contacts of chapters 3 and 6 would stop most of them first: switched off,
    // the TOI loop alone stands between the bullets and the box.
    pipeline.find(stage_group::kNarrowphase)->enabled = false;
    int mostEvents = 0;
    for (int step = 0; step < 3; ++step) {
        pipeline.step(world);
        mostEvents = std::max(mostEvents, world.step.ccd.toiEvents);
        for (int k = 1; k <= 8; ++k) {
            const Vec3 offset = world.bodies[std::size_t(k)].transform.position - world.bodies[std::size_t(target)].transform.position;
            CHECK(offset.norm() > Real(0.2));  // no bullet inside the box
        }
    }
    CHECK(mostEvents == kMaxToiEventsPerBody);
    CHECK(world.step.ccd.stepsBoundHit > 0);
    RunStats stats;
    stats.planNotes = pipeline.planNotes();
    CHECK(reportToJson(world, stats, "test").find("bound on time-of-impact events was hit") != std::string::npos);
}

TEST_CASE("a body stopped at its impact keeps its spin in its own axes and gains no energy", "[ch07][ccd]") {
    // Found by fuzz_stepper: a rod 0.8 m long (18 kg, restitution 0.78) spinning at 108 rad/s off
    // its axis beside a cylinder, a plate and two slivers, CCD on. A body stopped at its impact
    // waits at the pose it had then, turned back from where the step left it; its angular velocity
    // was kept in world axes, which on the turned-back pose spins it about other axes of its own
    // with another energy: 1,986 J to 2,175 J in ten frames, through chapter 7's stage alone.
    // Turned back with the pose, the spin keeps its energy, and the impact can only take energy.
    World world = loadSceneFile("tests/ch07/data/spinning-rod-bounces.json");
    Pipeline pipeline = makeChapter07Pipeline(world);
    const double start = computeEnergy(world).total();
    double most = start;
    int impacts = 0;
    for (int frame = 0; frame < 100; ++frame) {
        pipeline.step(world);
        impacts += world.step.ccd.toiEvents;
        most = std::max(most, computeEnergy(world).total());
    }
    INFO("energy " << start << " J, most in any frame " << most << " J, after 100 frames "
                   << computeEnergy(world).total() << " J, " << impacts << " impacts");
    CHECK(impacts > 0);
    CHECK(most <= start);
}
