// Chapter 3 inside the engine: the pipeline stage, the penetration probe, the registry entries,
// the demo scenes' drawing and the bench.
#include "03_epa/bench_epa.h"
#include "03_epa/chapter.h"
#include "03_epa/scenes.h"
#include "support/registry_fixture.h"
#include "support/scripted_panel.h"
#include "app/registry.h"
#include "support/fixture.h"
#include "support/quick_bench.h"
#include "world/debug_draw.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

using namespace stepwise;

namespace {

std::vector<std::string> stageNames(const Pipeline& pipeline) {
    const std::vector<Stage>& stages = pipeline.stages();
    std::vector<std::string> names(stages.size());
    std::transform(stages.begin(), stages.end(), names.begin(), [](const Stage& stage) { return stage.name; });
    return names;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}


}  // namespace

TEST_CASE("The chapter 3 pipeline swaps GJK's yes/no stage for one that makes contacts", "[ch03][pipeline]") {
    World world = test::makeWorld(test::zeroGravitySettings());
    test::addGround(world);                                                        // top at y = 0
    const int box = test::addBox(world, Vec3(0, Real(0.45), 0), Vec3::Constant(Real(0.5)));  // 5 cm into it
    test::addSphere(world, Vec3(10, 5, 0), Real(0.5));                             // alone
    Pipeline pipeline = makeChapter03Pipeline(world);
    const std::vector<std::string> names = stageNames(pipeline);
    CHECK(contains(names, "narrowphase:gjk_epa"));
    CHECK_FALSE(contains(names, "narrowphase:gjk"));

    pipeline.step(world);
    REQUIRE(world.contacts.size() == 1);
    REQUIRE(world.pairs.size() == 1);
    const Contact& contact = world.contacts[0];
    CHECK(contact.bodyA == 0);
    CHECK(contact.bodyB == box);
    CHECK(world.pairs[0] == (BodyPair{0, box}));
    CHECK(contact.pointCount == 1);
    CHECK(contact.normal.y() == Approx(1).epsilon(1e-5));          // from the ground up to the box
    CHECK(contact.points[0].depth == Approx(0.05).epsilon(1e-4));
    CHECK((contact.points[0].pointA - contact.points[0].pointB - contact.points[0].depth * contact.normal).norm() <
          Real(1e-5));
    CHECK(measureDeepestPenetration(world) == Approx(0.05).epsilon(1e-4));
}

TEST_CASE("A world of spheres plans the closed-form stage, and static pairs are skipped", "[ch03][pipeline]") {
    World world = test::makeWorld(test::zeroGravitySettings());
    test::addSphere(world, Vec3(0, 0, 0), 1, BodyType::Static);
    test::addSphere(world, Vec3(Real(0.5), 0, 0), 1, BodyType::Static);  // static-static: ignored
    test::addSphere(world, Vec3(0, Real(1.8), 0), 1);
    CHECK(allPairsClosedForm(world));
    Pipeline pipeline = makeChapter03Pipeline(world);
    CHECK(contains(stageNames(pipeline), "narrowphase:closed_form"));
    pipeline.step(world);
    CHECK(world.contacts.size() == 2);
    for (const Contact& contact : world.contacts) CHECK(contact.bodyB == 2);
    CHECK(measureDeepestPenetration(world) == Approx(0.2).epsilon(1e-4));

    test::addBox(world, Vec3(5, 5, 5), Vec3::Ones());
    CHECK(allPairsClosedForm(world));  // box-sphere has a closed form
    test::addBox(world, Vec3(9, 5, 5), Vec3::Ones());
    CHECK_FALSE(allPairsClosedForm(world));  // box-box does not
}

TEST_CASE("The penetration probe finds the deepest of many overlaps", "[ch03][pipeline]") {
    World world = test::makeWorld(test::zeroGravitySettings());
    for (int i = 0; i < 20; ++i) {
        // Pairs of boxes along x, the i-th pair overlapping by 0.01 * (i + 1).
        const Real x = Real(4 * i);
        test::addBox(world, Vec3(x, 0, 0), Vec3::Constant(Real(0.5)));
        test::addBox(world, Vec3(x, 1 - Real(0.01) * (i + 1), 0), Vec3::Constant(Real(0.5)));
    }
    CHECK(measureDeepestPenetration(world) == Approx(0.2).epsilon(1e-4));
    world.bodies.back().transform.position.y() = 5;
    CHECK(measureDeepestPenetration(world) == Approx(0.19).epsilon(1e-4));
}

TEST_CASE("Chapter 3 registers its pipeline, probe, bench, command and scenes", "[ch03][registry]") {
    const Registry& registry = test::chapterRegistry();
    World world = test::makeWorld();
    test::addGround(world);
    test::addBox(world, Vec3(0, Real(0.4), 0), Vec3::Constant(Real(0.5)));
    CHECK(contains(registry.makePipeline(world, 3).enabledStageNames(), "narrowphase:gjk_epa"));
    const PenetrationProbe* probe = registry.penetrationProbe(3);
    REQUIRE(probe != nullptr);
    CHECK(probe->chapter == 3);
    CHECK(probe->measure(world) == Approx(0.1).epsilon(1e-4));
    CHECK(registry.findBench("epa") != nullptr);
    CHECK(std::count_if(registry.commands().begin(), registry.commands().end(),
                        [](const CommandEntry& command) { return command.chapter == 3; }) == 1);
    CHECK(registry.findScene("epa-step-by-step") != nullptr);
    CHECK(registry.findScene("epa-contact-gallery") != nullptr);
}

TEST_CASE("The EPA stepper draws the polytope, its closest face and the contact", "[ch03][scenes]") {
    const SceneEntry* scene = &test::sceneNamed("epa-step-by-step");
    World world = scene->build();
    RecordingDraw draw;
    const EpaResult converged = drawEpaStep(world, 0, 1, -1, Vec3(3, 0, 0), draw);
    CHECK(converged.exit == EpaExit::Converged);
    CHECK(draw.count(RecordingDraw::Kind::Box) == 2);       // red contact cubes
    CHECK(draw.count(RecordingDraw::Kind::Triangle) == 1);  // the closest face, blue
    CHECK(draw.count(RecordingDraw::Kind::Line) >= 12);     // the polytope's edges
    CHECK(draw.count(RecordingDraw::Kind::Arrow) == 2);     // normal in the world and in A - B
    int red = 0, yellow = 0, blue = 0;
    for (const RecordingDraw::Command& command : draw.commands()) {
        red += command.kind == RecordingDraw::Kind::Box && command.color.r == colors::kRed.r;
        yellow += command.kind == RecordingDraw::Kind::Arrow && command.color.g == colors::kYellow.g;
        blue += command.kind == RecordingDraw::Kind::Triangle && command.color.b == colors::kBlue.b;
    }
    CHECK(red == 2);
    CHECK(yellow == 2);
    CHECK(blue == 1);

    // One expansion at a time: fewer faces, a shallower lower bound.
    draw.clear();
    const EpaResult first = drawEpaStep(world, 0, 1, 1, Vec3(3, 0, 0), draw);
    CHECK(first.iterations == 1);
    CHECK(first.depth <= converged.depth + Real(1e-6));

    // The panel drives the step count; the draw hook follows it.
    test::ScriptedPanel panel;
    panel.ints = {{"EPA expansions", 2}};
    panel.pressEveryButton = true;   // step, then reset
    panel.flipEveryCheckbox = true;  // run to convergence; stop turning box b
    const std::unique_ptr<SceneView> view = scene->makeView();
    view->panel(world, panel);
    CHECK(panel.sliders == 1);
    CHECK(panel.buttons == 2);
    CHECK(panel.lines.size() >= 2);
    draw.clear();
    view->draw(world, draw);
    CHECK(draw.count(RecordingDraw::Kind::Triangle) == 1);
    REQUIRE_FALSE(panel.lines.empty());
    CHECK(panel.lines[0].find("converged") != std::string::npos);

    // The demo makes a view afresh at every load: nothing the first one was told carries over.
    test::ScriptedPanel freshPanel;
    scene->makeView()->panel(world, freshPanel);
    REQUIRE_FALSE(freshPanel.lines.empty());
    CHECK(freshPanel.lines[0].find("after 0 expansions") != std::string::npos);
}

TEST_CASE("The contact gallery runs through the chapter 3 pipeline with finite contacts", "[ch03][scenes]") {
    const Registry& registry = test::chapterRegistry();
    const SceneEntry* scene = &test::sceneNamed("epa-contact-gallery");
    World world = scene->build();
    Pipeline pipeline = registry.makePipeline(world, 3);
    CHECK(contains(pipeline.enabledStageNames(), "narrowphase:gjk_epa"));
    std::size_t mostContacts = 0;
    test::simulate(world, pipeline, 3.0, [&](const World& stepped) {
        mostContacts = std::max(mostContacts, stepped.contacts.size());
        for (const Contact& contact : stepped.contacts) {
            CHECK(isFinite(contact.normal));
            CHECK(isFinite(contact.points[0].depth));
            CHECK(contact.points[0].depth >= 0);
        }
    });
    CHECK(mostContacts >= 5);
    RecordingDraw draw;
    scene->makeView()->draw(world, draw);
    CHECK(draw.count(RecordingDraw::Kind::Text) == 6);
}

TEST_CASE("The EPA bench runs in quick mode and writes its table", "[ch03][bench]") {
    const test::QuickBench run = test::runQuickBench(epaBench(), "ch03_bench_epa_test");
    CHECK(run.printed.find("peers:") != std::string::npos);
    bool defaultBoxesAccurate = false;
    for (const std::string& line : run.lines) {
        // boxes, extents, tolerance sweep at the default tolerance: the suite's accuracy holds.
        if (line.rfind("boxes,extents,tolerance,1e-05,", 0) == 0)
            defaultBoxesAccurate = std::stod(test::splitCells(line).at(7)) <= 1e-5;
    }
    CHECK(run.lines.size() == 8 * 5 + 1);
    CHECK(defaultBoxesAccurate);
}
