// Kinematic bodies: a moving platform carries a box by friction; a spinning paddle throws what it
// hits and is not slowed by it.
#include "08_joints/chapter.h"
#include "08_joints/kinematic.h"
#include "08_joints/scenes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace stepwise;

TEST_CASE("a box on a moving platform moves with it: slip under 2% of the travel", "[ch08][kinematic]") {
    World world;
    addGround(world);
    BodyDef platform;
    platform.name = "platform";
    platform.type = BodyType::Kinematic;
    platform.shape = Shape::box(Vec3(Real(1.5), Real(0.1), Real(1.5)));
    platform.transform.position = Vec3(0, Real(0.5), 0);
    platform.path = KinematicPath{-1, Vec3::Zero(), Vec3(Real(1.5), 0, 0), 4, 0};  // 3 m of travel, 3.7 m/s^2 at the ends
    const int carrier = addBody(world, platform);
    BodyDef box;
    box.name = "box";
    box.shape = Shape::box(Vec3::Constant(Real(0.25)));
    box.transform.position = Vec3(0, Real(0.85), 0);
    const int load = addBody(world, box);
    Pipeline pipeline = makeChapter08Pipeline(world);
    REQUIRE(pipeline.find(stage_group::kKinematic));
    for (int frame = 0; frame < 30; ++frame) pipeline.step(world);  // the box settles on it
    const auto offset = [&] {
        return world.bodies[static_cast<std::size_t>(load)].transform.position -
               world.bodies[static_cast<std::size_t>(carrier)].transform.position;
    };
    const Vec3 start = offset();
    Real slip = 0, pathError = 0;
    for (int frame = 0; frame < 480; ++frame) {
        pipeline.step(world);
        slip = std::max(slip, Vec3(offset() - start).norm());
        const Vec3 expected = pathPosition(world.kinematicPaths[0], world.time);
        pathError = std::max(pathError, Vec3(world.bodies[static_cast<std::size_t>(carrier)].transform.position - expected).norm());
    }
    INFO("slip " << slip << " m over 3 m of travel; platform off its path by " << pathError << " m");
    CHECK(slip < Real(0.02) * 3);
    CHECK(pathError < Real(1e-4));
    CHECK(offset().y() > Real(0.3));  // still on top
}

TEST_CASE("a spinning paddle throws a box and keeps its speed", "[ch08][kinematic]") {
    World world;
    addGround(world);
    BodyDef paddle;
    paddle.name = "paddle";
    paddle.type = BodyType::Kinematic;
    paddle.shape = Shape::box(Vec3(Real(1.5), Real(0.2), Real(0.1)));
    paddle.transform.position = Vec3(0, Real(0.3), 0);
    paddle.angularVelocity = Vec3(0, 3, 0);
    const int spinner = addBody(world, paddle);
    BodyDef box;
    box.name = "box";
    box.shape = Shape::box(Vec3::Constant(Real(0.2)));
    box.mass = 50;
    box.transform.position = Vec3(Real(1.0), Real(0.2), Real(0.6));
    const int thrown = addBody(world, box);
    Pipeline pipeline = makeChapter08Pipeline(world);
    Real fastest = 0;
    for (int frame = 0; frame < 120; ++frame) {
        pipeline.step(world);
        fastest = std::max(fastest, world.motionOf(thrown)->linearVelocity.norm());
    }
    INFO("box's top speed " << fastest << " m/s; paddle spin " << world.motionOf(spinner)->angularVelocity.transpose());
    CHECK(fastest > Real(2));  // the paddle's tip moves at 4.5 m/s
    CHECK(world.motionOf(spinner)->angularVelocity.isApprox(Vec3(0, 3, 0)));
    CHECK(world.bodies[static_cast<std::size_t>(spinner)].transform.position.isApprox(Vec3(0, Real(0.3), 0)));
}
