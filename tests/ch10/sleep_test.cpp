// Islands and sleeping (chapter 10, sleep.h). The worlds step through chapter 8's pipeline plus the
// sleep stages. Chapter 8's solve does not skip sleepers (chapter 10's fast solve does), so the
// tests look at what the sleep stages decide (who sleeps, who wakes, and when), and at the
// functions themselves on hand-made states.
#include "08_joints/chapter.h"
#include "10_skip_work/chapter.h"
#include "10_skip_work/sleep.h"
#include "support/scene_rejection.h"
#include "world/report.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <string>

using namespace stepwise;

namespace {

int addBox(World& world, const std::string& name, const Vec3& position, Real half = Real(0.5)) {
    BodyDef def;
    def.name = name;
    def.shape = Shape::box(Vec3::Constant(half));
    def.transform.position = position;
    return addBody(world, def);
}

/// A static ground (top at y = 0) and a stack of `height` unit boxes at x, resting exactly.
World groundWorld() {
    World world;
    addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(20, Real(0.5), 20));
    return world;
}

std::vector<int> addStack(World& world, Real x, int height, const std::string& prefix) {
    std::vector<int> bodies;
    for (int level = 0; level < height; ++level)
        bodies.push_back(addBox(world, prefix + std::to_string(level), Vec3(x, Real(0.5) + Real(level), 0)));
    return bodies;
}

bool asleep(const World& world, int body) { return world.motionOf(body)->asleep; }

bool allAsleep(const World& world, const std::vector<int>& bodies) {
    for (int body : bodies)
        if (!asleep(world, body)) return false;
    return true;
}

bool noneAsleep(const World& world, const std::vector<int>& bodies) {
    for (int body : bodies)
        if (asleep(world, body)) return false;
    return true;
}

Pipeline sleepingPipeline(const World& world) {
    Pipeline pipeline = makeChapter08Pipeline(world);
    addSleepStages(pipeline, world);
    return pipeline;
}

/// A touching contact record between two bodies, for hand-made states.
Contact touching(int a, int b) {
    Contact contact;
    contact.bodyA = std::min(a, b);
    contact.bodyB = std::max(a, b);
    contact.pointCount = 1;
    return contact;
}

}  // namespace

TEST_CASE("sleep stages sit after the narrowphase and at the end, and say so", "[ch10][sleep]") {
    World world = groundWorld();
    addStack(world, 0, 1, "box");
    const Pipeline pipeline = sleepingPipeline(world);
    const std::vector<Stage>& stages = pipeline.stages();
    std::size_t narrowphase = stages.size(), wake = stages.size();
    for (std::size_t i = 0; i < stages.size(); ++i) {
        if (stageGroup(stages[i].name) == stage_group::kNarrowphase) narrowphase = i;
        if (stages[i].name == "sleep:wake") wake = i;
    }
    REQUIRE(narrowphase < stages.size());
    CHECK(wake == narrowphase + 1);
    CHECK(stages[wake].frequency == StageFrequency::FrameStart);
    CHECK(stages.back().name == "sleep:islands");
    CHECK(stages.back().frequency == StageFrequency::FrameEnd);
    REQUIRE(pipeline.planNotes().count(stage_group::kSleep) == 1);
    CHECK(pipeline.planNotes().at(stage_group::kSleep) == "on: islands below 0.05 m/s for 0.5 s sleep");
}

TEST_CASE("a box coming to rest on the ground sleeps time_to_sleep later, not before, with zero velocity", "[ch10][sleep]") {
    World world = groundWorld();
    const int box = addBox(world, "box", Vec3(0, Real(1.0), 0));  // dropped from 0.5 m: it lands, then settles
    Pipeline pipeline = sleepingPipeline(world);
    double sleptAt = -1, lastFast = 0;
    for (int frame = 0; frame < 180 && sleptAt < 0; ++frame) {
        pipeline.step(world);
        if (asleep(world, box)) sleptAt = world.time;
        else if (!isSlow(world, box)) lastFast = world.time;
    }
    INFO("last fast at t = " << lastFast << " s, asleep at t = " << sleptAt << " s");
    REQUIRE(sleptAt > 0);
    CHECK(lastFast > 0.25);  // it fell for 0.32 s: the fall kept it awake
    // Not before: slow for time_to_sleep since it last moved (to a frame's round-off) ...
    CHECK(sleptAt - lastFast >= double(world.settings.timeToSleep) - 1e-6);
    // ... and not much later: settling after the landing takes a few frames at most.
    CHECK(sleptAt <= 0.32 + double(world.settings.timeToSleep) + 0.25);
    const Motion& motion = *world.motionOf(box);
    CHECK(motion.linearVelocity == Vec3::Zero());   // exactly zero, not "small"
    CHECK(motion.angularVelocity == Vec3::Zero());
    CHECK(countSleeping(world) == 1);
    // Nothing disturbs it: it sleeps on, still exactly at rest at every frame's end.
    const Vec3 position = world.bodies[std::size_t(box)].transform.position;
    for (int frame = 0; frame < 120; ++frame) {
        pipeline.step(world);
        REQUIRE(asleep(world, box));
        REQUIRE(world.motionOf(box)->linearVelocity == Vec3::Zero());
    }
    CHECK((world.bodies[std::size_t(box)].transform.position - position).norm() < Real(1e-3));
}

TEST_CASE("with chapter 10's fast solve a sleeper does not move at all", "[ch10][sleep]") {
    World world = groundWorld();
    const std::vector<int> stack = addStack(world, 0, 2, "box");
    Pipeline pipeline = makeChapter10Pipeline(world);
    addSleepStages(pipeline, world);
    for (int frame = 0; frame < 60; ++frame) pipeline.step(world);
    REQUIRE(allAsleep(world, stack));
    const Transform before = world.bodies[std::size_t(stack[1])].transform;
    for (int frame = 0; frame < 60; ++frame) pipeline.step(world);
    CHECK(allAsleep(world, stack));
    // Bit for bit: the fast solve treats sleepers as static and integrates nothing of them.
    CHECK(world.bodies[std::size_t(stack[1])].transform.position == before.position);
    CHECK(world.bodies[std::size_t(stack[1])].transform.rotation.coeffs() == before.rotation.coeffs());
}

TEST_CASE("a box still sliding never sleeps", "[ch10][sleep]") {
    World world;
    Material ice;
    ice.friction = 0;
    addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(200, Real(0.5), 20), Quat::Identity(), ice);
    BodyDef def;
    def.name = "slider";
    def.shape = Shape::box(Vec3::Constant(Real(0.5)));
    def.transform.position = Vec3(0, Real(0.5), 0);
    def.linearVelocity = Vec3(2, 0, 0);
    def.material = ice;
    const int slider = addBody(world, def);
    Pipeline pipeline = sleepingPipeline(world);
    for (int frame = 0; frame < 180; ++frame) {
        pipeline.step(world);
        REQUIRE_FALSE(asleep(world, slider));
        REQUIRE(world.motionOf(slider)->sleepTime == 0);
    }
    CHECK(world.motionOf(slider)->linearVelocity.x() > Real(1.5));
}

TEST_CASE("two stacks are two islands: one sleeps while the other is kept awake", "[ch10][sleep]") {
    SECTION("hand-made state: the timers decide per island") {
        World world = groundWorld();
        const std::vector<int> left = addStack(world, -3, 2, "left"), right = addStack(world, 3, 2, "right");
        // Each stack touches the ground (shared) and its own boxes touch each other.
        world.contacts = {touching(0, left[0]), touching(0, right[0]), touching(left[0], left[1]),
                          touching(right[0], right[1])};
        for (Motion& motion : world.motions) motion.sleepTime = 1;
        world.motionOf(right[1])->sleepTime = Real(0.2);  // one restless body keeps its whole island awake
        world.motionOf(left[1])->linearVelocity = Vec3(0, Real(0.01), 0);  // slow leftovers are dropped
        SleepScratch scratch;
        CHECK(putIslandsToSleep(world, scratch) == 2);
        CHECK(allAsleep(world, left));
        CHECK(noneAsleep(world, right));
        CHECK(world.motionOf(left[1])->linearVelocity == Vec3::Zero());
    }
    SECTION("stepped: a stack on a moving platform stays awake, the one on the ground sleeps") {
        World world = groundWorld();
        const std::vector<int> still = addStack(world, -3, 2, "still");
        BodyDef platform;
        platform.name = "platform";
        platform.type = BodyType::Kinematic;
        platform.shape = Shape::box(Vec3(Real(1.5), Real(0.1), Real(1.5)));
        platform.transform.position = Vec3(4, Real(0.5), 0);
        // Slow at the turns (below the sleep speed for a few frames): the contact keeps it awake anyway.
        platform.path = KinematicPath{-1, Vec3::Zero(), Vec3(Real(0.5), 0, 0), 4, 0};
        addBody(world, platform);
        const std::vector<int> riding = {addBox(world, "ride0", Vec3(4, Real(0.85), 0), Real(0.25)),
                                         addBox(world, "ride1", Vec3(4, Real(1.35), 0), Real(0.25))};
        Pipeline pipeline = sleepingPipeline(world);
        bool ridersEverSlept = false;
        for (int frame = 0; frame < 240; ++frame) {
            pipeline.step(world);
            ridersEverSlept = ridersEverSlept || !noneAsleep(world, riding);
        }
        CHECK(allAsleep(world, still));
        CHECK_FALSE(ridersEverSlept);
        CHECK(countSleeping(world) == 2);
    }
}

TEST_CASE("a ball dropped on a sleeping stack wakes that stack whole, not the other", "[ch10][sleep]") {
    World world = groundWorld();
    const std::vector<int> hit = addStack(world, 0, 3, "hit"), other = addStack(world, 5, 3, "other");
    BodyDef ball;
    ball.name = "ball";
    ball.shape = Shape::sphere(Real(0.3));
    ball.transform.position = Vec3(0, 12, 0);  // about 1.3 s of fall: the stacks are asleep by then
    const int dropped = addBody(world, ball);
    Pipeline pipeline = sleepingPipeline(world);
    bool stacksSleptBeforeImpact = false;
    int wokenFrame = -1;
    for (int frame = 0; frame < 150 && wokenFrame < 0; ++frame) {
        const bool before = allAsleep(world, hit) && allAsleep(world, other);
        pipeline.step(world);
        stacksSleptBeforeImpact = stacksSleptBeforeImpact || before;
        if (before && !allAsleep(world, hit)) wokenFrame = frame;
    }
    REQUIRE(stacksSleptBeforeImpact);
    REQUIRE(wokenFrame >= 0);
    INFO("woken at frame " << wokenFrame << ", ball at y = " << world.bodies[std::size_t(dropped)].transform.position.y());
    CHECK(world.bodies[std::size_t(dropped)].transform.position.y() > Real(2.5));  // woken as it reached the top box
    CHECK(noneAsleep(world, hit));     // the whole island, the bottom box included
    CHECK(allAsleep(world, other));    // a separate island: untouched
    // Every timer restarted: the ball's contact may wake the stack a frame before it lands (a
    // speculative contact), and a box that has not moved yet then counts that one frame again.
    for (int body : hit) CHECK(world.motionOf(body)->sleepTime <= world.settings.dt);
}

TEST_CASE("waking: what wakes a sleeping island, and what does not", "[ch10][sleep]") {
    World world = groundWorld();
    const std::vector<int> stack = addStack(world, 0, 3, "s");
    const int visitor = addBox(world, "visitor", Vec3(0, Real(3.5), 0));
    const int loner = addBox(world, "loner", Vec3(8, Real(0.5), 0));
    world.contacts = {touching(0, stack[0]), touching(0, loner), touching(stack[0], stack[1]),
                      touching(stack[1], stack[2]), touching(stack[2], visitor)};
    const auto sleepAll = [&] {
        for (int body : stack) world.motionOf(body)->asleep = true;
        world.motionOf(loner)->asleep = true;
    };
    SleepScratch scratch;

    SECTION("a slow awake body resting on it does not wake it") {
        sleepAll();
        world.motionOf(visitor)->sleepTime = Real(0.1);
        CHECK(wakeTouchedIslands(world, scratch) == 0);
        CHECK(countSleeping(world) == 4);
    }
    SECTION("an awake body that moved this frame wakes the island it touches, whole") {
        sleepAll();
        world.motionOf(visitor)->sleepTime = 0;
        CHECK(wakeTouchedIslands(world, scratch) == 3);
        CHECK(noneAsleep(world, stack));
        CHECK(asleep(world, loner));  // joined to the stack only through the static ground
    }
    SECTION("a user's velocity or force on one sleeper wakes its island") {
        sleepAll();
        world.motionOf(visitor)->sleepTime = 1;
        world.motionOf(stack[0])->force = Vec3(1, 0, 0);
        CHECK(wakeTouchedIslands(world, scratch) == 3);
        CHECK(asleep(world, loner));
        world.motionOf(loner)->angularVelocity = Vec3(0, Real(1e-6), 0);
        CHECK(wakeTouchedIslands(world, scratch) == 1);
        CHECK(countSleeping(world) == 0);
    }
    SECTION("a joint to an awake body wakes it") {
        sleepAll();
        world.motionOf(visitor)->sleepTime = 1;
        JointDesc joint;
        joint.type = JointType::BallSocket;
        joint.bodyA = loner;
        joint.bodyB = visitor;
        world.joints.push_back(joint);
        CHECK(wakeTouchedIslands(world, scratch) == 1);
        CHECK_FALSE(asleep(world, loner));
        CHECK(allAsleep(world, stack));
    }
    SECTION("wakeBody wakes the body's sleeping island and restarts the timers") {
        sleepAll();
        world.motionOf(stack[2])->sleepTime = 2;
        wakeBody(world, stack[2]);
        CHECK(noneAsleep(world, stack));
        CHECK(world.motionOf(stack[2])->sleepTime == 0);
        CHECK(asleep(world, loner));
        wakeBody(world, 0);  // static: nothing to wake
        CHECK(asleep(world, loner));
    }
}

TEST_CASE("a moving kinematic body keeps what it touches awake", "[ch10][sleep]") {
    World world = groundWorld();
    BodyDef belt;
    belt.name = "belt";
    belt.type = BodyType::Kinematic;
    belt.shape = Shape::box(Vec3(2, Real(0.1), 2));
    belt.linearVelocity = Vec3(Real(0.01), 0, 0);  // slow: below the sleep speed
    const int kinematic = addBody(world, belt);
    const int box = addBox(world, "box", Vec3(0, Real(0.6), 0));
    world.contacts = {touching(kinematic, box)};
    world.motionOf(box)->sleepTime = 1;
    SleepScratch scratch;
    CHECK(updateSleepTimers(world, Real(0.1)) == 1);
    CHECK(world.motionOf(box)->sleepTime == Approx(1.1));  // a slow belt is as good as static
    world.motionOf(kinematic)->linearVelocity = Vec3(1, 0, 0);
    CHECK(updateSleepTimers(world, Real(0.1)) == 1);      // the box itself is slow ...
    CHECK(world.motionOf(box)->sleepTime == 0);           // ... but rides a moving belt
    world.motionOf(box)->sleepTime = 1;
    CHECK(putIslandsToSleep(world, scratch) == 0);
    // And a moving belt wakes a sleeper on it.
    world.motionOf(box)->asleep = true;
    CHECK(wakeTouchedIslands(world, scratch) == 1);
}

TEST_CASE("\"sleeping\": false never sleeps", "[ch10][sleep]") {
    World world = loadSceneFromString(R"({"settings": {"sleeping": false},
        "bodies": [{"name": "ground", "type": "static", "shape": {"box": {"half_extents": [20, 0.5, 20]}}, "position": [0, -0.5, 0]},
                   {"name": "box", "shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}}, "position": [0, 0.5, 0]}]})");
    Pipeline pipeline = sleepingPipeline(world);
    CHECK_FALSE(pipeline.find(stage_group::kSleep));
    CHECK(pipeline.planNotes().at(stage_group::kSleep) == "off: the scene turns sleeping off");
    for (int frame = 0; frame < 120; ++frame) pipeline.step(world);
    CHECK(countSleeping(world) == 0);
}

TEST_CASE("the run report counts the sleeping bodies", "[ch10][sleep]") {
    World world = groundWorld();
    addStack(world, -3, 2, "a");
    addStack(world, 3, 1, "b");
    RunStats stats;  // no sleep plan (a pipeline before chapter 10): no key
    CHECK(reportToJson(world, stats, "test").find("sleeping_bodies") == std::string::npos);
    Pipeline pipeline = sleepingPipeline(world);
    stats.planNotes = pipeline.planNotes();
    CHECK(reportToJson(world, stats, "test").find("\"sleeping_bodies\": 0,") != std::string::npos);
    for (int frame = 0; frame < 90; ++frame) pipeline.step(world);
    REQUIRE(countSleeping(world) == 3);
    const std::string report = reportToJson(world, stats, "test");
    CHECK(report.find("\"sleeping_bodies\": 3,") != std::string::npos);
    CHECK(report.find("\"sleeping_bodies\"") < report.find("\"energy\""));
}

TEST_CASE("sleep settings: checked with their JSON path, saved and read back", "[ch10][sleep]") {
    for (const char* key : {"sleep_speed", "time_to_sleep"}) {
        for (const char* value : {"0", "-1", "1e400", "\"fast\""}) {
            const SceneError error =
                test::rejectionOf(std::string(R"({"settings": {")") + key + "\": " + value + "}}");
            INFO(error.what());
            CHECK(error.path() == std::string("settings.") + key);
        }
    }
    CHECK(std::string(test::rejectionOf(R"({"settings": {"sleep_speed": 0}})").what()).find("must be > 0") !=
          std::string::npos);
    CHECK(test::rejectionOf(R"({"settings": {"sleeping": 1}})").path() == "settings.sleeping");
    // A misspelt key is named, with the near miss (the loader's rule for every object).
    CHECK(std::string(test::rejectionOf(R"({"settings": {"time_to_slep": 1}})").what()).find("time_to_sleep") !=
          std::string::npos);

    const World defaults = loadSceneFromString("{}");
    CHECK(defaults.settings.sleeping);
    CHECK(defaults.settings.sleepSpeed == Real(0.05));
    CHECK(defaults.settings.timeToSleep == Real(0.5));
    CHECK(chapterReading("sleeping") == 10);
    CHECK(chapterReading("sleep_speed") == 10);
    CHECK(chapterReading("time_to_sleep") == 10);

    World world = loadSceneFromString(R"({"settings": {"sleeping": false, "sleep_speed": 0.125, "time_to_sleep": 1.25}})");
    const World copy = loadSceneFromString(saveSceneToString(world));
    CHECK_FALSE(copy.settings.sleeping);
    CHECK(copy.settings.sleepSpeed == Real(0.125));
    CHECK(copy.settings.timeToSleep == Real(1.25));
}
