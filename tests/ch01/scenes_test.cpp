// Chapter 1's demo scenes, through the registry as the demo and the CLI see them, and the
// integrators bench in quick mode.
#include "01_integrators/bench_integrators.h"
#include "01_integrators/integrate.h"
#include "01_integrators/scenes.h"
#include "app/registry.h"
#include "support/registry_fixture.h"
#include "support/fixture.h"
#include "support/quick_bench.h"
#include "world/debug_draw.h"

#include <catch2/catch.hpp>

#include <map>
#include <sstream>

using namespace stepwise;
using namespace stepwise::test;

TEST_CASE("chapter 1 registers its scenes, pipeline and bench", "[ch01][scenes]") {
    const Registry& registry = chapterRegistry();
    for (const char* name : {"integrators-side-by-side", "t-handle", "projectile"}) {
        const SceneEntry* entry = registry.findScene(name);
        REQUIRE(entry);
        CHECK(entry->chapter == 1);
        CHECK_FALSE(entry->observe.empty());
        CHECK(entry->observe.find('\n') == std::string::npos);
        REQUIRE(entry->makeView);
    }
    const BenchEntry* bench = registry.findBench("integrators");
    REQUIRE(bench);
    CHECK(bench->chapter == 1);
    const World world = registry.findScene("t-handle")->build();
    const Pipeline pipeline = registry.makePipeline(world, 1);
    CHECK(pipeline.enabledStageNames() == std::vector<std::string>{"integrate:semi_implicit_euler"});
}

TEST_CASE("every chapter 1 scene runs 10 s and stays finite, and its draw hook labels the bodies",
          "[ch01][scenes]") {
    const Registry& registry = chapterRegistry();
    for (const SceneEntry& entry : registry.scenes()) {
        if (entry.chapter != 1) continue;
        INFO(entry.name);
        World world = entry.build();
        Pipeline pipeline = registry.makePipeline(world, 1);
        simulate(world, pipeline, 10.0);
        for (const Body& body : world.bodies) {
            CHECK(body.transform.position.allFinite());
            CHECK(body.transform.rotation.coeffs().allFinite());
        }
        RecordingDraw draw;
        REQUIRE(entry.makeView);
        entry.makeView()->draw(world, draw);
        std::map<std::string, int> labels;
        for (const RecordingDraw::Command& command : draw.commands())
            if (command.kind == RecordingDraw::Kind::Text) ++labels[command.message];
        for (const Motion& motion : world.motions)
            CHECK(labels[toString(integratorOf(world, motion))] > 0);
    }
}

TEST_CASE("side by side: the RK4 chain loses energy, Euler and Verlet keep theirs in a band", "[ch01][scenes]") {
    World world = buildIntegratorsSideBySide();
    Pipeline pipeline = chapterRegistry().makePipeline(world, 1);
    CHECK(pipeline.stages().at(0).name == "integrate:mixed");
    // Energy of each chain (kinetic + gravity + its springs), the same way the demo panel sums it.
    auto chainEnergy = [](const World& w, IntegratorKind method) {
        return computeEnergy(w, [&](int bodyIndex) {
            const Motion* motion = w.motionOf(bodyIndex);
            return motion && integratorOf(w, *motion) == method;
        }).total();
    };
    const IntegratorKind methods[] = {IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet, IntegratorKind::Rk4};
    // Mean energy over the first and the last two seconds: averages out the band Euler and
    // Verlet oscillate in, and leaves any drift.
    const double duration = 20, window = 2;
    std::map<IntegratorKind, double> firstWindow, lastWindow;
    std::map<IntegratorKind, std::vector<double>> samples;
    simulate(world, pipeline, duration, [&](const World& w) {
        for (IntegratorKind method : methods) samples[method].push_back(chainEnergy(w, method));
    });
    const size_t windowFrames = static_cast<size_t>(framesFor(world, window));
    std::ostringstream summary;
    for (IntegratorKind method : methods) {
        const std::vector<double>& energy = samples[method];
        REQUIRE(energy.size() > 2 * windowFrames);
        for (size_t i = 0; i < windowFrames; ++i) {
            firstWindow[method] += energy[i] / windowFrames;
            lastWindow[method] += energy[energy.size() - 1 - i] / windowFrames;
        }
        summary << toString(method) << " mean energy, first 2 s " << firstWindow[method] << " J, last 2 s "
                << lastWindow[method] << " J\n";
    }
    INFO(summary.str());
    const double rk4Loss = firstWindow[IntegratorKind::Rk4] - lastWindow[IntegratorKind::Rk4];
    CHECK(rk4Loss > 1.0);  // J, out of roughly 12 J of swinging energy above the resting chain
    for (IntegratorKind method : {IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet})
        CHECK(std::abs(lastWindow[method] - firstWindow[method]) < 0.2 * rk4Loss);
}

TEST_CASE("the integrators bench runs in quick mode and writes its table and plots", "[ch01][bench]") {
    const test::QuickBench run =
        test::runQuickBench(integratorsBench(), "ch01_bench_test",
                            "method,steps,dt_s,h_omega,error_m,run_ms,ns_per_body_step,run_ms_q1,run_ms_q3");
    CHECK(run.rows.size() == 3 * 7);
    CHECK(run.printed.find("observed order") != std::string::npos);
    CHECK(test::rejectsUnwritablePath(integratorsBench()));
}
