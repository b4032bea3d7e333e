// Rolling through chapter 12's fast solve: a ball skidding onto rolling ends at 5/7 of its speed,
// and a ball rolling down a slope speeds up at 5/7 g sin(theta), both closed forms (a solid
// sphere's moment of inertia 2/5 m r^2). Chapter 10's arms reach a round body's core, so the
// separation it tracks between substeps does not turn the ball's bottom point up.
#include "12_planner/chapter.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;

TEST_CASE("through chapter 12 a skidding ball ends rolling at 5/7 of its speed, at one substep a frame", "[ch12][rolling]") {
    World world = loadSceneFile("scenes/reference/slide-to-roll.json");
    const Real startSpeed = world.motions[0].linearVelocity.x();
    Pipeline pipeline = makeChapter12Pipeline(world, SpeedOptions{});
    for (int frame = 0; frame < 60; ++frame) pipeline.step(world);
    const Motion& ball = world.motions[0];
    CHECK(std::abs(ball.linearVelocity.x() - startSpeed * 5 / 7) < Real(1e-4));
    CHECK(std::abs(ball.linearVelocity.y()) < Real(1e-4));  // was 8 cm/s down with turned arms
    CHECK(world.step.iterationPlan.iterations == 1);         // rolling steadily: one substep
}

TEST_CASE("through chapter 12 a ball rolls down a 30 degree slope at 5/7 g sin(theta)", "[ch12][rolling]") {
    // A ramp turned 30 degrees about z; the ball starts on it, 1 m up the slope, at rest.
    World world = loadSceneFromString(R"({
      "format": "stepwise-scene", "version": 1, "name": "rolling-slope",
      "settings": {"sleeping": false},
      "bodies": [
        {"name": "ramp", "type": "static", "shape": {"box": {"half_extents": [4, 0.1, 3]}},
         "position": [0, 2, 0], "orientation": [0, 0, 0.258819, 0.965926], "friction": 0.5},
        {"name": "ball", "shape": {"sphere": {"radius": 0.2}}, "position": [0.716025, 2.7598075, 0],
         "mass": 1, "friction": 0.5}
      ]})");
    Pipeline pipeline = makeChapter12Pipeline(world, SpeedOptions{});
    for (int frame = 0; frame < 60; ++frame) pipeline.step(world);
    const Vec3 downSlope(Real(-0.866025), Real(-0.5), 0);
    const Motion& ball = world.motions[0];
    const Real expected = Real(5) / 7 * Real(9.81) * Real(0.5) * Real(1);  // after 1 s
    CHECK(std::abs(ball.linearVelocity.dot(downSlope) - expected) < Real(1e-3) * expected);
    CHECK(std::abs(ball.angularVelocity.z() * Real(0.2) - ball.linearVelocity.dot(downSlope)) < Real(1e-3) * expected);
    CHECK(world.step.iterationPlan.iterations == 2);  // friction drags it along: it accelerates
}
