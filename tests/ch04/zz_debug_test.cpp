#include "04_pgs/chapter.h"
#include "04_pgs/contact_constraints.h"
#include "04_pgs/scenes.h"
#include "ch04_support.h"
#include "support/fixture.h"
#include <catch2/catch.hpp>
#include <iostream>
using namespace stepwise;
TEST_CASE("debug stack", "[.debug]") {
  for (int sub : {1, 2, 4}) for (int iters : {10, 20, 30, 50}) {
    World world = buildRestingScene();
    world.settings.solverIterations = iters;
    world.settings.substeps = sub;
    Pipeline pipeline = makeChapter04Pipeline(world);
    const int light = world.findBody("light");
    const int heavy = world.findBody("heavy");
    double b = 0, t = 0, bl = 0, tl = 0;
    test::simulate(world, pipeline, 5, [&](const World& w) {
        b = std::max(b, (double)test::overlapDepth(w, 0, light)); t = std::max(t, (double)test::overlapDepth(w, light, heavy));
        bl = test::overlapDepth(w, 0, light); tl = test::overlapDepth(w, light, heavy);
    });
    std::cout << "sub " << sub << " it " << iters << " max bottom " << b << " top " << t << " final " << bl << " " << tl << "\n";
  }
}
namespace {
struct Frozen { std::vector<ConstraintRow> rows; std::vector<SolverBody> bodies; };
Frozen freeze(World world, int frames) {
    Pipeline pipeline = makeChapter04Pipeline(world);
    for (int frame = 0; frame < frames; ++frame) pipeline.step(world);
    for (Stage& stage : pipeline.stages()) { if (stageGroup(stage.name) == "solve") break; stage.run(world, world.settings.dt); }
    Frozen f; f.bodies = gatherSolverBodies(world); f.rows = buildContactRows(world, f.bodies, world.settings.dt).rows; return f;
}
}
TEST_CASE("debug conv", "[.debug2]") {
  for (int frames : {20, 30, 60, 120}) {
    Frozen fr = freeze(buildSpherePitScene(40), frames);
    std::cout << "frames " << frames << " rows " << fr.rows.size() << "\n";
    for (int k : {1, 2, 3, 4, 8, 16, 32}) {
        auto r1 = fr.rows; auto b1 = fr.bodies; solveRows(r1, b1, SolverKind::GaussSeidel, k);
        auto r2 = fr.rows; auto b2 = fr.bodies; solveRows(r2, b2, SolverKind::Jacobi, k);
        auto g = measureResidual(r1, b1); auto j = measureResidual(r2, b2);
        std::cout << "  k " << k << " GS rms " << g.rms << " max " << g.max << "   J rms " << j.rms << " max " << j.max << "\n";
    }
  }
}
