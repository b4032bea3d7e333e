// The chapter as the programs see it: stage names, scenes, the draw hook, the benches.
#include "03_epa/chapter.h"
#include "04_pgs/benches.h"
#include "04_pgs/chapter.h"
#include "04_pgs/contact_constraints.h"
#include "04_pgs/scenes.h"
#include "support/registry_fixture.h"
#include "support/scripted_panel.h"
#include "world/contact_draw.h"
#include "app/registry.h"
#include "support/fixture.h"
#include "support/quick_bench.h"
#include "world/debug_draw.h"

#include <catch2/catch.hpp>

#include <map>

using namespace stepwise;

TEST_CASE("the pipeline's stage names say what runs", "[ch04][pipeline]") {
    World world = test::makeWorld();
    test::addGround(world);
    test::addSphere(world, Vec3(0, 1, 0), Real(0.5));
    CHECK(makeChapter04Pipeline(world).enabledStageNames() ==
          std::vector<std::string>{"integrate:velocities", "narrowphase:closed_form", "solve:pgs", "integrate:positions", "contacts:drop_unloaded"});
    test::addBox(world, Vec3(2, 1, 0), Vec3(Real(0.5), Real(0.5), Real(0.5)));
    world.settings.solver = SolverKind::Jacobi;
    CHECK(makeChapter04Pipeline(world).enabledStageNames() ==
          std::vector<std::string>{"integrate:velocities", "narrowphase:gjk_epa", "solve:jacobi", "integrate:positions", "contacts:drop_unloaded"});
    // RK4 cannot be split: integrate first, with chapter 1's whole-step stage.
    world.settings.integrator = IntegratorKind::Rk4;
    CHECK(chooseStepOrder(world) == StepOrder::IntegrateFirst);
    CHECK(makeChapter04Pipeline(world).enabledStageNames() ==
          std::vector<std::string>{"integrate:rk4", "narrowphase:gjk_epa", "solve:jacobi", "contacts:drop_unloaded"});
}

TEST_CASE("the solve stage reports what it did", "[ch04][pipeline]") {
    World world = buildRestingScene();
    Pipeline pipeline = makeChapter04Pipeline(world);
    pipeline.step(world);
    const SolverStats& stats = world.step.solver;
    CHECK(stats.contactPoints == 4);  // box, ball, light ball on the ground; heavy on light
    CHECK(stats.rows == 12);
    CHECK(stats.residualRms >= 0);
}

TEST_CASE("the registry's chapter 4 pipeline is this chapter's", "[ch04][pipeline]") {
    const Registry& registry = test::chapterRegistry();
    const World world = buildDropScene();
    CHECK(registry.makePipeline(world).enabledStageNames() == makeChapter04Pipeline(world).enabledStageNames());
    CHECK(registry.findBench("solver") != nullptr);
    CHECK(registry.findBench("resting") != nullptr);
}

TEST_CASE("every chapter 4 scene runs finite, keeps its bodies above the ground, and draws its impulses",
          "[ch04][pipeline]") {
    const Registry& registry = test::chapterRegistry();
    int scenes = 0;
    for (const SceneEntry& entry : registry.scenes()) {
        if (entry.chapter != 4) continue;
        ++scenes;
        INFO("scene " << entry.name);
        World world = entry.build();
        Pipeline pipeline = registry.makePipeline(world, 4);
        int arrows = 0;
        RecordingDraw draw;
        REQUIRE(entry.makeView);
        const std::unique_ptr<SceneView> view = entry.makeView();
        ContactDrawOptions impulsesOnly;
        impulsesOnly.points = impulsesOnly.normals = false;
        impulsesOnly.impulses = true;
        test::simulate(world, pipeline, 2, [&](const World& w) {
            draw.clear();
            drawContacts(draw, w, impulsesOnly);  // what the demo's "impulses" view draws
            arrows = std::max(arrows, draw.count(RecordingDraw::Kind::Arrow));
        });
        for (const Motion& motion : world.motions) {
            CHECK(motion.linearVelocity.allFinite());
            CHECK(world.bodies[motion.bodyIndex].transform.position.y() > -0.1);  // nothing fell through
        }
        CHECK(arrows > 0);
        CHECK(view->hasPanel());
    }
    CHECK(scenes >= 4);
}

TEST_CASE("bench solver measures: more iterations give less residual and Gauss-Seidel stays below Jacobi", "[ch04][bench]") {
    const test::QuickBench run =
        test::runQuickBench(solverBench(), "ch04_bench_solver_test",
                            "part,solver,iterations,solve_ms,velocity_residual,max_penetration,solve_ms_q1,solve_ms_q3");
    std::map<std::string, std::map<int, double>> residual;
    for (const std::vector<std::string>& cell : run.rows) {
        REQUIRE(cell.size() >= 5);
        if (cell[0] == "fixed_set") residual[cell[1]][std::stoi(cell[2])] = std::stod(cell[4]);
    }
    CHECK(residual["gauss_seidel"][50] < residual["gauss_seidel"][1]);
    CHECK(residual["gauss_seidel"][8] < residual["jacobi"][8]);
    CHECK(test::rejectsUnwritablePath(solverBench()));
}

TEST_CASE("the solver panel sets iterations, beta, slop, restitution, friction and the solver", "[ch04][pipeline]") {
    const SceneEntry* entry = &test::sceneNamed("pgs-drop");
    World world = entry->build();
    test::ScriptedPanel panel;
    panel.ints = {{"iterations", 3}, {"substeps", 2}, {"solver", 1}};
    panel.floats = {{"Baumgarte beta", 0.5f}, {"slop (mm)", 10.0f}, {"restitution", 0.7f}, {"friction", 0.2f}};
    entry->makeView()->panel(world, panel);
    CHECK(world.settings.solverIterations == 3);
    CHECK(world.settings.substeps == 2);
    CHECK(world.settings.solver == SolverKind::Jacobi);
    CHECK(world.settings.baumgarte == Approx(0.5));
    CHECK(world.settings.slop == Approx(0.01));
    for (const Body& body : world.bodies) {
        CHECK(body.material.restitution == Approx(0.7));
        CHECK(body.material.friction == Approx(0.2));
    }
    // The stage follows the toggle at once: a pipeline planned for Gauss-Seidel, run after the
    // toggle, steps exactly like one planned for Jacobi.
    World planned = entry->build();
    Pipeline plannedPipeline = makeChapter04Pipeline(planned);
    REQUIRE(plannedPipeline.find("solve:pgs"));
    planned.settings.solver = SolverKind::Jacobi;
    World fresh = entry->build();
    fresh.settings.solver = SolverKind::Jacobi;
    Pipeline freshPipeline = makeChapter04Pipeline(fresh);
    REQUIRE(freshPipeline.find("solve:jacobi"));
    test::simulate(planned, plannedPipeline, 1);
    test::simulate(fresh, freshPipeline, 1);
    for (size_t i = 0; i < planned.bodies.size(); ++i)
        CHECK(planned.bodies[i].transform.position == fresh.bodies[i].transform.position);
}
