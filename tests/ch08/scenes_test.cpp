// Chapter 8's scenes: every one runs; the gallery shows what each joint allows; the platform
// carries its rider and the paddle throws its targets; the view draws what a joint allows and
// turns a joint red past 1 cm (the scene files: scene_files_test.cpp).
#include "08_joints/chapter.h"
#include "04_pgs/solver.h"
#include "08_joints/joint_frame.h"
#include "08_joints/joint_rows.h"
#include "08_joints/joint_solver.h"
#include "08_joints/joint_view.h"
#include "08_joints/kinematic.h"
#include "08_joints/scenes.h"
#include "app/registry.h"
#include "world/debug_draw.h"
#include "scene_fixture.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace stepwise;
using test::angleAbout;
using test::finiteState;
using test::jointTo;
using test::slide;
using test::stepFrames;

namespace {

bool sameColor(const Color& a, const Color& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

int countColored(const RecordingDraw& draw, const Color& color) {
    const auto& commands = draw.commands();
    return int(std::count_if(commands.begin(), commands.end(),
                             [&](const RecordingDraw::Command& command) { return sameColor(command.color, color); }));
}

}  // namespace

TEST_CASE("every chapter 8 scene builds, runs 120 frames with finite state and draws its joints", "[ch08][scenes]") {
    std::vector<std::string> names;
    for (const SceneEntry& entry : chapterRegistry().scenes()) {
        if (entry.chapter != 8) continue;
        names.push_back(entry.name);
        INFO(entry.name);
        CHECK(entry.category == "Joints");
        CHECK_FALSE(entry.observe.empty());
        World world = entry.build();
        CHECK(world.name == entry.name);
        Pipeline pipeline = makeChapter08Pipeline(world);
        stepFrames(world, pipeline, 120);
        CHECK(finiteState(world));
        REQUIRE(entry.makeView);
        RecordingDraw recorded;
        entry.makeView()->draw(world, recorded);
        // Two anchors per joint, two path ends per kinematic path.
        CHECK(recorded.count(RecordingDraw::Kind::Point) == int(2 * world.joints.size() + 2 * world.kinematicPaths.size()));
    }
    // The demo opens on the chapter's first scene, and the render test photographs it.
    REQUIRE_FALSE(names.empty());
    CHECK(names.front() == "joints-sandbox");
    for (const char* expected : {"joints-gallery", "joints-ragdoll-pile", "joints-platform", "joints-rotator"})
        CHECK(std::find(names.begin(), names.end(), expected) != names.end());
}

TEST_CASE("the sandbox's pieces hold: the stack stands, the chain and the ragdoll keep their joints", "[ch08][scenes]") {
    World world = buildJointsSandbox();
    Pipeline pipeline = makeChapter08Pipeline(world);
    const Vec3 topStart = world.bodies[std::size_t(world.findBody("stack4"))].transform.position;
    stepFrames(world, pipeline, 240);
    REQUIRE(finiteState(world));
    const Vec3 topEnd = world.bodies[std::size_t(world.findBody("stack4"))].transform.position;
    CHECK((topEnd - topStart).norm() < Real(0.05));
    Real worst = 0;
    for (const JointDesc& joint : world.joints) worst = std::max(worst, measureJointError(world, joint).position);
    CHECK(worst < kJointErrorShown);  // nothing drawn red after 4 s
    // The ragdoll fell from 2 m and lies on the ground.
    CHECK(world.bodies[std::size_t(world.findBody("ragdoll-pelvis"))].transform.position.y() < Real(0.6));
}

TEST_CASE("the joint gallery shows each joint's limits, motor and spring", "[ch08][scenes]") {
    World world = buildJointGallery();
    REQUIRE(world.joints.size() == 7);
    Pipeline pipeline = makeChapter08Pipeline(world);
    const JointDesc& slider = jointTo(world, "slider-block");
    Real slideLow = 0;
    for (int frame = 0; frame < 360; ++frame) {
        pipeline.step(world);
        slideLow = std::min(slideLow, slide(world, slider));
    }
    REQUIRE(finiteState(world));
    // The spring at rest stretches by g / omega^2 (k = m omega^2): 9.81 / (4 pi)^2 = 6.2 cm.
    const JointFrame spring = jointFrame(world, jointTo(world, "spring-ball"));
    const Real omega = 2 * kPi * 2;
    CHECK((spring.anchorB - spring.anchorA).norm() == Approx(1 + Real(9.81) / (omega * omega)).margin(0.002));
    CHECK(angleAbout(world, jointTo(world, "hinge-limits-bar")) == Approx(-45 * kDegree).margin(1 * kDegree));
    const JointDesc& motor = jointTo(world, "hinge-motor-blade");
    CHECK(world.motionOf(motor.bodyB)->angularVelocity.dot(jointFrame(world, motor).axisA) == Approx(2).margin(0.05));
    const JointDesc& cone = jointTo(world, "cone-twist-bar");
    CHECK(swingAngle(jointFrame(world, cone)) == Approx(30 * kDegree).margin(1 * kDegree));
    CHECK(std::abs(angleAbout(world, cone)) < 21 * kDegree);
    CHECK(slideLow == Approx(-0.5).margin(0.01));
    CHECK(slide(world, slider) == Approx(0.5).margin(0.01));
    const JointError weld = measureJointError(world, jointTo(world, "fixed-block"));
    CHECK(weld.position < Real(0.005));
    CHECK(weld.angle < 1 * kDegree);
}

TEST_CASE("the moving platform carries its box by friction, following its path", "[ch08][scenes]") {
    World world = buildPlatformScene();
    const int platform = world.findBody("platform"), rider = world.findBody("platform-rider");
    REQUIRE(world.kinematicPaths.size() == 1);
    const Real offset = world.bodies[std::size_t(rider)].transform.position.x() -
                        world.bodies[std::size_t(platform)].transform.position.x();
    Pipeline pipeline = makeChapter08Pipeline(world);
    Real slip = 0, travel = 0;
    for (int frame = 0; frame < 480; ++frame) {  // two periods
        pipeline.step(world);
        const Vec3 platformAt = world.bodies[std::size_t(platform)].transform.position;
        CHECK((platformAt - pathPosition(world.kinematicPaths[0], world.time)).norm() < Real(1e-3));
        const Real riderX = world.bodies[std::size_t(rider)].transform.position.x();
        slip = std::max(slip, std::abs(riderX - platformAt.x() - offset));
        travel = std::max(travel, std::abs(riderX - offset));
    }
    REQUIRE(finiteState(world));
    INFO("slip " << slip << " m, travel " << travel << " m");
    CHECK(travel > Real(1.9));   // the box went the whole way with the platform...
    CHECK(slip < Real(0.05));    // ...without sliding on it
    CHECK(world.bodies[std::size_t(rider)].transform.position.y() > Real(0.85));
}

TEST_CASE("the rotator turns at its set speed, unpushed, and throws its targets out", "[ch08][scenes]") {
    World world = buildRotatorScene();
    const int paddle = world.findBody("rotator");
    const Vec3 paddleAt = world.bodies[std::size_t(paddle)].transform.position;
    Pipeline pipeline = makeChapter08Pipeline(world);
    stepFrames(world, pipeline, 180);
    REQUIRE(finiteState(world));
    const Body& body = world.bodies[std::size_t(paddle)];
    CHECK((body.transform.position - paddleAt).norm() < Real(1e-4));
    // 3 s at 3 rad/s: 9 rad about +y, 9 - 2 pi = 2.72 rad into the second turn.
    const Vec3 length = body.transform.rotation * Vec3::UnitX();
    CHECK(std::atan2(-length.z(), length.x()) == Approx(9 - 2 * kPi).margin(0.01));
    int thrown = 0;
    for (int i = 0; i < 6; ++i) {
        const Vec3 at = world.bodies[std::size_t(world.findBody("rotator-target" + std::to_string(i)))].transform.position;
        thrown += Vec3(at.x(), 0, at.z()).norm() > Real(1.2) + Real(0.15);  // beyond the paddle's reach
    }
    CHECK(thrown >= 5);
}

TEST_CASE("the joint view draws what each joint allows and turns a joint red past 1 cm", "[ch08][scenes]") {
    World world = buildJointGallery();
    RecordingDraw draw;
    JointView(true).draw(world, draw);
    CHECK(countColored(draw, colors::kRed) == 0);  // every joint starts where it should be
    CHECK(draw.count(RecordingDraw::Kind::Text) == 7);
    CHECK(draw.count(RecordingDraw::Kind::Arrow) == 2);  // the two motors

    SECTION("a hinge's limit arc spans its limits, and its hand shows the angle it is at") {
        World one = buildJointGallery();
        const JointDesc& hinge = jointTo(one, "hinge-limits-bar");
        Body& bar = one.bodies[std::size_t(hinge.bodyB)];
        const Vec3 anchor = jointFrame(one, hinge).anchorA;
        // Turn the bar 30 degrees about the hinge's anchor: the hand sits 75 degrees past the
        // lower limit's radius (at -45) and 15 degrees short of the upper one (at +45).
        const Quat turn(Eigen::AngleAxis<Real>(30 * kDegree, jointFrame(one, hinge).axisA));
        bar.transform.position = anchor + turn * (bar.transform.position - anchor);
        bar.transform.rotation = turn * bar.transform.rotation;
        RecordingDraw lines;
        drawJoint(lines, one, hinge);
        std::vector<Vec3> radii;  // lines that leave the anchor: the two limit radii and the hand
        for (const auto& command : lines.commands())
            if (command.kind == RecordingDraw::Kind::Line && (command.a - anchor).norm() < Real(1e-5))
                radii.push_back((command.b - anchor).normalized());
        REQUIRE(radii.size() == 3);
        const auto degrees = [](const Vec3& a, const Vec3& b) { return std::acos(std::clamp(a.dot(b), Real(-1), Real(1))) / kDegree; };
        CHECK(degrees(radii[0], radii[1]) == Approx(90).margin(0.1));  // the arc: -45 to 45
        CHECK(degrees(radii[0], radii[2]) == Approx(75).margin(0.1));
        CHECK(degrees(radii[1], radii[2]) == Approx(15).margin(0.1));
    }
    SECTION("a cone-twist's cone opens at its cone angle about A's axis") {
        const JointDesc& cone = jointTo(world, "cone-twist-bar");
        const JointFrame frame = jointFrame(world, cone);
        RecordingDraw lines;
        drawJoint(lines, world, cone);
        int rays = 0;  // the cone's lines from its apex to its ring
        for (const auto& command : lines.commands()) {
            if (!sameColor(command.color, colors::kMagenta) || (command.a - frame.anchorA).norm() > Real(1e-5)) continue;
            const Real angle = std::acos(std::clamp((command.b - command.a).normalized().dot(frame.axisA), Real(-1), Real(1)));
            CHECK(angle == Approx(30 * kDegree).margin(1e-3));
            ++rays;
        }
        CHECK(rays == 8);
    }
    SECTION("a slider's travel ends in ticks at its limits") {
        const JointDesc& slider = jointTo(world, "slider-block");
        const JointFrame frame = jointFrame(world, slider);
        RecordingDraw lines;
        drawJoint(lines, world, slider);
        int ticks = 0;
        for (const auto& command : lines.commands()) {
            const Vec3 middle = (command.a + command.b) / 2;
            for (Real end : {Real(-0.5), Real(0.5)})
                ticks += (middle - (frame.anchorA + frame.axisA * end)).norm() < Real(1e-5) &&
                         std::abs((command.b - command.a).dot(frame.axisA)) < Real(1e-6);
        }
        CHECK(ticks == 2);
    }
    SECTION("a distance joint is coloured by its stretch, and red when a rigid one is off by more than 1 cm") {
        World two = buildJointGallery();
        JointDesc spring = jointTo(two, "spring-ball");
        const Body& ball = two.bodies[std::size_t(spring.bodyB)];
        const Vec3 anchor = jointFrame(two, spring).anchorA;
        spring.length = (ball.transform.position - anchor).norm() / Real(1.5);  // 50% stretched
        RecordingDraw stretched;
        drawJoint(stretched, two, spring);
        CHECK(countColored(stretched, colors::kOrange) == 1);
        CHECK(countColored(stretched, colors::kRed) == 0);  // a spring is meant to stretch
        spring.springHertz = 0;                               // now a rigid rod, 50% too long
        RecordingDraw off;
        drawJoint(off, two, spring);
        CHECK(countColored(off, colors::kRed) == 3);          // the line and both anchors
    }
    SECTION("a weld pulled 2 cm off is drawn red") {
        World three = buildJointGallery();
        const JointDesc& weld = jointTo(three, "fixed-block");
        three.bodies[std::size_t(weld.bodyB)].transform.position.y() -= Real(0.02);
        RecordingDraw off;
        drawJoint(off, three, weld);
        CHECK(countColored(off, colors::kRed) == 3);  // the weld's cube and both anchors
    }
}

TEST_CASE("every joint of the gallery fills the slots jointSlotCount gives its type", "[ch08][joints]") {
    // A later solve lays out room for a joint before building it (chapter 11's lanes): the count
    // must be the rules' own, whatever a row comes out as this step.
    const World world = buildJointGallery();
    const std::vector<SolverBody> bodies = gatherSolverBodies(world);
    const JointFeedback feedback = jointFeedback(world.settings, world.settings.dt);
    JointRows rows;
    for (std::size_t j = 0; j < world.joints.size(); ++j) {
        const std::size_t before = rows.joints.size();
        appendJointRows(rows, world, static_cast<int>(j), bodies, world.settings.dt, feedback, /*carryImpulses=*/false);
        REQUIRE(rows.joints.size() == before + 1);
        INFO("joint " << j << ", type " << static_cast<int>(world.joints[j].type));
        CHECK(rows.joints.back().rowCount == jointSlotCount(world.joints[j].type));
        CHECK(rows.joints.back().pointBlock == hasPointBlock(world.joints[j].type));
    }
}
