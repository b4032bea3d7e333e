// Chapter 11's relax sweep where a swept stack's plan asks for it (relaxSweepNeeded): after a push
// out of a point deeper than the slop, and in the last substep.
#include "11_wide_solve/contact_solver.h"
#include "12_planner/chapter.h"
#include "12_planner/plan_constants.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <memory>

using namespace stepwise;

namespace {

World restingPyramid() { return loadSceneFile("scenes/reference/pyramid-20.json"); }

/// One frame of chapter 12's step: the plan, and the relax sweeps the solve ran.
struct ProfiledFrame {
    IterationPlan plan;
    int relaxSweeps = 0;
};

ProfiledFrame stepOnceProfiled(World& world) {
    SpeedOptions options;
    options.profile = std::make_shared<FastSolveStats>();
    Pipeline pipeline = makeChapter12Pipeline(world, options);
    pipeline.step(world);
    return {world.step.iterationPlan, options.profile->relaxSweeps};
}

}  // namespace

TEST_CASE("a swept stack at rest relaxes in its last substep alone", "[ch12][solve]") {
    // The 20-row pyramid rests within the slop everywhere: no biased sweep pushes, so only the last
    // substep relaxes, and the planner takes sqrt(2) times the relaxed law's 3.34 substeps.
    World pyramid = restingPyramid();
    const ProfiledFrame frame = stepOnceProfiled(pyramid);
    CHECK(frame.plan.shockPropagation);
    CHECK(frame.plan.relaxOnlyAfterPush);
    CHECK(frame.plan.iterations == 5);  // 3.34 x 1.414 = 4.7
    CHECK(frame.relaxSweeps == 1);
}

TEST_CASE("a swept stack relaxes every substep in which a point lies deeper than the slop", "[ch12][solve]") {
    // The top box of the pyramid pressed 2 cm into the two under it (the slop is 5 mm): each
    // biased sweep pushes it out, and each substep takes that push back.
    World pressed = restingPyramid();
    Body* top = nullptr;
    for (Body& body : pressed.bodies)
        if (body.type == BodyType::Dynamic && (!top || body.transform.position.y() > top->transform.position.y())) top = &body;
    REQUIRE(top);
    top->transform.position.y() -= Real(0.02);
    const ProfiledFrame frame = stepOnceProfiled(pressed);
    CHECK(frame.plan.relaxOnlyAfterPush);
    CHECK(frame.relaxSweeps == frame.plan.iterations);
}

TEST_CASE("a swept stack with restitution relaxes every substep at the relaxed law's count", "[ch12][solve]") {
    // Restitution reads the approach speeds the relax sweep keeps: such a stack's substeps all
    // relax, and the planner keeps the relaxed law's four.
    World bouncy = restingPyramid();
    for (Body& body : bouncy.bodies) body.material.restitution = Real(0.2);
    const ProfiledFrame frame = stepOnceProfiled(bouncy);
    CHECK(frame.plan.shockPropagation);
    CHECK_FALSE(frame.plan.relaxOnlyAfterPush);
    CHECK(frame.plan.iterations == 4);
    CHECK(frame.relaxSweeps == 4);
}
