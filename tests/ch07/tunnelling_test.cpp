// What chapter 7 is for: fast small bodies do not cross a 5 cm wall, a spinning rod does not,
// and two bullets that meet head on keep their momentum.
#include "07_ccd/chapter.h"
#include "07_ccd/scenes.h"
#include "07_ccd/shots.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace stepwise;

namespace {

/// Shots at 50 to 500 m/s through chapter 7's pipeline with the given CCD setting: how many
/// ended a step with their centre past the wall.
int countTunnels(CcdMode ccd, int shots) {
    Random random(1407);
    int tunnels = 0;
    for (int i = 0; i < shots; ++i) {
        const Real speed = random.uniformReal(50, 500);
        World world = buildShot(randomShot(random, speed), ccd);
        Pipeline pipeline = makeChapter07Pipeline(world);
        bool crossed = false;
        for (int step = 0; step < kShotSteps; ++step) {
            pipeline.step(world);
            crossed = crossed || tunnelled(world);
        }
        tunnels += crossed ? 1 : 0;
    }
    return tunnels;
}

/// The largest x any corner of a box body reaches.
Real farthestX(const World& world, int body) {
    const Body& rod = world.bodies[std::size_t(body)];
    Real farthest = -kRealMax;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 local((corner & 1 ? 1 : -1) * rod.shape.halfExtents.x(), (corner & 2 ? 1 : -1) * rod.shape.halfExtents.y(),
                         (corner & 4 ? 1 : -1) * rod.shape.halfExtents.z());
        farthest = std::max(farthest, rod.transform.apply(local).x());
    }
    return farthest;
}

}  // namespace

TEST_CASE("1,000 shots of spheres, boxes and hulls at 50 to 500 m/s: none crosses a 5 cm wall with CCD", "[ch07][tunnel]") {
    CHECK(countTunnels(CcdMode::Auto, 1000) == 0);
}

TEST_CASE("the same shots with CCD off go through the wall: the problem the chapter solves", "[ch07][tunnel]") {
    const int tunnels = countTunnels(CcdMode::Off, 1000);
    INFO(tunnels << " of 1000 shots tunnelled with CCD off");
    CHECK(tunnels > 500);
}

TEST_CASE("a thin rod spinning at 100 rad/s and flying at 50 m/s never ends a step through the wall", "[ch07][tunnel]") {
    World world = buildSpinningRod();
    const int rod = world.findBody("rod");
    Pipeline pipeline = makeChapter07Pipeline(world);
    Real deepest = -kRealMax;   // farthest any corner got past the wall's near face
    for (int step = 0; step < 30; ++step) {
        pipeline.step(world);
        deepest = std::max(deepest, farthestX(world, rod) + kWallHalfThickness);
        INFO("step " << step << ": rod centre at x = " << world.bodies[std::size_t(rod)].transform.position.x());
        REQUIRE(world.bodies[std::size_t(rod)].transform.position.x() < -kWallHalfThickness);
    }
    INFO("deepest corner " << deepest << " m past the near face");
    CHECK(deepest < 2 * world.settings.slop);  // no corner deeper than the contact's allowance
    CHECK(world.step.ccd.totalToiEvents > 0);  // the loop, not only the speculative contacts, acted
}

TEST_CASE("a volley at the gun range: three bullets meet the wall in the same step and all three stop", "[ch07][tunnel]") {
    World world = buildGunRange();
    Pipeline pipeline = makeChapter07Pipeline(world);
    const int wall = world.findBody("wall");
    std::vector<int> atWall;  // the bullets fired at the wall (the wall lies at z < 0)
    for (std::size_t i = 0; i < world.bodies.size(); ++i)
        if (world.bodies[i].bullet && world.motionOf(int(i))->linearVelocity.z() < 0) atWall.push_back(int(i));
    REQUIRE(atWall.size() == 3);
    for (int step = 0; step < 30; ++step) {
        pipeline.step(world);
        for (int bullet : atWall) {
            // Through the wall: the centre past its far face, within its span (a bullet that slid
            // along the wall and off its end may go round it).
            const Vec3 local = world.bodies[std::size_t(wall)].transform.applyInverse(world.bodies[std::size_t(bullet)].transform.position);
            const Vec3 span = world.bodies[std::size_t(wall)].shape.halfExtents;
            const bool within = std::abs(local.y()) < span.y() && std::abs(local.z()) < span.z();
            INFO("step " << step << ", " << world.bodies[std::size_t(bullet)].name << " at " << local.transpose());
            CHECK_FALSE((within && local.x() > span.x()));
        }
    }
    CHECK(world.step.ccd.totalToiEvents >= 3);
}

TEST_CASE("two bullets head on at 300 m/s each collide and keep their momentum within 1e-4", "[ch07][tunnel]") {
    World world = buildHeadOnBullets();
    Pipeline pipeline = makeChapter07Pipeline(world);
    const int left = world.findBody("left"), right = world.findBody("right");
    const auto momentum = [&] {
        return world.motionOf(left)->mass * world.motionOf(left)->linearVelocity +
               world.motionOf(right)->mass * world.motionOf(right)->linearVelocity;
    };
    const Vec3 before = momentum();
    const Real scale = world.motionOf(right)->mass * 300;  // the larger body's momentum, N s
    bool passed = false;
    for (int step = 0; step < 10; ++step) {
        pipeline.step(world);
        passed = passed || world.bodies[std::size_t(left)].transform.position.x() > world.bodies[std::size_t(right)].transform.position.x();
        CHECK((momentum() - before).norm() <= Real(1e-4) * scale);
    }
    CHECK_FALSE(passed);
    CHECK(world.motionOf(left)->linearVelocity.x() < 0);   // the light one is thrown back
}
