// Coulomb friction: a sliding ball starts rolling when and as fast as the closed form says; a box
// on a ramp slides exactly when the ramp is steeper than atan(mu).
#include "04_pgs/chapter.h"
#include "04_pgs/scenes.h"
#include "ch04_support.h"
#include "support/fixture.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;

TEST_CASE("a ball launched sliding reaches pure rolling at 5/7 of its speed after 2v/(7 mu g)", "[ch04][friction]") {
    const double mu = 0.3, speed = 4, gravity = 9.81;
    World world = test::makeWorld();
    // 8 substeps: the transition time is found to one step, and 2v/(7 mu g) is ~0.4 s, so 60 Hz
    // frames alone would resolve it only to 4 %.
    world.settings.substeps = 8;
    test::addGround(world);
    const Real radius = Real(0.5);
    const int ball = addBall(world, "ball", Vec3(0, radius - world.settings.slop, 0), radius, 2,
                             Material{static_cast<Real>(mu), 0});
    world.bodies[0].material.friction = static_cast<Real>(mu);
    // Diagonal, so the test also covers friction directions that are not the axes.
    const Vec3 direction = Vec3(3, 0, -4).normalized();
    test::setVelocity(world, ball, static_cast<Real>(speed) * direction);
    Pipeline pipeline = makeChapter04Pipeline(world);

    double rollingTime = -1, rollingSpeed = 0;
    test::simulate(world, pipeline, 1.5, [&](const World& w) {
        if (rollingTime >= 0) return;
        const Motion& motion = *w.motionOf(ball);
        // Velocity of the material point at the bottom: zero when it rolls.
        const Vec3 slip = motion.linearVelocity + motion.angularVelocity.cross(Vec3(0, -radius, 0));
        if (slip.norm() < 1e-3 * speed) {
            rollingTime = w.time;
            rollingSpeed = motion.linearVelocity.norm();
        }
    });
    const double expectedTime = 2 * speed / (7 * mu * gravity);
    INFO("rolling after " << rollingTime << " s at " << rollingSpeed << " m/s; closed form " << expectedTime << " s at "
                          << 5.0 / 7 * speed << " m/s");
    REQUIRE(rollingTime > 0);
    CHECK(test::relativeError(rollingTime, expectedTime) < 0.03);
    CHECK(test::relativeError(rollingSpeed, 5.0 / 7 * speed) < 0.03);
    // And it keeps rolling in the launch direction.
    CHECK(world.motionOf(ball)->linearVelocity.normalized().dot(direction) > 0.9999);
}

TEST_CASE("a box on a ramp slides when the ramp is steeper than atan(mu), and stays when gentler", "[ch04][friction]") {
    const Real mu = Real(0.5);
    const Real critical = std::atan(mu);
    const double seconds = 2;
    SECTION("steeper by 5 degrees: slides as (g sin - mu g cos) t^2 / 2") {
        const Real angle = critical + Real(5.0 * kPi / 180);
        int box = -1;
        World world = buildRampScene(angle, mu, &box);
        const Vec3 start = world.bodies[box].transform.position;
        Pipeline pipeline = makeChapter04Pipeline(world);
        test::simulate(world, pipeline, seconds);
        const Vec3 downhill = -(Quat(Eigen::AngleAxis<Real>(angle, Vec3::UnitZ())) * Vec3::UnitX());
        const double travelled = (world.bodies[box].transform.position - start).dot(downhill);
        const double expected = 0.5 * 9.81 * (std::sin(angle) - mu * std::cos(angle)) * seconds * seconds;
        INFO("slid " << travelled << " m, closed form " << expected << " m");
        CHECK(travelled > 0.8 * expected);
        CHECK(travelled < 1.1 * expected);
    }
    SECTION("gentler by 5 degrees: stays") {
        const Real angle = critical - Real(5.0 * kPi / 180);
        int box = -1;
        World world = buildRampScene(angle, mu, &box);
        const Vec3 start = world.bodies[box].transform.position;
        Pipeline pipeline = makeChapter04Pipeline(world);
        test::simulate(world, pipeline, seconds);
        const double moved = (world.bodies[box].transform.position - start).norm();
        INFO("moved " << moved << " m");
        CHECK(moved < 0.01);
    }
}
