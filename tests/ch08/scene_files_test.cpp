// Chapter 8's scene files: the gallery file loads, runs without warnings and survives a save and
// a load, as do the built scenes; bad joint input is rejected at its JSON path; every shipped scene
// file still loads.
#include "08_joints/chapter.h"
#include "08_joints/kinematic.h"
#include "08_joints/scenes.h"
#include "app/registry.h"
#include "app/runner.h"
#include "world/scene.h"
#include "support/scene_rejection.h"
#include "scene_fixture.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <functional>

using namespace stepwise;
using test::angleAbout;
using test::finiteState;
using test::jointTo;
using test::slide;
using test::stepFrames;

namespace {

const std::string kGalleryFile = "scenes/joint-gallery.json";

using test::rejectionOf;

/// A post and a bar, joined by `joint` (JSON text without a and b), for the error cases.
std::string sceneWithJoint(const std::string& joint, const std::string& barExtra = "") {
    return R"({"bodies": [{"name": "post", "type": "static", "shape": {"box": {"half_extents": [0.1, 0.1, 0.1]}}},
                          {"name": "bar", "shape": {"box": {"half_extents": [0.4, 0.05, 0.05]}}, "position": [0.5, 0, 0])" +
           barExtra + R"(}],
              "joints": [{"a": "post", "b": "bar", )" + joint + "}]}";
}

}  // namespace

TEST_CASE("the gallery file loads and runs through the chapter's pipeline without warnings", "[ch08][scenes]") {
    World world = loadSceneFile(kGalleryFile);
    REQUIRE(world.joints.size() == 7);
    REQUIRE(world.kinematicPaths.size() == 1);
    // The hinged bar starts 30 degrees down from the reference rotation the file gives.
    const JointDesc hinge = jointTo(world, "hinge-limits-bar");
    CHECK(angleAbout(world, hinge) == Approx(-30 * kDegree).margin(0.01 * kDegree));
    Pipeline pipeline = chapterRegistry().makePipeline(world);
    RunOptions options;
    options.frames = 300;
    const RunStats stats = runHeadless(world, pipeline, chapterRegistry(), options);
    CHECK(stats.warnings.empty());
    REQUIRE(finiteState(world));
    CHECK(angleAbout(world, hinge) == Approx(-45 * kDegree).margin(2 * kDegree));
    CHECK(slide(world, jointTo(world, "slider-block")) == Approx(0.5).margin(0.01));
}

TEST_CASE("save then load keeps every joint field and kinematic path", "[ch08][scenes]") {
    const std::vector<std::pair<const char*, std::function<World()>>> sources = {
        {"the gallery file", [] { return loadSceneFile(kGalleryFile); }},
        {"the gallery scene", buildJointGallery},
        {"the sandbox", buildJointsSandbox}};
    for (const auto& [source, build] : sources) {
        World world = build();
        Pipeline pipeline = makeChapter08Pipeline(world);
        stepFrames(world, pipeline, 37);  // paths part way through: the saved phase has moved on
        INFO(source);
        const World copy = loadSceneFromString(saveSceneToString(world));
        REQUIRE(copy.joints.size() == world.joints.size());
        for (std::size_t i = 0; i < world.joints.size(); ++i) {
            const JointDesc &a = world.joints[i], &b = copy.joints[i];
            INFO("joint " << i << " " << toString(a.type));
            CHECK(a.type == b.type);
            CHECK(a.bodyA == b.bodyA);
            CHECK(a.bodyB == b.bodyB);
            CHECK((a.localAnchorA - b.localAnchorA).norm() < Real(1e-6));
            CHECK((a.localAnchorB - b.localAnchorB).norm() < Real(1e-6));
            CHECK(a.collideConnected == b.collideConnected);
            if (a.type != JointType::Distance && a.type != JointType::BallSocket)
                CHECK(std::abs(a.referenceRotation.dot(b.referenceRotation)) > Real(1 - 1e-6));
            if (a.type == JointType::Hinge || a.type == JointType::ConeTwist || a.type == JointType::Slider)
                CHECK((a.axis - b.axis).norm() < Real(1e-6));
            if (a.type == JointType::Distance) {
                CHECK(b.length.value_or(-1) == Approx(a.length.value_or(-1)));
                CHECK(a.springHertz == b.springHertz);
                CHECK(a.springDampingRatio == b.springDampingRatio);
            }
            CHECK(a.limits == b.limits);
            CHECK(a.coneAngle == b.coneAngle);
            CHECK(a.twistLimits == b.twistLimits);
            CHECK(a.motor.has_value() == b.motor.has_value());
            if (a.motor && b.motor) {
                CHECK(a.motor->speed == b.motor->speed);
                CHECK(a.motor->maxForce == b.motor->maxForce);
            }
            CHECK(a.frictionTorque == b.frictionTorque);
        }
        REQUIRE(copy.kinematicPaths.size() == world.kinematicPaths.size());
        for (std::size_t i = 0; i < world.kinematicPaths.size(); ++i) {
            const KinematicPath &a = world.kinematicPaths[i], &b = copy.kinematicPaths[i];
            CHECK(a.body == b.body);
            CHECK((a.amplitude - b.amplitude).norm() < Real(1e-6));
            CHECK(a.period == b.period);
            // The copy starts at the original's present: same line, same place on it from now on.
            CHECK((a.center - b.center).norm() < Real(1e-3));
            CHECK((pathPosition(a, world.time + 1) - pathPosition(b, 1)).norm() < Real(1e-3));
        }
    }
}

TEST_CASE("bad joint input is rejected at its JSON path", "[ch08][scenes]") {
    struct Case {
        std::string scene, path, message;
    };
    const std::vector<Case> cases = {
        {R"({"bodies": [{"name": "ball", "shape": {"sphere": {"radius": 1}}}],
             "joints": [{"type": "ball_socket", "a": "ball", "b": "bal"}]})",
         "joints[0].b", "unknown body \"bal\""},
        {sceneWithJoint(R"("type": "hinge", "axis": [0, 0, 0])"), "joints[0].axis", "must not be zero"},
        {sceneWithJoint(R"("type": "slider", "limits": [0.5, -0.5])"), "joints[0].limits", "lo <= hi"},
        {sceneWithJoint(R"("type": "hinge", "limits": [-4, 1])"), "joints[0].limits", "[-pi, pi]"},
        {sceneWithJoint(R"("type": "distance", "motor": {"speed": 1, "max_force": 5})"), "joints[0]",
         "unknown key \"motor\""},
        {sceneWithJoint(R"("type": "slider", "motor": {"speed": 1, "max_torque": 5})"), "joints[0].motor",
         "unknown key \"max_torque\" (accepted: speed, max_force)"},
        {sceneWithJoint(R"("type": "cone_twist", "reference_rotation": [0, 0, 0, 2])"), "joints[0].reference_rotation",
         "must be a unit quaternion"},
        {sceneWithJoint(R"("type": "fixed")", R"(, "path": {"amplitude": [1, 0, 0], "period": 2})"), "bodies[1].path",
         "only kinematic bodies follow a path"},
    };
    for (const Case& bad : cases) {
        INFO(bad.scene);
        const SceneError error = rejectionOf(bad.scene);
        REQUIRE(error.issues().size() == 1);
        CHECK(error.path() == bad.path);
        INFO(error.what());
        CHECK(error.issues()[0].message.find(bad.message) != std::string::npos);
    }
}

TEST_CASE("every shipped scene file still loads", "[ch08][scenes]") {
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator("scenes")) {
        if (entry.path().extension() != ".json") continue;
        INFO(entry.path().string());
        CHECK_NOTHROW(loadSceneFile(entry.path().string(), chapterRegistry().sceneGenerators()));
        ++files;
    }
    CHECK(files >= 5);
}
