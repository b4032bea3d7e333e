// The stress scene generator: layouts, shapes, no body starting inside another, the same world
// for the same seed, and the three ways to reach it (scene files, `stepwise stress`, the bench).
#include "05_sap/benches.h"
#include "05_sap/chapter.h"
#include "05_sap/stress_command.h"
#include "05_sap/stress_scene.h"
#include "app/runner.h"
#include "support/scene_rejection.h"
#include "world/scene.h"
#include "support/temp_path.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace stepwise;

namespace {

std::string temporaryPath(const std::string& name) { return test::tempPath(name).string(); }

/// Loads scene text through a registry that knows chapter 5's generator.
World loadWithGenerators(const std::string& text) {
    Registry registry;
    registerChapters(registry);
    return loadSceneFromString(text, "test", registry.sceneGenerators());
}

std::string sceneError(const std::string& text) {
    return test::rejectionMessage([&] { loadWithGenerators(text); }, "no error");
}

}  // namespace

TEST_CASE("the stress scene lays its bodies out sparse or dense, above the ground, apart", "[ch05][stress]") {
    for (StressDensity density : {StressDensity::Sparse, StressDensity::Dense}) {
        for (StressShape shape : {StressShape::Sphere, StressShape::Diamond, StressShape::Box, StressShape::Mixed,
                                  StressShape::Capsule, StressShape::Cylinder, StressShape::All}) {
            INFO(toString(density) << ", " << toString(shape));
            StressParams params;
            params.count = 300;
            params.density = density;
            params.shape = shape;
            params.dropHeight = 0;
            World world = buildStressScene(params);
            REQUIRE(world.bodies.size() == 301);
            CHECK(world.bodies[0].type == BodyType::Static);
            CHECK(world.dynamicBodyCount() == 300);
            const Aabb ground = computeAabb(world.bodies[0].shape, world.bodies[0].transform);
            CHECK(ground.max.y() == Approx(0).margin(1e-6));
            int shapes[kShapeTypeCount] = {};
            for (std::size_t i = 1; i < world.bodies.size(); ++i) {
                const Aabb box = computeAabb(world.bodies[i].shape, world.bodies[i].transform);
                CHECK(box.min.y() >= -1e-5);                                        // nothing starts in the ground
                CHECK((box.min.array() >= ground.min.array() - 1e-3).head<3>().all());  // the ground is under all
                ++shapes[static_cast<int>(world.bodies[i].shape.type)];
            }
            if (shape == StressShape::Mixed)
                CHECK((shapes[static_cast<int>(ShapeType::Sphere)] == 100 && shapes[static_cast<int>(ShapeType::Convex)] == 100 &&
                       shapes[static_cast<int>(ShapeType::Box)] == 100));
            if (shape == StressShape::All)
                for (ShapeType kind : {ShapeType::Sphere, ShapeType::Convex, ShapeType::Box, ShapeType::Capsule, ShapeType::Cylinder})
                    CHECK(shapes[static_cast<int>(kind)] == 60);
            if (shape == StressShape::Capsule) CHECK(shapes[static_cast<int>(ShapeType::Capsule)] == 300);
            if (shape == StressShape::Cylinder) CHECK(shapes[static_cast<int>(ShapeType::Cylinder)] == 300);
            // No two bodies start inside each other (dense spheres may start exactly touching).
            world.settings.broadphase = BroadphaseMode::Sap;
            Pipeline pipeline = makeChapter05Pipeline(world);
            findCandidatePairs(world);
            updateContacts(world, world.candidatePairs);
            for (const Contact& contact : world.contacts)
                if (contact.bodyA != 0) CHECK(contact.points[0].depth < Real(1e-3));
            // Sparse bodies are spread out: far fewer neighbours than dense ones.
            const double perBody = static_cast<double>(world.broadphase.axisOverlaps) / 300;
            if (density == StressDensity::Sparse) CHECK(perBody < 15);
            if (density == StressDensity::Dense && shape == StressShape::Sphere) CHECK(world.candidatePairs.size() > 600);
        }
    }
}

TEST_CASE("the same parameters give the same world, and another seed another", "[ch05][stress]") {
    StressParams params;
    params.count = 50;
    const World first = buildStressScene(params), second = buildStressScene(params);
    params.seed = 6;
    const World other = buildStressScene(params);
    bool anyDifferent = false;
    for (std::size_t i = 0; i < first.bodies.size(); ++i) {
        CHECK(first.bodies[i].transform.position == second.bodies[i].transform.position);
        CHECK(first.bodies[i].transform.rotation.coeffs() == second.bodies[i].transform.rotation.coeffs());
        anyDifferent = anyDifferent || first.bodies[i].transform.position != other.bodies[i].transform.position;
    }
    CHECK(anyDifferent);
    // The drop height is the lowest bodies' bottoms.
    params.dropHeight = 5;
    const World high = buildStressScene(params);
    Real lowest = 1e9;
    for (std::size_t i = 1; i < high.bodies.size(); ++i)
        lowest = std::min(lowest, computeAabb(high.bodies[i].shape, high.bodies[i].transform).min.y());
    CHECK(lowest >= 5);
    CHECK(lowest < Real(5.3));
}

TEST_CASE("a scene file can name the generator with its parameters", "[ch05][stress]") {
    const World world = loadWithGenerators(R"({"format": "stepwise-scene", "version": 1, "name": "pile",
        "settings": {"broadphase": "brute", "substeps": 2},
        "bodies": [{"name": "marker", "type": "static", "shape": {"sphere": {"radius": 0.1}}, "position": [0, 50, 0]}],
        "generator": {"stress": {"count": 40, "density": "dense", "shape": "box", "drop_height": 3, "seed": 9}}})");
    CHECK(world.name == "pile");
    CHECK(world.settings.broadphase == BroadphaseMode::Brute);
    CHECK(world.settings.substeps == 2);
    REQUIRE(world.bodies.size() == 1 + 1 + 40);  // the listed body, the ground, the generated ones
    CHECK(world.bodies[0].name == "marker");
    CHECK(world.bodies[1].name == "ground");
    CHECK(world.bodies[2].shape.type == ShapeType::Box);
    // Bad parameters name their JSON path.
    CHECK(sceneError(R"({"generator": {"stress": {"count": 0}}})") ==
          "generator.stress.count: must be an integer in [1, 100000]");
    CHECK(sceneError(R"({"generator": {"stress": {"density": "thick"}}})") ==
          "generator.stress.density: must be one of \"sparse\", \"dense\" (got \"thick\")");
    CHECK(sceneError(R"({"generator": {"stress": {"shape": "cube"}}})").find("generator.stress.shape: must be one of") == 0);
    CHECK(sceneError(R"({"generator": {"stress": {"drop_hieght": 2}}})").find("generator.stress: unknown key \"drop_hieght\"") == 0);
    CHECK(sceneError(R"({"generator": {"storm": {}}})") == "generator: unknown generator \"storm\" (known: \"stress\")");
    CHECK(sceneError(R"({"generator": {"stress": {}, "storm": {}}})").find("generator: must be an object with one key") == 0);
    // Without the chapter's generators a program rejects the key with a reason.
    try {
        loadSceneFromString(R"({"generator": {"stress": {}}})", "test");
        FAIL("no error");
    } catch (const SceneError& error) {
        CHECK(std::string(error.what()) == "generator: unknown generator \"stress\" (this program knows none)");
    }
}

TEST_CASE("stepwise stress runs the scene, and saves a scene file that regenerates it", "[ch05][stress]") {
    StressArgs args;
    args.params.count = 30;
    args.params.shape = StressShape::Sphere;
    args.frames = 20;
    args.broadphase = "sap";
    args.reportPath = temporaryPath("ch05_stress_report.json");
    std::ostringstream out, err;
    REQUIRE(runStressCommand(args, chapterRegistry(), out, err) == 0);
    CHECK(out.str().find("broadphase sap (settings.broadphase is \"sap\")") != std::string::npos);
    std::ifstream report(args.reportPath);
    CHECK(report.good());
    std::remove(args.reportPath.c_str());

    StressArgs save = args;
    save.savePath = temporaryPath("ch05_stress_scene.json");
    REQUIRE(runStressCommand(save, chapterRegistry(), out, err) == 0);
    Registry registry;
    registerChapters(registry);
    const World loaded = loadSceneOrBuiltin(registry, save.savePath);
    const World built = buildStressScene(args.params);
    REQUIRE(loaded.bodies.size() == built.bodies.size());
    for (std::size_t i = 0; i < built.bodies.size(); ++i)
        CHECK(loaded.bodies[i].transform.position == built.bodies[i].transform.position);
    CHECK(loaded.settings.broadphase == BroadphaseMode::Sap);
    std::remove(save.savePath.c_str());

    StressArgs bad = args;
    bad.reportPath = "/nonexistent-dir/report.json";
    CHECK(runStressCommand(bad, chapterRegistry(), out, err) == 2);
    CHECK(err.str().find("/nonexistent-dir/report.json: cannot write the file") != std::string::npos);
}

TEST_CASE("stepwise stress runs the chapter it is asked for, the latest by default", "[ch05][stress]") {
    StressArgs args;
    args.params.count = 20;
    args.params.shape = StressShape::Sphere;
    args.frames = 3;
    const Registry& registry = chapterRegistry();
    auto summary = [&](std::optional<int> chapter) {
        StressArgs asked = args;
        asked.chapter = chapter;
        std::ostringstream out, err;
        REQUIRE(runStressCommand(asked, registry, out, err) == 0);
        return out.str();
    };
    const std::string latest = summary(std::nullopt);
    CHECK(latest.find("engine     chapter " + std::to_string(registry.lastChapter()) + " (the latest)") !=
          std::string::npos);
    CHECK(summary(registry.lastChapter()).find(" (the latest)") != std::string::npos);
    // The run reads gravity and dt (chapter 1) and the broadphase setting (chapter 5).
    for (const char* used : {"gravity", "dt (", "broadphase ("}) {
        INFO(used << " in\n" << latest);
        const std::size_t notUsed = latest.find("not used");
        CHECK((notUsed == std::string::npos || latest.find(used, notUsed) == std::string::npos));
    }
    // Chapter 4's engine tests every pair: no broadphase stage, and the broadphase setting unused.
    const std::string chapter4 = summary(4);
    CHECK(chapter4.find("engine     chapter 4\n") != std::string::npos);
    CHECK(chapter4.find("broadphase:") == std::string::npos);
    CHECK(chapter4.find("broadphase (chapter 5)") != std::string::npos);
    CHECK(latest.find("broadphase:") != std::string::npos);

    for (int unknown : {0, -1, registry.lastChapter() + 1, 99}) {
        StressArgs bad = args;
        bad.chapter = unknown;
        std::ostringstream out, err;
        CHECK(runStressCommand(bad, registry, out, err) == 2);
        CHECK(err.str() == "error: --chapter " + std::to_string(unknown) + ": no such chapter (this program has chapters 1 to " +
                               std::to_string(registry.lastChapter()) + ")\n");
        CHECK(out.str().empty());
    }
}
