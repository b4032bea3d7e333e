// Exercise check for chapter 12 (`ctest -L ch12-exercise`): rewrite supportDepth in
// chapters/12_planner/iteration_plan.cpp from the page (one breadth-first search over the touching
// contacts, started from every dynamic body that touches a static or kinematic one, at depth 1),
// and run this. On columns, pyramids, two separate stacks, a body that touches nothing and a box
// lying on another without reaching the ground, the depth must be the deepest dynamic body's
// count of bodies down to a support, and each body's depth must be its own.
#include "04_pgs/scenes.h"
#include "10_skip_work/scenes.h"
#include "11_wide_solve/contact_solver.h"
#include "12_planner/chapter.h"

#include <catch2/catch.hpp>

#include <string>

using namespace stepwise;

namespace {

/// One frame through chapter 12, so that the contacts exist, then the planner's depth of them.
int depthAfterOneFrame(World& world, StackSearch& search) {
    world.settings.sleeping = false;
    Pipeline pipeline = makeChapter12Pipeline(world);
    pipeline.step(world);
    std::vector<int> contacts;
    collectSolvableContacts(world, contacts);
    return supportDepth(world, contacts, search);
}

World column(int height, Real x = 0) {
    World world = emptyWorld("column");
    addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(20, Real(0.5), 20), Quat::Identity(), Material{});
    for (int i = 0; i < height; ++i)
        addCrate(world, "box" + std::to_string(i), Vec3(x, Real(0.5) + static_cast<Real>(i), 0), Vec3::Constant(Real(0.5)), 1,
                 Material{}, Quat::Identity());
    return world;
}

}  // namespace

TEST_CASE("exercise: the depth of a stack counts its bodies down to a support", "[ch12-exercise]") {
    StackSearch search;
    for (int height : {1, 2, 5, 9}) {
        World world = column(height);
        CHECK(depthAfterOneFrame(world, search) == height);
        for (int box = 0; box < height; ++box)  // body 0 is the ground, box i is body i + 1
            CHECK(search.depth[static_cast<std::size_t>(box + 1)] == box + 1);
    }
    World pyramid = buildPyramidRow(1, 6);
    CHECK(depthAfterOneFrame(pyramid, search) == 6);

    // Two stacks side by side: the deeper one counts.
    World two = column(3);
    for (int i = 0; i < 6; ++i)
        addCrate(two, "tall" + std::to_string(i), Vec3(5, Real(0.5) + static_cast<Real>(i), 0), Vec3::Constant(Real(0.5)), 1,
                 Material{}, Quat::Identity());
    CHECK(depthAfterOneFrame(two, search) == 6);

    // Nothing touches a support: no stack at all.
    World flying = emptyWorld("flying");
    addCrate(flying, "a", Vec3(0, 5, 0), Vec3::Constant(Real(0.5)), 1, Material{}, Quat::Identity());
    addCrate(flying, "b", Vec3(0, 6, 0), Vec3::Constant(Real(0.5)), 1, Material{}, Quat::Identity());
    CHECK(depthAfterOneFrame(flying, search) == 0);
}
