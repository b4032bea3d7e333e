// Hinges: a pendulum's period against the closed form, its axis held, its limits held under load,
// and its motor's speed.
#include "08_joints/chapter.h"
#include "08_joints/joint_frame.h"
#include "joint_fixture.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace stepwise;

namespace {

using test::addPost;
using test::boxBody;
using test::jointBetween;

/// A 1 m rod (10 cm square) hanging from a hinge about z at the origin, turned by `angle`.
struct Pendulum {
    World world;
    int rod = -1;
    int joint = 0;
};

Pendulum makePendulum(Real angle, Real mass = 2) {
    Pendulum pendulum;
    World& world = pendulum.world;
    const int post = addPost(world);
    BodyDef rod = boxBody("rod", Vec3(Real(0.05), Real(0.5), Real(0.05)), mass);
    const Quat turn(Eigen::AngleAxis<Real>(angle, Vec3::UnitZ()));
    rod.transform.rotation = turn;
    rod.transform.position = turn * Vec3(0, Real(-0.5), 0);
    pendulum.rod = addBody(world, rod);
    world.joints.push_back(jointBetween(JointType::Hinge, post, pendulum.rod, Vec3(0, Real(0.5), 0), Vec3::UnitZ()));
    return pendulum;
}

Real hingeAngle(const World& world, int joint) {
    const JointDesc& desc = world.joints[static_cast<std::size_t>(joint)];
    return twistAngle(jointFrame(world, desc).deviation, desc.axis);
}

}  // namespace

TEST_CASE("a hinge pendulum swings with the closed-form period and keeps to its axis", "[ch08][hinge]") {
    const Real amplitude = Real(0.2);
    Pendulum pendulum = makePendulum(amplitude);
    World& world = pendulum.world;
    Pipeline pipeline = makeChapter08Pipeline(world);
    // Physical pendulum: T0 = 2 pi sqrt(I / (m g d)) about the pivot, with the amplitude's
    // correction 1 + a^2/16 + 11 a^4/3072.
    const Real mass = world.motionOf(pendulum.rod)->mass;
    const Real length = 1, width = Real(0.1), d = Real(0.5), g = Real(9.81);
    const Real inertia = mass * (length * length + width * width) / 12 + mass * d * d;
    const Real period = 2 * kPi * std::sqrt(inertia / (mass * g * d)) *
                        (1 + amplitude * amplitude / 16 + 11 * std::pow(amplitude, Real(4)) / 3072);
    std::vector<double> downCrossings;  // times the angle passes zero going negative
    Real previous = hingeAngle(world, 0), offAxis = 0;
    for (int frame = 0; frame < 600; ++frame) {
        pipeline.step(world);
        const Real angle = hingeAngle(world, 0);
        offAxis = std::max(offAxis, swingAngle(jointFrame(world, world.joints[0])));
        if (previous > 0 && angle <= 0)
            downCrossings.push_back(world.time - world.settings.dt * double(angle / (angle - previous)));
        previous = angle;
    }
    REQUIRE(downCrossings.size() >= 4);
    const double measured = (downCrossings.back() - downCrossings.front()) / double(downCrossings.size() - 1);
    INFO("period measured " << measured << " s, closed form " << period << " s; off-axis " << offAxis << " rad");
    CHECK(std::abs(measured - period) / period < 0.01);
    CHECK(offAxis < Real(1e-3));
}

TEST_CASE("a hinge holds its axis against a load that would tip the body off it", "[ch08][hinge]") {
    // The rod hangs 30 cm along the axle from its pivot, so gravity twists it about x all the
    // time, and it starts with a push about x as well: only the hinge's two angular rows keep
    // its axis on the post's.
    Pendulum pendulum = makePendulum(Real(0.5));
    World& world = pendulum.world;
    world.joints[0].localAnchorB = Vec3(0, Real(0.5), Real(-0.3));
    world.bodies[static_cast<std::size_t>(pendulum.rod)].transform.position += Vec3(0, 0, Real(0.3));
    world.motionOf(pendulum.rod)->angularVelocity = Vec3(Real(0.5), 0, 0);
    Pipeline pipeline = makeChapter08Pipeline(world);
    Real offAxis = 0, gap = 0;
    for (int frame = 0; frame < 300; ++frame) {
        pipeline.step(world);
        if (frame < 10) continue;  // the push is taken out in the first frames
        offAxis = std::max(offAxis, swingAngle(jointFrame(world, world.joints[0])));
        gap = std::max(gap, measureJointError(world, world.joints[0]).position);
    }
    INFO("off-axis " << offAxis << " rad, anchor gap " << gap << " m");
    CHECK(offAxis < Real(1e-3));
    CHECK(gap < Real(1e-3));
}

TEST_CASE("a hinge limit holds a loaded arm within 1 degree", "[ch08][hinge]") {
    // A 1 m arm along +x with 10 kg on its end, hinged at the post about z with limits [0, 90]
    // degrees: gravity turns it towards negative angles, the lower limit holds it level. It is
    // dropped onto the limit from 60 degrees.
    World world;
    const int post = addPost(world);
    BodyDef arm = boxBody("arm", Vec3(Real(0.5), Real(0.05), Real(0.05)), 10);
    const Quat start(Eigen::AngleAxis<Real>(60 * kDegree, Vec3::UnitZ()));
    arm.transform.rotation = start;
    arm.transform.position = start * Vec3(Real(0.5), 0, 0);
    const int body = addBody(world, arm);
    JointDesc hinge = jointBetween(JointType::Hinge, post, body, Vec3(Real(-0.5), 0, 0), Vec3::UnitZ());
    hinge.limits = std::pair<Real, Real>{0, 90 * kDegree};
    world.joints.push_back(hinge);
    Pipeline pipeline = makeChapter08Pipeline(world);
    Real lowest = kRealMax;
    for (int frame = 0; frame < 180; ++frame) {
        pipeline.step(world);
        lowest = std::min(lowest, hingeAngle(world, 0));
    }
    INFO("lowest angle " << lowest / kDegree << " degrees; at rest " << hingeAngle(world, 0) / kDegree);
    CHECK(lowest > -1 * kDegree);
    CHECK(std::abs(hingeAngle(world, 0)) < 1 * kDegree);
}

TEST_CASE("a hinge motor reaches its target speed within 1%", "[ch08][hinge]") {
    // A wheel on a vertical axle: gravity along the axle, no torque about it.
    World world;
    const int post = addPost(world);
    const int body = addBody(world, boxBody("wheel", Vec3(Real(0.4), Real(0.05), Real(0.4)), 5, Vec3(0, Real(-0.2), 0)));
    JointDesc hinge = jointBetween(JointType::Hinge, post, body, Vec3::Zero(), Vec3::UnitY());
    hinge.localAnchorA = Vec3(0, Real(-0.2), 0);
    hinge.motor = JointMotor{Real(2), Real(20)};
    world.joints.push_back(hinge);
    Pipeline pipeline = makeChapter08Pipeline(world);
    for (int frame = 0; frame < 120; ++frame) pipeline.step(world);
    const Real speed = world.motionOf(body)->angularVelocity.dot(Vec3::UnitY());
    INFO("wheel speed " << speed << " rad/s");
    CHECK(std::abs(speed - 2) < Real(0.02));
    // A weak motor turning the other way cannot reverse it in a second: its 0.05 N m slows the
    // wheel (I = m (0.8^2 + 0.8^2) / 12 = 0.533 kg m^2) by 0.094 rad/s each second, no more.
    world.joints[0].motor = JointMotor{Real(-2), Real(0.05)};
    for (int frame = 0; frame < 60; ++frame) pipeline.step(world);
    const Real slowed = world.motionOf(body)->angularVelocity.dot(Vec3::UnitY());
    const Real expected = 2 - Real(0.05) / (5 * Real(1.28) / 12);
    INFO("after 1 s of a weak reverse motor " << slowed << " rad/s, expected " << expected);
    CHECK(std::abs(slowed - expected) < Real(0.005));
}
