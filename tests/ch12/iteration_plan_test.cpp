// Chapter 12's planner for solver_iterations "auto": more substeps where unlike masses rest on one another
// by more than 200 to 1 and for stacks over 20 bodies deep, the scene's ten elsewhere; a change of
// count carries the same forces over.
#include "12_planner/chapter.h"
#include "12_planner/iteration_plan.h"
#include "12_planner/plan_constants.h"
#include "11_wide_solve/lanes.h"
#include "world/report.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

using namespace stepwise;

namespace {

/// Four 1 m boxes, by default of 1, 10, 100 and 1000 kg with the heaviest on top
/// (scenes/reference/mass-ratio-tower.json).
World tower(const std::string& iterations, const std::array<int, 4>& masses = {1, 10, 100, 1000}) {
    std::string boxes;
    for (int i = 0; i < 4; ++i) {
        boxes += R"(, {"name": "box)" + std::to_string(i) + R"(", "shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}}, "position": [0, )" +
                 std::to_string(i) + R"(.5, 0], "mass": )" + std::to_string(masses[std::size_t(i)]) + "}";
    }
    return loadSceneFromString(R"({"name": "tower", "settings": {"solver_iterations": )" + iterations + R"(}, "bodies": [
        {"name": "ground", "type": "static", "shape": {"box": {"half_extents": [50, 0.5, 50]}}, "position": [0, -0.5, 0]})" +
                               boxes + "]}");
}

struct Standing {
    Real drift = 0;  // largest sideways move of a box, m
    Real sag = 0;    // largest drop of a box, m
};

Standing runFiveSeconds(World& world, const SpeedOptions& options = SpeedOptions{}) {
    Pipeline pipeline = makeChapter12Pipeline(world, options);
    const World start = world;
    Standing standing;
    for (int frame = 0; frame < 300; ++frame) {
        pipeline.step(world);
        for (std::size_t i = 1; i < world.bodies.size(); ++i) {
            const Vec3 move = world.bodies[i].transform.position - start.bodies[i].transform.position;
            standing.drift = std::max(standing.drift, std::hypot(move.x(), move.z()));
            standing.sag = std::max(standing.sag, -move.y());
        }
    }
    return standing;
}

}  // namespace

TEST_CASE("solver_iterations auto: a 1:1000 tower stands, where the scene's ten let it fall", "[ch12][solve]") {
    World automatic = tower(R"("auto")");
    const Standing held = runFiveSeconds(automatic);
    INFO("auto: drift " << held.drift << " m, sag " << held.sag << " m");
    CHECK(held.drift < Real(0.01));
    CHECK(held.sag < Real(0.04));
    // 10 x sqrt(1000 / 200) = 22.4 (planner-fits section 1: it stands from 21), and no shock
    // sweep (unlike masses)
    CHECK(automatic.step.iterationPlan.mostIterations == 23);
    CHECK(automatic.step.iterationPlan.shockFrames == 0);
    CHECK(automatic.step.iterationPlan.largestRatio == Approx(1000));
    CHECK(describeIterationPlan(automatic).find("auto: up to 23") == 0);
    // The report quotes the planner's own thresholds (plan_constants.h), which the plan carries.
    const PlanThresholds& quoted = automatic.step.iterationPlan.thresholds;
    CHECK(quoted.plainMassRatio == kPlainMassRatio);
    CHECK(quoted.fewestUnlikeSubsteps == kFewestUnlikeSubsteps);
    const std::string ratio = std::to_string(static_cast<int>(kPlainMassRatio));
    CHECK(describeIterationPlan(automatic).find("over " + ratio + " to 1") != std::string::npos);
    CHECK(planReasonText(PlanReason::MassRatio, quoted).find("over " + ratio + " times lighter") != std::string::npos);
    CHECK(planReasonText(PlanReason::UnlikeStack, quoted).find("at least " + std::to_string(kFewestUnlikeSubsteps)) !=
          std::string::npos);

    // 10 written out is the format's default, so it plans as "auto" does; plan_iterations false
    // holds the count at ten.
    World stated = tower("10");
    const Standing statedHeld = runFiveSeconds(stated);
    CHECK(statedHeld.drift == held.drift);
    CHECK(stated.step.iterationPlan.mostIterations == 23);

    World ten = tower(R"(10, "plan_iterations": false)");
    const Standing fell = runFiveSeconds(ten);
    INFO("10: drift " << fell.drift << " m, sag " << fell.sag << " m");
    CHECK((fell.sag > Real(1) || fell.drift > Real(1)));  // it does not stand: crushed, or walked a metre off its base
    CHECK(ten.step.iterationPlan.mostIterations == 10);
    CHECK(describeIterationPlan(ten).find("the scene's solver_iterations") != std::string::npos);
}

TEST_CASE("solver_iterations auto takes no more than ten substeps for masses resting on lighter ones within 200 to 1", "[ch12][solve]") {
    // 100 kg on 10 on 1 (chapter 6's heavy-on-light), four deep: 10 sqrt(100 / 200) = 7.1 asks
    // for eight substeps, and the tower stands (planner-fits section 1: from six).
    World world = tower(R"("auto")", {1, 10, 100, 100});
    const Standing standing = runFiveSeconds(world);
    INFO("drift " << standing.drift << " m, sag " << standing.sag << " m");
    CHECK(standing.drift < Real(0.01));
    CHECK(standing.sag < Real(0.04));
    CHECK(world.step.iterationPlan.mostIterations == 8);
}

TEST_CASE("solver_iterations auto: a shallow heap of unlike masses takes the square-root law below 200 to 1, a deep one ten", "[ch12][solve]") {
    // 10 kg on 5 on 2 on 1: the load paths read 10, and 10 sqrt(10 / 200) = 2.2 asks for three
    // substeps, kFewestUnlikeSubsteps (planner-fits section 5: such a tower stands from three).
    World shallow = tower(R"("auto")", {1, 2, 5, 10});
    const Standing standing = runFiveSeconds(shallow);
    INFO("drift " << standing.drift << " m, sag " << standing.sag << " m");
    CHECK(standing.drift < Real(0.01));
    CHECK(standing.sag < Real(0.04));
    const IterationPlan& plan = shallow.step.iterationPlan;
    CHECK(plan.iterations == kFewestUnlikeSubsteps);
    CHECK(plan.reason == PlanReason::UnlikeStack);
    CHECK(plan.largestRatio == Approx(10));

    // Eight boxes of 1 and 3 kg in turn, deeper than kShallowUnlikeDepth: the scene's count.
    std::string boxes;
    for (int i = 0; i < 8; ++i)
        boxes += R"(, {"name": "box)" + std::to_string(i) + R"(", "shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}}, "position": [0, )" +
                 std::to_string(i) + R"(.5, 0], "mass": )" + (i % 2 ? "3" : "1") + "}";
    World deep = loadSceneFromString(R"({"name": "column", "bodies": [
        {"name": "ground", "type": "static", "shape": {"box": {"half_extents": [50, 0.5, 50]}}, "position": [0, -0.5, 0]})" +
                                     boxes + "]}");
    const Standing column = runFiveSeconds(deep);
    INFO("column: drift " << column.drift << " m, sag " << column.sag << " m");
    CHECK(column.drift < Real(0.01));
    CHECK(deep.step.iterationPlan.stackDepth > kShallowUnlikeDepth);
    CHECK(deep.step.iterationPlan.iterations == 10);
    CHECK(deep.step.iterationPlan.reason == PlanReason::UnlikeStack);
}

namespace {

/// A reference scene (the suites run in the source tree).
World sceneFile(const std::string& name) { return loadSceneFile("scenes/reference/" + name); }

/// The deepest stack of the world's current contacts, as the planner counts it.
int depthNow(const World& world) {
    std::vector<int> order(world.contacts.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    StackSearch search;
    return supportDepth(world, order, search);
}

}  // namespace

TEST_CASE("the planner counts a stack's depth from its support", "[ch12][solve]") {
    World pyramid = sceneFile("pyramid-40.json");
    Pipeline pipeline = makeChapter12Pipeline(pyramid, SpeedOptions{});
    pipeline.step(pyramid);
    CHECK(depthNow(pyramid) == 40);  // the top box rests on 39 rows and the ground

    World stack = sceneFile("stack-16.json");
    Pipeline stackPipeline = makeChapter12Pipeline(stack, SpeedOptions{});
    stackPipeline.step(stack);
    CHECK(depthNow(stack) == 16);
    CHECK(stack.step.iterationPlan.stackDepth == 16);
    // Like masses and nothing bouncing, but a column: its sweep would be fifteen one-lane blocks
    // against the frame's two, about ten substeps, for the one it saves (3.34 x 0.8^0.7 = 2.85
    // with it, 10 x 0.8^2 x sqrt(0.3) = 3.5 without).
    CHECK(!stack.step.iterationPlan.shockPropagation);
    CHECK(stack.step.iterationPlan.iterations == 4);
}

TEST_CASE("the planner prices the shock sweep in substeps by the blocks it would build", "[ch12][solve]") {
    const auto sweepCost = [](World world) {
        Pipeline pipeline = makeChapter12Pipeline(world, SpeedOptions{});
        pipeline.step(world);
        std::vector<int> order(world.contacts.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
        StackSearch search;
        supportDepth(world, order, search);
        return shockSweepSubsteps(world, order, search);
    };
    // The column: 15 layers of one contact (the ground's is not swept), one-lane blocks, against
    // 16 / kPricedLanes blocks in the frame (two of eight floats, four of four doubles; the planner
    // prices 256-bit blocks in every build).
    const Real column = 15 * kShockLaneBlocks * kShockBlockSubsteps / Real(16 / kPricedLanes);
    CHECK(sweepCost(sceneFile("stack-16.json")) == Approx(column));
    // The 20-row pyramid: each layer in two groups (a box rests on two), about as many blocks as
    // the frame has, so a few substeps.
    const Real pyramid = sweepCost(sceneFile("pyramid-20.json"));
    CHECK(pyramid > Real(2));
    CHECK(pyramid < Real(4));
    World pyramidWorld = sceneFile("pyramid-20.json");
    Pipeline pipeline = makeChapter12Pipeline(pyramidWorld, SpeedOptions{});
    pipeline.step(pyramidWorld);
    CHECK(pyramidWorld.step.iterationPlan.shockPropagation);
    CHECK(pyramidWorld.step.iterationPlan.iterations == 5);  // one-sweep substeps: 3.34 x sqrt(2) = 4.7
}

TEST_CASE("solver_iterations auto holds a stack's substep length at another frame rate", "[ch12][solve]") {
    // The laws were measured at 60 Hz: at 30 Hz a 20-row pyramid takes 3.34 x 2 x sqrt(2) = 9.4
    // one-sweep substeps, ten, and walks about as it does at 60 Hz (kHeldStackDrift bounds both);
    // at 120 Hz, 10 x 0.55 / 2, three without the sweep.
    World thirty = sceneFile("pyramid-20.json");
    thirty.settings.dt = Real(1) / Real(30);
    Pipeline pipeline = makeChapter12Pipeline(thirty, SpeedOptions{});
    const World start = thirty;
    Real drift = 0;
    for (int frame = 0; frame < 150; ++frame) {  // five seconds
        pipeline.step(thirty);
        for (std::size_t i = 1; i < thirty.bodies.size(); ++i) {
            const Vec3 move = thirty.bodies[i].transform.position - start.bodies[i].transform.position;
            drift = std::max(drift, std::hypot(move.x(), move.z()));
        }
    }
    INFO("drift at 30 Hz: " << drift << " m");
    CHECK(thirty.step.iterationPlan.mostIterations == 10);
    CHECK(thirty.step.iterationPlan.shockFrames > 0);
    CHECK(drift < kHeldStackDrift);

    World oneTwenty = sceneFile("pyramid-20.json");
    oneTwenty.settings.dt = Real(1) / Real(120);
    Pipeline fast = makeChapter12Pipeline(oneTwenty, SpeedOptions{});
    fast.step(oneTwenty);
    CHECK(oneTwenty.step.iterationPlan.iterations == 3);
    CHECK(!oneTwenty.step.iterationPlan.shockPropagation);
}

TEST_CASE("solver_iterations auto counts a stack of like masses by its depth", "[ch12][solve]") {
    // Four boxes of 1 kg: 10 x (4 / 20)^2 x 0.55 is under one, and a stack takes at least two;
    // the boxes sink 3.6 mm in all (within the slop at each contact), 14 mm at one substep.
    World four = tower(R"("auto")", {1, 1, 1, 1});
    const Standing standing = runFiveSeconds(four);
    INFO("drift " << standing.drift << " m, sag " << standing.sag << " m");
    CHECK(four.step.iterationPlan.mostIterations == kFewestStackSubsteps);
    CHECK(standing.drift < Real(1e-4));
    CHECK(standing.sag < Real(0.005));
    // A 20-row pyramid with the shock sweep: 3.34 relaxed substeps' worth, 4.7 of one sweep (five),
    // and it walks under 20 x kHeldWalkPerBody = 2.5 mm.
    World pyramid = sceneFile("pyramid-20.json");
    const Standing pyramidHeld = runFiveSeconds(pyramid);
    INFO("pyramid-20: drift " << pyramidHeld.drift << " m, sag " << pyramidHeld.sag << " m");
    CHECK(pyramid.step.iterationPlan.mostIterations == 5);
    CHECK(pyramid.step.iterationPlan.shockFrames > 0);  // until it sleeps
    CHECK(pyramidHeld.drift < 20 * kHeldWalkPerBody);
}

TEST_CASE("solver_iterations auto takes fewer substeps where no load passes from body to body", "[ch12][solve]") {
    // Free flight: one substep of 1/60 s (the centre's parabola is exact); a block sliding down the
    // ramp, which rests on the world alone: two once its friction drags it (the first frame has no
    // impulses yet); a ball rolling steadily: one; at 1/30 s twice as many, the same work a second.
    for (const Real dt : {Real(1) / Real(60), Real(1) / Real(30)}) {
        const int perSixtieth = dt > Real(1) / Real(60) ? 2 : 1;
        World projectile = sceneFile("projectile.json");
        projectile.settings.dt = dt;
        Pipeline flight = makeChapter12Pipeline(projectile, SpeedOptions{});
        flight.step(projectile);
        CHECK(projectile.step.iterationPlan.iterations == perSixtieth);

        World ramp = sceneFile("ramp.json");
        ramp.settings.dt = dt;
        Pipeline rampPipeline = makeChapter12Pipeline(ramp, SpeedOptions{});
        for (int frame = 0; frame < 10; ++frame) rampPipeline.step(ramp);
        REQUIRE(!ramp.contacts.empty());
        CHECK(ramp.step.iterationPlan.stackDepth == 1);
        CHECK(ramp.step.iterationPlan.iterations == 2 * perSixtieth);
        CHECK(describeIterationPlan(ramp).find("auto: " + std::to_string(perSixtieth) + " to " +
                                               std::to_string(2 * perSixtieth) + " by what touches") == 0);

        World ball = sceneFile("slide-to-roll.json");
        ball.settings.dt = dt;
        Pipeline ballPipeline = makeChapter12Pipeline(ball, SpeedOptions{});
        const auto frames = static_cast<int>(std::lround(Real(0.1) / dt));  // skidding for 0.29 s
        for (int frame = 0; frame < frames; ++frame) ballPipeline.step(ball);
        CHECK(ball.step.iterationPlan.iterations == 2 * perSixtieth);
        for (int frame = 0; frame < 4 * frames; ++frame) ballPipeline.step(ball);  // rolling at 5/7 v
        REQUIRE(!ball.contacts.empty());
        CHECK(ball.step.iterationPlan.iterations == perSixtieth);
    }
    // A box on a box is a load carried: at least kFewestStackSubsteps, and a frame in which a ball
    // arrives bouncing takes the scene's ten (chapter 4's elastic ball would rise above its start
    // at fewer).
    World two = tower(R"("auto")", {1, 1, 1, 1});
    Pipeline towerPipeline = makeChapter12Pipeline(two, SpeedOptions{});
    towerPipeline.step(two);
    CHECK(two.step.iterationPlan.iterations == kFewestStackSubsteps);
    World bounce = sceneFile("bouncing-ball.json");
    Pipeline bouncePipeline = makeChapter12Pipeline(bounce, SpeedOptions{});
    int arrivals = 0, departures = 0;
    for (int frame = 0; frame < 120; ++frame) {
        const Real fallSpeed = -bounce.motionOf(1)->linearVelocity.y();  // the ball, before the frame's forces
        bouncePipeline.step(bounce);
        if (bounce.contacts.empty()) continue;
        if (fallSpeed > bounce.settings.restitutionThreshold) {
            ++arrivals;
            CHECK(bounce.step.iterationPlan.iterations == 10);
        } else if (fallSpeed < 0) {
            ++departures;  // rising off the floor: nothing arrives, nothing bounces
            CHECK(bounce.step.iterationPlan.iterations == 1);
        }
    }
    CHECK(arrivals > 0);
    CHECK(departures > 0);
    CHECK(bounce.step.iterationPlan.fewestIterations == 1);
}

TEST_CASE("solver_iterations auto keeps ten substeps for the frame a cradle is struck, one between", "[ch12][solve]") {
    // The middle balls rest against one another with restitution 1: they bounce only when the
    // first ball arrives, and the strike must still pass on whole.
    World cradle = sceneFile("newtons-cradle.json");
    Pipeline pipeline = makeChapter12Pipeline(cradle, SpeedOptions{});
    int struck = 0, resting = 0;
    for (int frame = 0; frame < 60; ++frame) {
        pipeline.step(cradle);
        if (cradle.contacts.empty()) continue;
        if (cradle.step.iterationPlan.iterations == 10) ++struck;
        if (cradle.step.iterationPlan.iterations == 1) ++resting;
    }
    CHECK(struck >= 1);
    CHECK(struck <= 3);   // the strike and the speculative frames before it
    CHECK(resting > 40);
    CHECK(cradle.motionOf(4)->linearVelocity.x() == Approx(2.0).margin(0.02));
    CHECK(cradle.motionOf(0)->linearVelocity.norm() < Real(0.02));
}

TEST_CASE("solver_iterations auto holds what hangs by joints to its sag: four substeps for a pendulum, 18 for a chain", "[ch12][solve]") {
    World pendulum = sceneFile("hinge-pendulum.json");
    Pipeline pendulumPipeline = makeChapter12Pipeline(pendulum, SpeedOptions{});
    for (int frame = 0; frame < 30; ++frame) pendulumPipeline.step(pendulum);
    CHECK(pendulum.step.iterationPlan.stackDepth == 1);  // the bob hangs from the static pivot
    // 10 sqrt(1/20 x 0.000884 / 0.0003) = 3.8: four substeps.
    CHECK(pendulum.step.iterationPlan.mostIterations == 4);
    CHECK(pendulum.settings.solverIterations == 10);     // the scene's setting, as it was

    World chain = sceneFile("hanging-chain.json");
    Pipeline chainPipeline = makeChapter12Pipeline(chain, SpeedOptions{});
    chainPipeline.step(chain);
    CHECK(chain.step.iterationPlan.stackDepth == 20);    // twenty links below the anchor
    CHECK(chain.step.iterationPlan.iterations == 18);    // 10 sqrt(0.000884 / 0.0003) = 17.2

    World fixed = sceneFile("hinge-pendulum.json");
    fixed.settings.planIterations = false;
    Pipeline fixedPipeline = makeChapter12Pipeline(fixed, SpeedOptions{});
    fixedPipeline.step(fixed);
    CHECK(fixed.step.iterationPlan.iterations == 10);     // a number in the scene: the scene's count
}

TEST_CASE("a body in free flight follows its parabola exactly in one substep", "[ch12][solve]") {
    World world = sceneFile("projectile.json");
    const World launch = world;
    Pipeline pipeline = makeChapter12Pipeline(world, SpeedOptions{});
    for (int frame = 0; frame < 60; ++frame) pipeline.step(world);
    const Real t = Real(60) * world.settings.dt;
    const Vec3 start = launch.bodies[0].transform.position;
    const Vec3 velocity = launch.motions[0].linearVelocity;
    const Vec3 exact = start + velocity * t + Real(0.5) * world.settings.gravity * t * t;
    // Euler at one substep would be g h t / 2 = 8 cm low; float rounding over 60 frames is far less.
    CHECK((world.bodies[0].transform.position - exact).norm() < Real(1e-4));
    CHECK(world.step.iterationPlan.mostIterations == 1);
}

TEST_CASE("solver_iterations auto: a 40-row pyramid stands, where the scene's ten let its top rows sway", "[ch12][solve]") {
    World automatic = sceneFile("pyramid-40.json");
    const Standing held = runFiveSeconds(automatic);
    INFO("auto: drift " << held.drift << " m, sag " << held.sag << " m");
    CHECK(held.drift < Real(0.01));
    CHECK(held.drift < 40 * kHeldWalkPerBody);  // the planner holds 5 mm
    // With the shock sweep, 3.34 x 2^0.7 = 5.4 relaxed substeps, 7.7 of one sweep
    CHECK(automatic.step.iterationPlan.mostIterations == 8);
    CHECK(automatic.step.iterationPlan.deepestStack == 40);
    CHECK(describeIterationPlan(automatic).find("a shock sweep up the stack (40 deep) ended") != std::string::npos);

    // The same substeps without the sweep: the top rows walk over a centimetre.
    World unshocked = sceneFile("pyramid-40.json");
    SpeedOptions noShock;
    noShock.shockPropagation = false;
    const Standing walked = runFiveSeconds(unshocked, noShock);
    INFO("no shock sweep: drift " << walked.drift << " m");
    CHECK(unshocked.step.iterationPlan.mostIterations == 8);
    CHECK(unshocked.step.iterationPlan.shockFrames == 0);
    CHECK(walked.drift > Real(0.01));

    World ten = sceneFile("pyramid-40.json");
    ten.settings.planIterations = false;
    const Standing swayed = runFiveSeconds(ten);
    INFO("10: drift " << swayed.drift << " m");
    CHECK(swayed.drift > Real(0.015));
}

TEST_CASE("a change of substep count carries the same forces into the next frame", "[ch12][solve]") {
    // A settled 16-box stack whose count goes from 10 to 20: the impulses carried from the last
    // frame are per substep, and are halved with it, so nothing jumps.
    World stack = sceneFile("stack-16.json");
    stack.settings.planIterations = false;
    stack.settings.sleeping = false;
    Pipeline pipeline = makeChapter12Pipeline(stack, SpeedOptions{});
    for (int frame = 0; frame < 120; ++frame) pipeline.step(stack);
    stack.settings.solverIterations = 20;
    pipeline.step(stack);
    Real fastest = 0;
    for (const Motion& motion : stack.motions) fastest = std::max(fastest, motion.linearVelocity.norm());
    INFO("fastest box after the change: " << fastest << " m/s");
    CHECK(fastest < Real(0.01));
}
