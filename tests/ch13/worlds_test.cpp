// Chapter 13's promises, against closed forms: a cylinder stands on its face and rolls down a
// slope at (2/3) g sin(theta); a compound table has the mass properties of its parts and tips at
// the angle that puts its centre of mass over its legs' edge; a box slides over a floor of
// triangles, or a height field, without bumping at the seams; a ball rolls down a height-field
// ramp to the closed-form speed. And every earlier promise holds through chapter 13's pipeline.
#include "04_pgs/scenes.h"
#include "06_manifolds/scenes.h"
#include "13_worlds/chapter.h"
#include "13_worlds/scenes.h"
#include "promises/promises.h"
#include "world/state_hash.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;

namespace {

int worldsTestAdd(World& world, const std::string& name, const Shape& shape, const Vec3& position,
                  BodyType type = BodyType::Dynamic, const Quat& rotation = Quat::Identity(), Real friction = Real(0.6)) {
    BodyDef def;
    def.name = name;
    def.type = type;
    def.shape = shape;
    def.transform.position = position;
    def.transform.rotation = rotation;
    def.material.friction = friction;
    return addBody(world, def);
}

Real worldsTestTilt(const World& world, int body) {
    const Vec3 up = world.bodies[static_cast<std::size_t>(body)].transform.rotation * Vec3::UnitY();
    return std::acos(std::clamp(up.y(), Real(-1), Real(1)));
}

void worldsTestRun(World& world, Pipeline& pipeline, int frames) {
    for (int frame = 0; frame < frames; ++frame) pipeline.step(world);
}

}  // namespace

TEST_CASE("through chapter 13: the promises of chapters 1 to 4 hold", "[ch13][earlier]") {
    const int chapter = GENERATE(1, 2, 3, 4);
    test::checkPromisesOfChapter(
        chapter, {{"chapter 13", [](World& world, ContactSearch) { return makeChapter13Pipeline(world); }}});
}

TEST_CASE("a scene without chapter 13's shapes runs chapter 12's step bit for bit", "[ch13][earlier]") {
    World one = buildPyramid(6), two = one;  // chapter 6's pyramid of boxes
    Pipeline chapter12 = makeChapter12Pipeline(one), chapter13 = makeChapter13Pipeline(two);
    CHECK(chapter13.planNotes().at(stage_group::kWorldShapes).find("left out") == 0);
    for (int frame = 0; frame < 120; ++frame) {
        chapter12.step(one);
        chapter13.step(two);
        REQUIRE(stateHash(one) == stateHash(two));
    }
}

TEST_CASE("a cylinder stands on its face, on the rim's points, and does not rock", "[ch13][cylinder]") {
    World world = emptyWorld("standing-can");
    addGroundPlane(world);
    const int can = worldsTestAdd(world, "can", Shape::cylinder(Real(0.3), Real(0.4)), Vec3(0, Real(0.405), 0));
    Pipeline pipeline = makeChapter13Pipeline(world);
    worldsTestRun(world, pipeline, 120);
    CHECK(worldsTestTilt(world, can) < Real(0.002));
    CHECK(std::abs(world.bodies[static_cast<std::size_t>(can)].transform.position.y() - Real(0.4)) < Real(0.01));
    REQUIRE(world.contacts.size() == 1);
    CHECK(world.contacts[0].pointCount >= 3);  // a face, not a point
    CHECK(world.motionOf(can)->angularVelocity.norm() < Real(0.01));
}

// [ch13-rolling-test]
TEST_CASE("a solid cylinder rolls down a 20-degree slope at (2/3) g sin(theta)", "[ch13][cylinder]") {
    const Real slope = Real(20) * kPi / 180;
    const Quat tilt(Eigen::AngleAxis<Real>(-slope, Vec3::UnitZ()));  // downhill towards +x
    World world = emptyWorld("rolling-can");
    world.settings.sleeping = false;
    worldsTestAdd(world, "slope", Shape::box(Vec3(20, Real(0.5), 3)), Vec3::Zero(), BodyType::Static, tilt, 1);
    const Real radius = Real(0.3);
    const Vec3 start = tilt * Vec3(-15, Real(0.5) + radius + Real(0.001), 0);
    const int can = worldsTestAdd(world, "can", Shape::cylinder(radius, Real(0.5)), start, BodyType::Dynamic,
                                  tilt * Quat(Eigen::AngleAxis<Real>(kPi / 2, Vec3::UnitX())), 1);
    Pipeline pipeline = makeChapter13Pipeline(world);
    const Vec3 downhill = tilt * Vec3::UnitX();
    worldsTestRun(world, pipeline, 30);  // settled onto the slope
    const Real early = world.motionOf(can)->linearVelocity.dot(downhill);
    worldsTestRun(world, pipeline, 60);
    const Real late = world.motionOf(can)->linearVelocity.dot(downhill);
    const Real acceleration = (late - early) / Real(1);
    const Real expected = Real(2) / 3 * Real(9.81) * std::sin(slope);
    INFO("acceleration " << acceleration << " m/s^2, closed form " << expected);
    CHECK(std::abs(acceleration - expected) < Real(0.01) * expected);
}
// [ch13-rolling-test]

TEST_CASE("a compound table's mass properties are its parts' in closed form", "[ch13][compound]") {
    const Real width = Real(1.6), depth = Real(0.9), height = Real(0.75), thickness = Real(0.05), leg = Real(0.06);
    const Shape table = tableShape(width, depth, height, thickness, leg);
    const MassProperties props = computeMassProperties(table, 700);
    // By hand, in double: a box's inertia m/12 (b^2 + c^2), moved by m d^2.
    const double top = 700.0 * width * depth * thickness, legMass = 700.0 * leg * leg * (height - thickness);
    const double topY = height - thickness / 2.0, legY = (height - thickness) / 2.0;
    const double mass = top + 4 * legMass, centre = (top * topY + 4 * legMass * legY) / mass;
    const double legX = (width - leg) / 2.0, legZ = (depth - leg) / 2.0, legH = height - thickness;
    const double iyy = top / 12 * (width * width + depth * depth) + 4 * (legMass / 12 * (2 * leg * leg) +
                                                                         legMass * (legX * legX + legZ * legZ));
    const double ixx = top / 12 * (thickness * thickness + depth * depth) + top * (topY - centre) * (topY - centre) +
                       4 * (legMass / 12 * (legH * legH + leg * leg) + legMass * ((legY - centre) * (legY - centre) + legZ * legZ));
    CHECK(props.mass == Approx(mass).epsilon(1e-6));
    CHECK(props.localCenter.y() == Approx(centre).epsilon(1e-6));
    CHECK(props.inertia(1, 1) == Approx(iyy).epsilon(1e-5));
    CHECK(props.inertia(0, 0) == Approx(ixx).epsilon(1e-5));
    CHECK(std::abs(props.inertia(0, 1)) < 1e-6 * iyy);
}

TEST_CASE("a table on two legs tips over past the angle that puts its centre of mass over their edge, not before",
          "[ch13][compound]") {
    const Real width = Real(1.2), depth = Real(0.8), height = Real(0.75);
    const Shape table = tableShape(width, depth, height, Real(0.05), Real(0.06));
    const Real centre = computeMassProperties(table, 700).localCenter.y();
    const Real critical = std::atan2(width / 2, centre);  // its centre of mass over the pivot edge
    for (const Real offset : {Real(-0.05), Real(0.05)}) {
        World world = emptyWorld("tipping-table");
        world.settings.sleeping = false;
        addGroundPlane(world, 1);
        const Real angle = critical + offset;
        const Quat rotation(Eigen::AngleAxis<Real>(-angle, Vec3::UnitZ()));  // left legs lifted, pivot at x = +w/2
        const Vec3 pivot(width / 2, 0, 0);
        const int body = worldsTestAdd(world, "table", table, pivot - rotation * pivot + Vec3(0, Real(0.002), 0),
                                       BodyType::Dynamic, rotation, 1);
        Pipeline pipeline = makeChapter13Pipeline(world);
        worldsTestRun(world, pipeline, 180);
        INFO("released " << offset << " rad from the critical " << critical << " rad; tilt after 3 s "
                         << worldsTestTilt(world, body));
        if (offset < 0)
            CHECK(worldsTestTilt(world, body) < Real(0.02));  // back on four legs
        else
            CHECK(worldsTestTilt(world, body) > Real(1));     // over
    }
}

// [ch13-seam-test]
TEST_CASE("a box slides over a floor of triangles, or a height field, without bumping at the seams", "[ch13][mesh]") {
    const bool heightField = GENERATE(false, true);
    World world = emptyWorld(heightField ? "sliding-on-height-field" : "sliding-on-tiles");
    world.settings.sleeping = false;
    worldsTestAdd(world, "floor", heightField ? flatHeightField(30, 1) : tiledFloor(30, 1), Vec3::Zero(),
                  BodyType::Static, Quat::Identity(), 0);
    const int box = worldsTestAdd(world, "box", Shape::box(Vec3::Constant(Real(0.5))), Vec3(2, Real(0.5), Real(15.3)),
                                  BodyType::Dynamic, Quat::Identity(), 0);
    world.motions[static_cast<std::size_t>(world.bodies[static_cast<std::size_t>(box)].motionIndex)].linearVelocity = Vec3(5, 0, 0);
    Pipeline pipeline = makeChapter13Pipeline(world);
    Real slowest = 5, fastest = 5, bump = 0;
    for (int frame = 0; frame < 240; ++frame) {  // 4 s: 20 m over twenty seams
        pipeline.step(world);
        const Vec3 velocity = world.motionOf(box)->linearVelocity;
        slowest = std::min(slowest, velocity.x());
        fastest = std::max(fastest, velocity.x());
        bump = std::max(bump, std::abs(velocity.y()));
    }
    INFO("speed " << slowest << " to " << fastest << " m/s, vertical speed up to " << bump << " m/s");
    CHECK(slowest > Real(5 * 0.995));
    CHECK(fastest < Real(5 * 1.005));
    CHECK(bump < Real(0.01));
    CHECK(world.bodies[static_cast<std::size_t>(box)].transform.position.x() > Real(21.5));
}
// [ch13-seam-test]

TEST_CASE("a ball rolls down a height-field ramp to the closed-form speed", "[ch13][heightfield]") {
    // A 15-degree ramp as a height field: 40 cells of 0.5 m along x, falling towards +x.
    const Real slope = Real(15) * kPi / 180;
    const int columns = 41, rows = 5;
    std::vector<Real> heights;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) heights.push_back(Real(10) - Real(column) * Real(0.5) * std::tan(slope));
    World world = emptyWorld("ramp");
    world.settings.sleeping = false;
    worldsTestAdd(world, "ramp", Shape::heightFieldOf(rows, columns, Real(0.5), heights), Vec3::Zero(), BodyType::Static,
                  Quat::Identity(), 1);
    const Real radius = Real(0.25);
    const Vec3 normal(std::sin(slope), std::cos(slope), 0);
    const Vec3 start = Vec3(2, Real(10) - 2 * std::tan(slope), 1) + (radius + Real(0.001)) * normal;
    const int ball = worldsTestAdd(world, "ball", Shape::sphere(radius), start, BodyType::Dynamic, Quat::Identity(), 1);
    Pipeline pipeline = makeChapter13Pipeline(world);
    worldsTestRun(world, pipeline, 150);
    const Real drop = start.y() - world.bodies[static_cast<std::size_t>(ball)].transform.position.y();
    const Real speed = world.motionOf(ball)->linearVelocity.norm();
    const Real expected = std::sqrt(Real(10) / 7 * Real(9.81) * drop);  // mg h = (1/2) m v^2 + (1/2)(2/5) m r^2 (v/r)^2
    INFO("dropped " << drop << " m: " << speed << " m/s, closed form " << expected);
    CHECK(drop > 1);
    CHECK(std::abs(speed - expected) < Real(0.01) * expected);
}

TEST_CASE("a pile dropped on hills lands on them: no body passes through the ground", "[ch13][heightfield]") {
    World world = buildTerrainPile(40);
    Pipeline pipeline = makeChapter13Pipeline(world);
    const Real lowestGround = world.bodies[0].shape.heightField->lowest;
    Real lowest = kRealMax;
    for (int frame = 0; frame < 240; ++frame) {
        pipeline.step(world);
        for (const Body& body : world.bodies)
            if (body.type == BodyType::Dynamic) lowest = std::min(lowest, body.transform.position.y());
    }
    Real deepest = 0;
    for (const Contact& contact : world.contacts)
        for (int i = 0; i < contact.pointCount; ++i) deepest = std::max(deepest, contact.points[i].depth);
    INFO("lowest body centre " << lowest << " m over ground down to " << lowestGround << " m; deepest contact " << deepest << " m");
    CHECK(lowest > lowestGround);
    CHECK(deepest < Real(0.1));  // still settling at 4 s (a few cm); passing through is decimetres
}

TEST_CASE("worlds-seams: the active_edges setting is the seam's A/B, read every step", "[ch13][mesh]") {
    struct Outcome {
        Real bump = 0;       // the sliding boxes' largest vertical speed, m/s
        Real ballSpeed = 0;  // m/s after 150 frames
        Real expected = 0;   // the closed form for the ball's drop
    };
    const auto run = [](bool activeEdges, bool switchAtStart) {
        World world = buildSeamScene();
        world.settings.activeEdges = switchAtStart ? !activeEdges : activeEdges;
        Pipeline pipeline = makeChapter13Pipeline(world);
        world.settings.activeEdges = activeEdges;  // as the demo's checkbox: after the pipeline is made
        const int ball = world.findBody("ball-on-ramp");
        const Real startY = world.bodies[static_cast<std::size_t>(ball)].transform.position.y();
        Outcome outcome;
        for (int frame = 0; frame < 150; ++frame) {
            pipeline.step(world);
            for (const char* name : {"box-on-tiles", "box-on-height-field"})
                outcome.bump = std::max(outcome.bump, std::abs(world.motionOf(world.findBody(name))->linearVelocity.y()));
        }
        const Real drop = startY - world.bodies[static_cast<std::size_t>(ball)].transform.position.y();
        outcome.ballSpeed = world.motionOf(ball)->linearVelocity.norm();
        outcome.expected = std::sqrt(Real(10) / 7 * Real(9.81) * drop);
        return outcome;
    };
    const Outcome on = run(true, false), off = run(false, false), switchedOn = run(true, true), switchedOff = run(false, true);
    INFO("ball " << on.ballSpeed << " m/s (closed form " << on.expected << ") on, " << off.ballSpeed << " off; boxes' vertical speed up to "
                 << on.bump << " m/s");
    CHECK(on.bump < Real(0.01));
    CHECK(std::abs(on.ballSpeed - on.expected) < Real(0.01) * on.expected);
    CHECK(off.ballSpeed < Real(0.85) * off.expected);
    CHECK(switchedOn.ballSpeed == on.ballSpeed);  // the setting is read every step, not when the pipeline is made
    CHECK(switchedOff.ballSpeed == off.ballSpeed);
}
