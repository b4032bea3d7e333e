// The pipeline runs its stages in order, times them, and lets a stage be switched off.
#include <catch2/catch.hpp>

#include "world/pipeline.h"

using namespace stepwise;

TEST_CASE("stages run in order, once per substep", "[common][pipeline]") {
    World world;
    world.settings.substeps = 3;
    std::vector<std::string> calls;
    Pipeline pipeline;
    pipeline.add({"integrate", [&](World&, Real dt) { calls.push_back("integrate " + std::to_string(dt)); }});
    pipeline.add({"solve:pgs", [&](World&, Real) { calls.push_back("solve"); }});
    pipeline.insertBefore("solve", {"narrowphase:gjk", [&](World&, Real) { calls.push_back("narrowphase"); }});
    pipeline.step(world);
    REQUIRE(calls.size() == 9);
    REQUIRE(calls[1] == "narrowphase");
    REQUIRE(calls[2] == "solve");
    REQUIRE(calls[0] == "integrate " + std::to_string(world.settings.dt / 3));
    REQUIRE(world.frame == 1);
    REQUIRE(world.time == Approx(world.settings.dt));
    REQUIRE(pipeline.enabledStageNames() == std::vector<std::string>{"integrate", "narrowphase:gjk", "solve:pgs"});
}

TEST_CASE("a disabled stage does not run and is not listed", "[common][pipeline]") {
    World world;
    int narrowphaseRuns = 0;
    Pipeline pipeline;
    pipeline.add({"integrate", [](World&, Real) {}});
    pipeline.add({"narrowphase:gjk", [&](World&, Real) { ++narrowphaseRuns; }});
    pipeline.find("narrowphase")->enabled = false;
    pipeline.step(world);
    REQUIRE(narrowphaseRuns == 0);
    REQUIRE(pipeline.enabledStageNames() == std::vector<std::string>{"integrate"});
    REQUIRE(pipeline.remove("narrowphase:gjk"));
    REQUIRE_FALSE(pipeline.find("narrowphase"));
    REQUIRE(stageGroup("broadphase:sap") == "broadphase");
}

TEST_CASE("static bodies own no motion state", "[common][world]") {
    World world;
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.shape = Shape::box(Vec3(10, 0.5f, 10));
    const int groundIndex = addBody(world, ground);
    BodyDef ball;
    ball.shape = Shape::sphere(0.5f);
    ball.mass = 2;
    const int ballIndex = addBody(world, ball);
    REQUIRE(world.motions.size() == 1);
    REQUIRE(world.motionOf(groundIndex) == nullptr);
    REQUIRE(world.motionOf(ballIndex)->mass == Approx(2));
    REQUIRE(world.bodies[ballIndex].name == "body1");

    BodyDef massless = ball;
    massless.mass = 0;
    REQUIRE_THROWS_AS(addBody(world, massless), std::invalid_argument);
}
