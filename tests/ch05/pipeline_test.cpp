// Chapter 5 inside the engine: the stage and its place, the auto choice and the report that
// names it, brute force and sweep and prune giving bit-identical runs, the demo's overlay and
// panel, and the registry entries.
#include "04_pgs/scenes.h"
#include "05_sap/chapter.h"
#include "05_sap/scenes.h"
#include "app/panel.h"
#include "app/runner.h"
#include "support/fixture.h"
#include "support/scripted_panel.h"
#include "world/debug_draw.h"
#include "world/report.h"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>

using namespace stepwise;

namespace {

const Registry& registry() {
    static const Registry instance = [] {
        Registry r;
        registerChapters(r);
        return r;
    }();
    return instance;
}

World bodiesInARow(int count) {
    World world = test::makeWorld();
    test::addGround(world);
    for (int i = 1; i < count; ++i) test::addSphere(world, Vec3(Real(1.5) * static_cast<Real>(i), 1, 0), Real(0.5));
    return world;
}

/// The report of a run, without timings; the broadphase's own entries (its stage name and the
/// "broadphase" object) are taken out and returned apart.
std::string reportWithout(World world, BroadphaseMode mode, long frames, std::string& broadphaseUsed) {
    world.settings.broadphase = mode;
    Pipeline pipeline = makeChapter05Pipeline(world);
    RunOptions options;
    options.frames = frames;
    const RunStats stats = runHeadless(world, pipeline, registry(), options);
    nlohmann::ordered_json report = nlohmann::ordered_json::parse(reportToJson(world, stats, engineVersion()));
    report.erase("timing_ms");
    broadphaseUsed = report["broadphase"]["used"].get<std::string>();
    report.erase("broadphase");
    nlohmann::ordered_json stages = nlohmann::ordered_json::array();
    for (const auto& stage : report["pipeline"])
        if (stage.get<std::string>().rfind("broadphase:", 0) != 0) stages.push_back(stage);
    report["pipeline"] = stages;
    return report.dump(2);
}

}  // namespace

TEST_CASE("the broadphase stage runs before the narrowphase, at its frequency", "[ch05][pipeline]") {
    World world = bodiesInARow(3);
    world.settings.broadphase = BroadphaseMode::Sap;
    CHECK(makeChapter05Pipeline(world).enabledStageNames() ==
          std::vector<std::string>{"integrate:velocities", "broadphase:sap", "narrowphase:closed_form", "solve:pgs",
                                   "integrate:positions", "contacts:drop_unloaded"});
    world.settings.broadphase = BroadphaseMode::Brute;
    world.settings.integrator = IntegratorKind::Rk4;
    CHECK(makeChapter05Pipeline(world).enabledStageNames() ==
          std::vector<std::string>{"integrate:rk4", "broadphase:brute", "narrowphase:closed_form", "solve:pgs",
                                   "contacts:drop_unloaded"});
    world.settings.integrator = IntegratorKind::SemiImplicitEuler;
    const Pipeline oncePerFrame = makeChapter05Pipeline(world, StepOrder::SplitIntegration, ContactSearch::OncePerFrame);
    CHECK(oncePerFrame.find(stage_group::kBroadphase)->frequency == StageFrequency::FrameStart);
    CHECK(oncePerFrame.find(stage_group::kNarrowphase)->frequency == StageFrequency::FrameStart);
    CHECK(makeChapter05Pipeline(world).find(stage_group::kBroadphase)->frequency == StageFrequency::EverySubstep);
}

TEST_CASE("auto tests all pairs below the measured crossover and sweeps from it on, and says why", "[ch05][pipeline]") {
    World small = bodiesInARow(kAutoSapMinBodies - 1);
    World large = bodiesInARow(kAutoSapMinBodies);
    CHECK(chooseBroadphase(small) == BroadphaseMode::Brute);
    CHECK(chooseBroadphase(large) == BroadphaseMode::Sap);
    CHECK(makeChapter05Pipeline(small).find("broadphase:brute") != nullptr);
    CHECK(makeChapter05Pipeline(large).find("broadphase:sap") != nullptr);
    CHECK(broadphaseReason(small).find("fewer than the " + std::to_string(kAutoSapMinBodies)) != std::string::npos);
    CHECK(broadphaseReason(large).find("at least the " + std::to_string(kAutoSapMinBodies)) != std::string::npos);
    large.settings.broadphase = BroadphaseMode::Brute;
    CHECK(chooseBroadphase(large) == BroadphaseMode::Brute);
    CHECK(broadphaseReason(large) == "settings.broadphase is \"brute\"");
}

TEST_CASE("the run report and the summary name the broadphase and why", "[ch05][pipeline]") {
    World world = bodiesInARow(kAutoSapMinBodies + 5);
    Pipeline pipeline = makeChapter05Pipeline(world);
    RunOptions options;
    options.frames = 3;
    const RunStats stats = runHeadless(world, pipeline, registry(), options);
    const nlohmann::json report = nlohmann::json::parse(reportToJson(world, stats, engineVersion()));
    CHECK(report["broadphase"]["used"] == "sap");
    CHECK(report["broadphase"]["reason"].get<std::string>().rfind("auto: ", 0) == 0);
    CHECK(report["broadphase"]["candidate_pairs"] == world.candidatePairs.size());
    std::ostringstream summary;
    printSummary(summary, world, stats);
    CHECK(summary.str().find("broadphase sap (auto: ") != std::string::npos);
    // Before chapter 5 no broadphase runs, and the report says nothing about one.
    World earlier = bodiesInARow(3);
    Pipeline chapter4 = makeChapter04Pipeline(earlier);
    const RunStats earlierStats = runHeadless(earlier, chapter4, registry(), options);
    CHECK(nlohmann::json::parse(reportToJson(earlier, earlierStats, engineVersion())).count("broadphase") == 0);
}

TEST_CASE("brute force and sweep and prune give bit-identical reports on every built-in scene", "[ch05][pipeline]") {
    int scenes = 0;
    for (const SceneEntry& entry : registry().scenes()) {
        INFO("scene " << entry.name);
        const World world = loadSceneOrBuiltin(registry(), entry.name);
        std::string bruteUsed, sapUsed;
        const std::string brute = reportWithout(world, BroadphaseMode::Brute, 90, bruteUsed);
        const std::string sap = reportWithout(world, BroadphaseMode::Sap, 90, sapUsed);
        CHECK(bruteUsed == "brute");
        CHECK(sapUsed == "sap");
        REQUIRE(brute == sap);
        ++scenes;
    }
    CHECK(scenes >= 14);  // chapters 1 to 5
}

TEST_CASE("searched once per frame with substeps, the broadphase still feeds every speculative contact",
          "[ch05][pipeline]") {
    for (const World& scene : {buildSpherePitScene(30), buildDropScene(), buildStressScene(demoStressParams(StressDensity::Dense))}) {
        INFO(scene.name);
        World brute = scene, sap = scene;
        brute.settings.substeps = sap.settings.substeps = 4;
        brute.settings.broadphase = BroadphaseMode::Brute;
        sap.settings.broadphase = BroadphaseMode::Sap;
        Pipeline brutePipeline = makeChapter05Pipeline(brute, StepOrder::SplitIntegration, ContactSearch::OncePerFrame);
        Pipeline sapPipeline = makeChapter05Pipeline(sap, StepOrder::SplitIntegration, ContactSearch::OncePerFrame);
        // Right after the broadphase: every pair chapter 3's own search (all pairs, boxes grown by
        // the speculative margin) would hand the narrowphase must be among the candidates.
        long checked = 0;
        Stage check;
        check.name = "check:candidates";
        check.frequency = StageFrequency::FrameStart;
        check.run = [&checked](World& w, Real) {
            for (const BodyPair& pair : findAllPairCandidates(w, substepsAhead(w, ContactSearch::OncePerFrame))) {
                if (w.bodies[pair.bodyA].type != BodyType::Dynamic && w.bodies[pair.bodyB].type != BodyType::Dynamic) continue;
                ++checked;
                CHECK(std::binary_search(w.candidatePairs.begin(), w.candidatePairs.end(), pair));
            }
        };
        sapPipeline.insertBefore(stage_group::kNarrowphase, check);
        for (int frame = 0; frame < 60; ++frame) {
            brutePipeline.step(brute);
            sapPipeline.step(sap);
            REQUIRE(brute.candidatePairs == sap.candidatePairs);
        }
        CHECK(checked > 100);
        for (std::size_t i = 0; i < sap.bodies.size(); ++i)
            REQUIRE(brute.bodies[i].transform.position == sap.bodies[i].transform.position);
    }
}

TEST_CASE("the broadphase follows the setting at once, as the demo's toggle needs", "[ch05][pipeline]") {
    World planned = buildStressScene(demoStressParams(StressDensity::Sparse));
    Pipeline pipeline = makeChapter05Pipeline(planned);
    REQUIRE(pipeline.find("broadphase:sap"));
    test::simulate(planned, pipeline, 0.5);
    CHECK(planned.broadphase.used == BroadphaseMode::Sap);
    planned.settings.broadphase = BroadphaseMode::Brute;
    World copy = planned;
    copy.settings.broadphase = BroadphaseMode::Sap;
    Pipeline copyPipeline = makeChapter05Pipeline(copy);
    test::simulate(planned, pipeline, 0.5);
    test::simulate(copy, copyPipeline, 0.5);
    CHECK(planned.broadphase.used == BroadphaseMode::Brute);
    CHECK(copy.broadphase.used == BroadphaseMode::Sap);
    for (std::size_t i = 0; i < planned.bodies.size(); ++i)
        REQUIRE(planned.bodies[i].transform.position == copy.bodies[i].transform.position);
}

TEST_CASE("the stress scenes draw the bounds, the pairs and the sweep axis, and the panel drives them",
          "[ch05][scenes]") {
    for (const char* name : {"sap-stress", "sap-stress-dense"}) {
        INFO(name);
        const SceneEntry* entry = registry().findScene(name);
        REQUIRE(entry);
        REQUIRE(entry->makeView);
        CHECK(entry->chapter == 5);
        World world = entry->build();
        Pipeline pipeline = registry().makePipeline(world);
        test::simulate(world, pipeline, 1.0);
        std::unique_ptr<SceneView> view = entry->makeView();
        REQUIRE(view->hasPanel());
        RecordingDraw draw;
        view->draw(world, draw);
        CHECK(draw.count(RecordingDraw::Kind::Box) == world.dynamicBodyCount());  // one bound per moving body
        CHECK(draw.count(RecordingDraw::Kind::Arrow) == 1);                      // the sweep axis
        CHECK(draw.count(RecordingDraw::Kind::Line) >= world.dynamicBodyCount());  // intervals (and pairs)
        CHECK(draw.count(RecordingDraw::Kind::Text) == 1);

        test::ScriptedPanel panel;
        panel.ints = {{"broadphase", 2}};
        view->panel(world, panel);
        CHECK(world.settings.broadphase == BroadphaseMode::Brute);
        const auto shows = [&](const std::string& part) {
            return std::any_of(panel.lines.begin(), panel.lines.end(),
                               [&](const std::string& line) { return line.find(part) != std::string::npos; });
        };
        CHECK(shows("candidate pairs: " + std::to_string(world.candidatePairs.size())));
        CHECK(shows("sweep axis: "));
        // The generator's controls take effect with "regenerate"; the settings stay.
        test::ScriptedPanel regenerate;
        regenerate.ints = {{"bodies", 60}, {"shape", 1}};
        regenerate.floats = {{"drop height (m)", 7.0f}};
        regenerate.pressEveryButton = true;
        regenerate.flipEveryCheckbox = true;  // bounds, pairs and intervals off
        view->panel(world, regenerate);
        REQUIRE(world.bodies.size() == 61);
        CHECK(world.bodies[1].shape.type == ShapeType::Convex);
        CHECK(world.settings.broadphase == BroadphaseMode::Brute);
        CHECK(world.name == name);
        test::simulate(world, pipeline, 0.1);
        draw.clear();
        view->draw(world, draw);
        CHECK(draw.commands().empty());
        // A fresh view (the demo's restart) starts from the scene's own parameters.
        CHECK(entry->build().bodies.size() == static_cast<std::size_t>(demoStressParams(
                                                  std::string(name) == "sap-stress" ? StressDensity::Sparse : StressDensity::Dense).count + 1));
    }
}

TEST_CASE("chapter 5 registers its pipeline, scenes, bench, command and generator", "[ch05][registry]") {
    const World world = buildStressScene(demoStressParams(StressDensity::Sparse));
    CHECK(registry().makePipeline(world).enabledStageNames() == makeChapter05Pipeline(world).enabledStageNames());
    CHECK(registry().makePipeline(world, 4).find(stage_group::kBroadphase) == nullptr);
    REQUIRE(registry().findBench("broadphase"));
    CHECK(registry().findBench("broadphase")->chapter == 5);
    CHECK(registry().sceneGenerators().count("stress") == 1);
    CHECK(std::count_if(registry().commands().begin(), registry().commands().end(),
                        [](const CommandEntry& command) { return command.chapter == 5; }) == 1);
}
