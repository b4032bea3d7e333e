#include "04_pgs/chapter.h"
#include "04_pgs/contact_constraints.h"
#include "04_pgs/scenes.h"
#include "ch04_support.h"
#include "support/fixture.h"
#include <catch2/catch.hpp>
#include <iostream>
using namespace stepwise;
TEST_CASE("debug stack", "[.debug]") {
    World world = buildRestingScene();
    world.settings.solverIterations = 40;
    Pipeline pipeline = makeChapter04Pipeline(world);
    test::simulate(world, pipeline, 3);
    // one more step by hand
    Real dt = world.settings.dt;
    auto& st = pipeline.stages();
    st[0].run(world, dt); st[1].run(world, dt);
    for (auto& c : world.contacts) std::cout << "raw " << c.bodyA << "-" << c.bodyB << " d " << c.points[0].depth << "\n";
    auto bodies = gatherSolverBodies(world);
    auto cr = buildContactRows(world, bodies, dt);
    for (auto& ref : cr.points) {
        const Contact& c = world.contacts[ref.contactIndex];
        auto& r = cr.rows[ref.normalRow];
        std::cout << "contact " << c.bodyA << "-" << c.bodyB << " n " << c.normal.transpose() << " depth " << c.points[0].depth << " pA " << c.points[0].pointA.transpose() << " pB " << c.points[0].pointB.transpose() << " bias " << r.bias << " m " << r.effectiveMass << " jv " << rowVelocity(r, bodies) << "\n";
    }
    std::cout << "dropped " << cr.separatingDropped << " invalid " << cr.invalidSkipped << "\n";
    for (int k = 0; k < 5; ++k) {
        solveGaussSeidel(cr.rows, bodies, 8);
        for (auto& ref : cr.points) std::cout << " imp " << cr.rows[ref.normalRow].impulse << " jv " << rowVelocity(cr.rows[ref.normalRow], bodies);
        std::cout << "\n";
    }
}
