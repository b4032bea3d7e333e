// Chapter 11's solve takes every scene: joints (chapter 8's rows, in the same substeps as the
// contacts), springs and drag (chapter 1's forces every substep) and kinematic bodies (infinitely
// heavy, moving). The wide and the scalar path still give the same bits; the joints' stiffness is
// the setting's, up to a quarter of the substep rate.
#include "08_joints/builders.h"
#include "08_joints/chapter.h"
#include "08_joints/scenes.h"
#include "11_wide_solve/chapter.h"
#include "11_wide_solve/joint_pass.h"
#include "11_wide_solve/scenes.h"
#include "world/scene.h"
#include "world/state_hash.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace stepwise;

namespace {

Pipeline jointPipelineFor(const World& world, SolverPath path = SolverPath::Wide) {
    WideSolveOptions wide;
    wide.solverPath = path;
    return makeChapter11Pipeline(world, SkipWorkOptions{}, wide);
}

std::vector<int> allJointsOf(const World& world) {
    std::vector<int> joints(world.joints.size());
    std::iota(joints.begin(), joints.end(), 0);
    return joints;
}

/// A 1 kg ball hanging at rest at the origin from a static pivot 1 m above it on one joint.
World hangingBall(JointType type) {
    World world = emptyWorld("hanging-ball");
    BodyDef pivot;
    pivot.name = "pivot";
    pivot.type = BodyType::Static;
    pivot.shape = Shape::sphere(Real(0.05));
    pivot.transform.position = Vec3(0, 1, 0);
    const int a = addBody(world, pivot);
    BodyDef ball;
    ball.name = "ball";
    ball.shape = Shape::sphere(Real(0.1));
    ball.mass = 1;
    ball.transform.position = Vec3::Zero();  // at y = 0, where a float resolves a micrometre's sag
    const int b = addBody(world, ball);
    JointDesc joint;
    joint.type = type;
    joint.bodyA = a;
    joint.bodyB = b;
    joint.localAnchorA = Vec3(0, -1, 0);
    joint.localAnchorB = Vec3::Zero();
    world.joints.push_back(joint);
    world.settings.sleeping = false;
    return world;
}

}  // namespace

TEST_CASE("the fast solve takes joints, springs, drag and kinematic bodies", "[ch11][joints]") {
    for (World world : {buildJointsSandbox(), buildJointGallery(), buildPlatformScene(), loadSceneFile("scenes/spring-pair.json")}) {
        INFO(world.name);
        std::string why;
        CHECK(fastSolveApplies(world, &why));
        const Pipeline pipeline = jointPipelineFor(world);
        CHECK(pipeline.find(stage_group::kSolve)->name == "solve:wide_relax");
        const std::string note = pipeline.planNotes().at(stage_group::kSolve);
        if (!world.joints.empty()) CHECK(note.find("joint(s) one at a time in the same substeps") != std::string::npos);
        if (!world.springs.empty()) CHECK(note.find("springs and drag as forces every substep") != std::string::npos);
    }
}

TEST_CASE("with joints, springs and kinematic bodies the wide and the scalar path give the same bits", "[ch11][joints]") {
    const std::vector<World> scenes = {buildJointsSandbox(), buildJointGallery(), buildRagdollPile(4),
                                       loadSceneFile("scenes/spring-pair.json"), buildRotatorScene()};
    for (const World& start : scenes) {
        World wide = start, scalar = start;
        Pipeline widePipeline = jointPipelineFor(wide, SolverPath::Wide);
        Pipeline scalarPipeline = jointPipelineFor(scalar, SolverPath::Scalar);
        for (int frame = 0; frame < 120; ++frame) {
            widePipeline.step(wide);
            scalarPipeline.step(scalar);
            INFO(start.name << ", frame " << frame);
            REQUIRE(stateHash(wide) == stateHash(scalar));
        }
    }
}

TEST_CASE("ten ragdolls in a pile come to rest on the fast solve, every joint within a centimetre", "[ch11][joints]") {
    World world = buildRagdollPile(10);
    world.settings.sleeping = false;  // at rest by the solve, not by being put to sleep
    const std::vector<int> joints = allJointsOf(world);
    Pipeline pipeline = jointPipelineFor(world);
    const double initial = computeEnergy(world).total();
    double highest = initial;
    JointErrorSummary settled;
    for (int frame = 0; frame < 480; ++frame) {
        pipeline.step(world);
        highest = std::max(highest, computeEnergy(world).total());
        if (frame < 420) continue;
        const JointErrorSummary error = largestJointError(world, joints);
        settled.position = std::max(settled.position, error.position);
        settled.angle = std::max(settled.angle, error.angle);
    }
    Real fastest = 0;
    for (const Motion& motion : world.motions) fastest = std::max(fastest, motion.linearVelocity.norm());
    INFO("energy: start " << initial << " J, highest " << highest << " J; fastest " << fastest << " m/s; joint error "
                          << settled.position * 1000 << " mm, " << settled.angle * 180 / kPi << " deg");
    CHECK(highest <= initial + 1e-3 * std::abs(initial));  // the joints make no energy
    CHECK(fastest < Real(0.05));
    CHECK(settled.position < Real(0.01));
}

// [ch11-joint-sag-test]
// A joint's soft row at rest is a spring: the ball sags by F / (m_eff w^2) = g / w^2 (m_eff = 1 kg
// against a static pivot), with w the setting's frequency, or a quarter of the substep rate when
// the setting asks for more.
TEST_CASE("joint_hertz sets a joint's stiffness, up to a quarter of the substep rate", "[ch11][joints]") {
    const auto sagAt = [](Real hertz, int substeps) {
        World world = hangingBall(JointType::BallSocket);
        world.settings.jointHertz = hertz;
        world.settings.solverIterations = substeps;
        Pipeline pipeline = jointPipelineFor(world);
        for (int frame = 0; frame < 240; ++frame) pipeline.step(world);
        return -world.bodies[1].transform.position.y();
    };
    const auto expected = [](Real hertz) { return Real(9.81) / std::pow(2 * kPi * hertz, Real(2)); };
    CHECK(sagAt(50, 10) == Approx(expected(50)).epsilon(0.02));    // 0.099 mm
    CHECK(sagAt(1000, 10) == Approx(expected(150)).epsilon(0.02)); // capped: 600 Hz substeps, 150 Hz
    CHECK(sagAt(1000, 20) == Approx(expected(300)).epsilon(0.02)); // 1,200 Hz substeps: 300 Hz
    CHECK(fastJointFeedback(Settings{}, Real(1) / 1200).soft.biasRate > 0);
}
// [ch11-joint-sag-test]

TEST_CASE("springs and drag act every substep: the period and the decay of closed form", "[ch11][joints]") {
    // A 2 kg ball on a 200 N/m spring to a world point (zero rest length), no gravity: period
    // 2 pi sqrt(m / k) = 0.628 s.
    World world = emptyWorld("spring", Vec3::Zero());
    BodyDef ball;
    ball.name = "ball";
    ball.shape = Shape::sphere(Real(0.1));
    ball.mass = 2;
    ball.transform.position = Vec3(Real(0.5), 0, 0);
    addBody(world, ball);
    Spring spring;
    spring.bodyA = 0;
    spring.anchorB = Vec3::Zero();
    spring.stiffness = 200;
    world.springs.push_back(spring);
    world.settings.sleeping = false;
    Pipeline pipeline = jointPipelineFor(world);
    REQUIRE(fastSolveApplies(world));
    // Time of the first crossing of x = 0 going back up: three quarters of a period.
    Real previous = world.bodies[0].transform.position.x();
    Real crossing = 0;
    for (int frame = 1; frame < 120 && crossing == 0; ++frame) {
        pipeline.step(world);
        const Real x = world.bodies[0].transform.position.x();
        if (previous < 0 && x >= 0) crossing = (Real(frame - 1) + previous / (previous - x)) * world.settings.dt;
        previous = x;
    }
    CHECK(crossing == Approx(Real(0.75) * 2 * kPi * std::sqrt(Real(2) / 200)).epsilon(0.01));

    // Drag of 2 /s on a ball flying at 10 m/s without gravity: v = 10 exp(-2 t).
    World drag = emptyWorld("drag", Vec3::Zero());
    ball.mass = 1;
    ball.transform.position = Vec3::Zero();
    ball.linearVelocity = Vec3(10, 0, 0);
    addBody(drag, ball);
    drag.dampings.push_back(Damping{-1, 2, 0});
    drag.settings.sleeping = false;
    Pipeline dragPipeline = jointPipelineFor(drag);
    for (int frame = 0; frame < 60; ++frame) dragPipeline.step(drag);
    CHECK(drag.motions[0].linearVelocity.x() == Approx(10 * std::exp(Real(-2))).epsilon(0.01));
}

TEST_CASE("a kinematic platform carries its box on the fast solve, and no contact moves it", "[ch11][joints]") {
    World world = buildPlatformScene();
    World alone = world;  // the same platform stepped by chapter 8's solve: where its path takes it
    Pipeline pipeline = jointPipelineFor(world);
    Pipeline reference = makeChapter08Pipeline(alone);
    int platform = -1, rider = -1;
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        if (world.bodies[i].type == BodyType::Kinematic) platform = static_cast<int>(i);
        if (world.bodies[i].name == "platform-rider") rider = static_cast<int>(i);
    }
    REQUIRE(platform >= 0);
    REQUIRE(rider >= 0);
    const auto offset = [&] {
        return world.bodies[static_cast<std::size_t>(rider)].transform.position -
               world.bodies[static_cast<std::size_t>(platform)].transform.position;
    };
    for (int frame = 0; frame < 30; ++frame) {
        pipeline.step(world);
        reference.step(alone);
    }
    const Vec3 start = offset();
    Real slip = 0, pathError = 0;
    for (int frame = 0; frame < 240; ++frame) {
        pipeline.step(world);
        reference.step(alone);
        slip = std::max(slip, Vec3(offset() - start).norm());
        pathError = std::max(pathError, Vec3(world.bodies[static_cast<std::size_t>(platform)].transform.position -
                                             alone.bodies[static_cast<std::size_t>(platform)].transform.position)
                                            .norm());
    }
    INFO("slip " << slip << " m, platform off chapter 8's by " << pathError << " m");
    CHECK(slip < Real(0.04));          // under 1% of the 4 m of travel
    CHECK(pathError < Real(1e-4));     // the box never pushes the platform
}
