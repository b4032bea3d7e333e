// The chapter's stage, scenes, overlay and registration: the narrowphase finds exactly the
// pairs the oracle says overlap, frame after frame of the demo scene.

#include "02_gjk/chapter.h"
#include "02_gjk/scenes.h"
#include "support/registry_fixture.h"
#include "support/scripted_panel.h"
#include "app/registry.h"
#include "gjk_test_util.h"
#include "world/debug_draw.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace stepwise;

namespace {

bool hasPair(const World& world, int a, int b) {
    return std::find(world.pairs.begin(), world.pairs.end(), BodyPair{a, b}) != world.pairs.end();
}

}  // namespace

TEST_CASE("the chapter 2 pipeline is chapter 1's plus narrowphase:gjk", "[ch02][pipeline]") {
    const World world = buildGjkTwoBoxes();
    const Pipeline pipeline = makeChapter02Pipeline(world);
    const std::vector<std::string> names = pipeline.enabledStageNames();
    REQUIRE(names.size() == 2);
    CHECK(names[0].rfind("integrate:", 0) == 0);
    CHECK(names[1] == "narrowphase:gjk");
}

TEST_CASE("gjk-two-boxes: the stage reports the pair exactly while the oracle says it overlaps", "[ch02][pipeline]") {
    World world = buildGjkTwoBoxes();
    Pipeline pipeline = makeChapter02Pipeline(world);
    int overlappingFrames = 0, separatedFrames = 0, judged = 0;
    for (int frame = 0; frame < 900; ++frame) {
        pipeline.step(world);
        const Body& a = world.bodies[0];
        const Body& b = world.bodies[1];
        const oracle::OracleBox boxA = oracle::makeOracleBox(a.shape.halfExtents, a.transform);
        const oracle::OracleBox boxB = oracle::makeOracleBox(b.shape.halfExtents, b.transform);
        const double exactSigned = oracle::boxSignedDistance(boxA, boxB);
        if (std::abs(exactSigned) <= 1e-4) continue;
        ++judged;
        INFO("frame " << frame << ", exact signed distance " << exactSigned);
        CHECK(hasPair(world, 0, 1) == (exactSigned < 0));
        (exactSigned < 0 ? overlappingFrames : separatedFrames)++;
    }
    // The scene must show both states, repeatedly: that is what it is for.
    CHECK(overlappingFrames > 100);
    CHECK(separatedFrames > 100);
    CHECK(judged > 800);
}

TEST_CASE("gjk-sphere-diamond: the diamond's tips dip in and out of the sphere", "[ch02][pipeline]") {
    World world = buildGjkSphereDiamond();
    Pipeline pipeline = makeChapter02Pipeline(world);
    int hits = 0, misses = 0, changes = 0;
    bool previous = false;
    for (int frame = 0; frame < 900; ++frame) {
        pipeline.step(world);
        const bool hit = hasPair(world, 0, 1);
        changes += (frame > 0 && hit != previous) ? 1 : 0;
        previous = hit;
        (hit ? hits : misses)++;
        // Cross-check with the distance query: intersecting pairs have no positive distance.
        const GjkDistanceResult distance = gjkDistance(makeProxy(world.bodies[0]), makeProxy(world.bodies[1]));
        if (distance.separated) CHECK_FALSE(hit);
    }
    CHECK(hits > 50);
    CHECK(misses > 50);
    CHECK(changes >= 4);
}

TEST_CASE("narrowphase skips static-static pairs and tests the rest", "[ch02][pipeline]") {
    World world;
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.shape = Shape::box(Vec3(5, Real(0.5), 5));
    addBody(world, ground);
    BodyDef wall = ground;
    wall.transform.position = Vec3(0, 1, 0);  // overlaps the ground, but both are static
    addBody(world, wall);
    BodyDef crate;
    crate.shape = Shape::box(Vec3::Constant(Real(0.5)));
    crate.transform.position = Vec3(0, Real(0.9), 0);
    addBody(world, crate);
    CHECK(findIntersectingPairs(world) == 2);
    REQUIRE(world.pairs.size() == 2);
    CHECK(hasPair(world, 0, 2));
    CHECK(hasPair(world, 1, 2));
    CHECK_FALSE(hasPair(world, 0, 1));
}

TEST_CASE("the overlay draws A - B, the origin, the simplex and the iteration count", "[ch02][scenes]") {
    const World world = buildGjkTwoBoxes();
    CHECK(minkowskiPoints(world.bodies[0], world.bodies[1], SupportMode::Extents).size() == 64);
    RecordingDraw draw;
    drawGjkOverlay(world, draw, SupportMode::Extents, Vec3(0, 4, 0));
    CHECK(draw.count(RecordingDraw::Kind::Point) >= 64);
    CHECK(draw.count(RecordingDraw::Kind::Hull) == 1);
    bool iterationText = false;
    for (const auto& command : draw.commands())
        iterationText = iterationText || (command.kind == RecordingDraw::Kind::Text && command.message.find("iterations") != std::string::npos);
    CHECK(iterationText);
    // A round shape is sampled from its support map instead; the hull stays buildable.
    const World round = buildGjkSphereDiamond();
    const std::vector<Vec3> roundPoints = minkowskiPoints(round.bodies[0], round.bodies[1], SupportMode::Extents);
    CHECK(roundPoints.size() > 64);
    CHECK(roundPoints.size() <= size_t(kMaxHullPoints));
    RecordingDraw roundDraw;
    drawGjkOverlay(round, roundDraw, SupportMode::Extents, Vec3(0, 3, 0));
    CHECK(roundDraw.count(RecordingDraw::Kind::Hull) == 2);  // the diamond itself, and A - B
}

TEST_CASE("chapter 2 registers its scenes, pipeline and bench", "[ch02][registry]") {
    const Registry& registry = test::chapterRegistry();
    for (const char* name : {"gjk-two-boxes", "gjk-sphere-diamond"}) {
        const SceneEntry* entry = registry.findScene(name);
        REQUIRE(entry != nullptr);
        CHECK(entry->chapter == 2);
        REQUIRE(entry->makeView);
        const std::unique_ptr<SceneView> view = entry->makeView();
        CHECK(view->hasPanel());
        World world = entry->build();
        Pipeline pipeline = registry.makePipeline(world, 2);
        CHECK(pipeline.find("narrowphase:gjk") != nullptr);
        RecordingDraw draw;
        view->draw(world, draw);
        CHECK(draw.count(RecordingDraw::Kind::Text) >= 1);
    }
    const BenchEntry* bench = registry.findBench("gjk");
    REQUIRE(bench != nullptr);
    CHECK(bench->chapter == 2);
}

TEST_CASE("the panel moves body 1 and stops its spin", "[ch02][scenes]") {
    const SceneEntry* entry = &test::sceneNamed("gjk-two-boxes");
    World world = entry->build();
    test::ScriptedPanel panel;
    panel.floats = {{"body 1 x (m)", 0.25f}};
    panel.ints = {{"box support map", 1}};  // vertex-loop support
    entry->makeView()->panel(world, panel);
    CHECK(world.bodies[1].transform.position.x() == Approx(0.25));
    CHECK(world.motionOf(1)->angularVelocity.norm() == 0);
    REQUIRE_FALSE(panel.lines.empty());
    CHECK(panel.lines[0].find("INTERSECT") != std::string::npos);  // the plank now pierces the cube
}
