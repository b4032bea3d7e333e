// Rolling resistance (Material::rollingResistance, chapter 10's solve): a ball rolling on level
// ground slows at the closed form's rate and stops, a ball spinning in place stops, and without it
// both go on for ever, as a perfectly rigid ball on a perfectly rigid floor does.
#include "11_wide_solve/chapter.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace stepwise;

namespace {

/// A 0.2 m ball of 1 kg on the ground, rolling along x at `speed` (or spinning about y at `spin`).
World ballOnGround(Real resistance, Real speed, Real spin) {
    const std::string resistanceKey =
        resistance > 0 ? R"(, "rolling_resistance": )" + std::to_string(resistance) : std::string();
    return loadSceneFromString(R"({
      "format": "stepwise-scene", "version": 1, "name": "rolling-resistance",
      "bodies": [
        {"name": "ground", "type": "static", "shape": {"box": {"half_extents": [50, 0.5, 50]}}, "position": [0, -0.5, 0]},
        {"name": "ball", "shape": {"sphere": {"radius": 0.2}}, "position": [0, 0.2, 0], "mass": 1,
         "velocity": [)" + std::to_string(speed) + R"(, 0, 0], "angular_velocity": [0, )" + std::to_string(spin) + ", " +
                               std::to_string(-speed / Real(0.2)) + "]" + resistanceKey + R"(}
      ]})");
}

}  // namespace

TEST_CASE("rolling resistance slows a rolling ball at 5/7 c g and stops it", "[ch11][rolling]") {
    // The floor holds the ball's turn back by a torque c r N; rolling without slipping, the ball's
    // speed then falls at c r m g / (r (m + I / r^2)) = 5/7 c g for a solid sphere.
    const Real resistance = Real(0.05);
    World world = ballOnGround(resistance, 1, 0);
    Pipeline pipeline = makeChapter11Pipeline(world);
    for (int frame = 0; frame < 60; ++frame) pipeline.step(world);
    const Real expected = 1 - Real(5) / 7 * resistance * Real(9.81) * 1;  // after 1 s: 0.650 m/s
    const Motion& ball = *world.motionOf(1);
    INFO("speed after 1 s " << ball.linearVelocity.x() << " m/s, closed form " << expected);
    CHECK(std::abs(ball.linearVelocity.x() - expected) < Real(0.01));
    CHECK(std::abs(ball.angularVelocity.z() * Real(0.2) + ball.linearVelocity.x()) < Real(0.01));  // still rolling
    for (int frame = 0; frame < 180; ++frame) pipeline.step(world);
    CHECK(world.motionOf(1)->linearVelocity.norm() < Real(1e-3));
    CHECK(world.motionOf(1)->asleep);  // at rest, so it sleeps
    // Stopping distance v^2 / (2 a) = 1.43 m.
    CHECK(world.bodies[1].transform.position.x() == Approx(1 / (2 * Real(5) / 7 * resistance * Real(9.81))).epsilon(0.02));
}

TEST_CASE("rolling resistance stops a ball spinning in place; without it, it spins on", "[ch11][rolling]") {
    // One contact point has no spread for the twist row to grip: only rolling resistance stops it.
    World resisted = ballOnGround(Real(0.05), 0, 3);
    World free = ballOnGround(0, 0, 3);
    Pipeline resistedPipeline = makeChapter11Pipeline(resisted);
    Pipeline freePipeline = makeChapter11Pipeline(free);
    for (int frame = 0; frame < 120; ++frame) {
        resistedPipeline.step(resisted);
        freePipeline.step(free);
    }
    CHECK(resisted.motionOf(1)->angularVelocity.norm() < Real(1e-3));
    CHECK(free.motionOf(1)->angularVelocity.y() == Approx(3).epsilon(1e-3));
}

TEST_CASE("without rolling resistance a rolling ball keeps its speed", "[ch11][rolling]") {
    World world = ballOnGround(0, 1, 0);
    Pipeline pipeline = makeChapter11Pipeline(world);
    for (int frame = 0; frame < 120; ++frame) pipeline.step(world);
    CHECK(world.motionOf(1)->linearVelocity.x() == Approx(1).epsilon(1e-3));
}

TEST_CASE("rolling_resistance is read, written back and checked", "[ch11][rolling][scene]") {
    World world = ballOnGround(Real(0.25), 0, 0);
    CHECK(world.bodies[1].material.rollingResistance == Approx(0.25));
    CHECK(world.bodies[0].material.rollingResistance == 0);
    const World again = loadSceneFromString(saveSceneToString(world));
    CHECK(again.bodies[1].material.rollingResistance == Approx(0.25));
    try {
        ballOnGround(Real(1.5), 0, 0);
        FAIL("a rolling resistance of 1.5 was accepted");
    } catch (const std::exception& error) {
        CHECK(std::string(error.what()).find("rolling_resistance") != std::string::npos);
    }
}
