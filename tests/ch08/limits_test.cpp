// Slider and cone-twist joints driven against their limits: the slider's travel within 1 mm, the
// cone's swing and the twist within 1 degree.
#include "08_joints/chapter.h"
#include "08_joints/joint_frame.h"
#include "joint_fixture.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

using namespace stepwise;

namespace {

using test::addPost;
using test::boxBody;
using test::jointBetween;

/// A 20 kg block on a vertical slider from the post, limits and motor as given.
World sliderWorld(int& body, std::optional<std::pair<Real, Real>> limits, std::optional<JointMotor> motor,
                  const Vec3& push = Vec3::Zero()) {
    World world;
    const int post = addPost(world);
    BodyDef block = boxBody("block", Vec3::Constant(Real(0.1)), 20);
    block.linearVelocity = push;
    body = addBody(world, block);
    JointDesc slider = jointBetween(JointType::Slider, post, body, Vec3::Zero(), Vec3::UnitY());
    slider.limits = limits;
    slider.motor = motor;
    world.joints.push_back(slider);
    return world;
}

}  // namespace

TEST_CASE("a slider keeps a falling load on its axis and stops it at its limit within 1 mm", "[ch08][limits]") {
    // A 20 kg block on a vertical slider, limits [-0.5, 0.5] m, released from 0 with a sideways
    // push: it falls half a metre onto the lower limit and rests there.
    int body = -1;
    World world = sliderWorld(body, std::pair<Real, Real>{Real(-0.5), Real(0.5)}, std::nullopt, Vec3(Real(0.5), 0, 0));
    Pipeline pipeline = makeChapter08Pipeline(world);
    Real lowest = 0, offAxis = 0, turned = 0;
    for (int frame = 0; frame < 180; ++frame) {
        pipeline.step(world);
        const Vec3 position = world.bodies[static_cast<std::size_t>(body)].transform.position;
        lowest = std::min(lowest, position.y());
        if (frame >= 5) offAxis = std::max(offAxis, Vec3(position.x(), 0, position.z()).norm());
        turned = std::max(turned, measureJointError(world, world.joints[0]).angle);
    }
    const Real rest = world.bodies[static_cast<std::size_t>(body)].transform.position.y();
    INFO("lowest " << lowest << " m, at rest " << rest << " m, off the axis " << offAxis << " m, turned " << turned << " rad");
    CHECK(lowest > Real(-0.501));
    CHECK(std::abs(rest + Real(0.5)) < Real(0.001));
    CHECK(offAxis < Real(0.001));
    CHECK(turned < 1 * kDegree);
}

TEST_CASE("a slider motor drives its load up at the set speed", "[ch08][limits]") {
    int body = -1;
    World world = sliderWorld(body, std::nullopt, JointMotor{Real(0.5), Real(1000)});
    Pipeline pipeline = makeChapter08Pipeline(world);
    for (int frame = 0; frame < 60; ++frame) pipeline.step(world);
    const Real speed = world.motionOf(body)->linearVelocity.y();
    INFO("speed " << speed << " m/s");
    CHECK(std::abs(speed - Real(0.5)) < Real(0.005));
}

TEST_CASE("cone-twist limits hold within 1 degree when driven against them", "[ch08][limits]") {
    // A 1 m, 5 kg rod hangs from a cone-twist joint (cone 30 degrees, twist +-20 degrees about the
    // rod) and is kicked: sideways at 8 rad/s into the cone, or about its length at 8 rad/s into
    // the twist limit. Then the cone is laid on its side so that gravity holds the rod against it.
    const Real cone = 30 * kDegree, twistLimit = 20 * kDegree;
    const auto run = [&](const Vec3& kick, const Vec3& down) {
        World world;
        world.settings.gravity = down * Real(9.81);
        const int post = addPost(world);
        BodyDef rod = boxBody("rod", Vec3(Real(0.05), Real(0.5), Real(0.05)), 5, Vec3(0, Real(-0.5), 0));
        rod.angularVelocity = kick;
        const int body = addBody(world, rod);
        JointDesc joint = jointBetween(JointType::ConeTwist, post, body, Vec3(0, Real(0.5), 0), -Vec3::UnitY());
        joint.coneAngle = cone;
        joint.twistLimits = std::pair<Real, Real>{-twistLimit, twistLimit};
        world.joints.push_back(joint);
        Pipeline pipeline = makeChapter08Pipeline(world);
        std::pair<Real, Real> largest{0, 0};  // swing, |twist|
        for (int frame = 0; frame < 180; ++frame) {
            pipeline.step(world);
            const JointFrame frameNow = jointFrame(world, world.joints[0]);
            largest.first = std::max(largest.first, swingAngle(frameNow));
            largest.second = std::max(largest.second, std::abs(twistAngle(frameNow.deviation, joint.axis)));
        }
        return largest;
    };
    const auto [swingKicked, twistOfSwing] = run(Vec3(8, 0, 0), -Vec3::UnitY());
    const auto [swingOfTwist, twistKicked] = run(Vec3(0, 8, 0), -Vec3::UnitY());
    const auto [swingLoaded, twistLoaded] = run(Vec3::Zero(), Vec3(1, 0, 0));
    INFO("kicked sideways: swing " << swingKicked / kDegree << " deg; kicked about the rod: twist " << twistKicked / kDegree
                                   << " deg; pulled sideways by gravity: swing " << swingLoaded / kDegree << " deg");
    CHECK(swingKicked < cone + 1 * kDegree);
    CHECK(swingKicked > cone - 1 * kDegree);  // it did reach the cone
    CHECK(twistKicked < twistLimit + 1 * kDegree);
    CHECK(twistKicked > twistLimit - 1 * kDegree);
    CHECK(swingLoaded < cone + 1 * kDegree);
    CHECK(swingLoaded > cone - 1 * kDegree);
    (void)twistOfSwing;
    (void)swingOfTwist;
    (void)twistLoaded;
}
