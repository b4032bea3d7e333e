// The chapter's promises about stacks, at 60 Hz with the default settings, no sleeping, 10 s
// each (stacking_study.h measures): what stands, how far it drifts and sinks.
#include "06_manifolds/chapter.h"
#include "06_manifolds/scenes.h"
#include "06_manifolds/stacking_study.h"
#include "support/fixture.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

constexpr double kSeconds = 10;
constexpr double kDriftLimit = 0.01;       // m sideways
constexpr double kSinkAllowance = 0.002;   // m below the slop per contact

void requireStands(const World& world, const StackingConfig& config = {}) {
    const StackingMeasure measure = measureStacking(world, config, kSeconds);
    INFO(world.name << ": drift " << measure.maxDrift << " m, sink beyond the slop per contact " << measure.maxSinkExcess
                    << " m, deepest " << measure.maxPenetration << " m");
    CHECK(measure.stood);
    CHECK(measure.maxDrift < kDriftLimit);
    CHECK(measure.maxSinkExcess <= kSinkAllowance);
}

}  // namespace

TEST_CASE("a stack of 16 unit boxes stands: no drift over 1 cm, each sinks at most the slop per contact + 2 mm",
          "[ch06][stacking]") {
    requireStands(buildBoxStack(16));
}

TEST_CASE("a 20-row pyramid of 210 unit boxes stands by the same measure", "[ch06][stacking]") {
    requireStands(buildPyramid(20));
}

TEST_CASE("100 kg on three 1 kg boxes stands and sinks no more than the slop per contact", "[ch06][stacking]") {
    const World world = buildHeavyOnLight();
    const StackingMeasure measure = measureStacking(world, {}, kSeconds);
    INFO("drift " << measure.maxDrift << " m, sink " << measure.maxSink << " m, per contact " << measure.maxSinkPerContact);
    CHECK(measure.stood);
    CHECK(measure.maxDrift < kDriftLimit);
    CHECK(measure.maxSinkPerContact <= world.settings.slop);
}

TEST_CASE("a tower of 1, 10, 100 and 1000 kg from the top stands", "[ch06][stacking]") {
    requireStands(buildMassTower(true));
}

// Not met yet (the page gives the numbers): the default lets the 1000 kg box crush the 1 kg one,
// and soft_step's springs hold it in some runs but not all.
TEST_CASE("1000 kg on top of 100, 10 and 1 kg stands with soft_step", "[ch06][stacking][!mayfail]") {
    const World world = buildMassTower(false);
    StackingConfig soft;
    soft.stabilisation = Stabilisation::SoftStep;
    const StackingMeasure measure = measureStacking(world, soft, kSeconds);
    INFO("soft_step: drift " << measure.maxDrift << " m, sink " << measure.maxSink << " m");
    CHECK(measure.stood);
}

TEST_CASE("a box resting on a 30 degree ramp with mu 0.8 creeps less than 1 mm in 10 s", "[ch06][stacking]") {
    int box = -1;
    World world = buildStickingRamp(&box);
    const Vec3 start = world.bodies[box].transform.position;
    Pipeline pipeline = makeChapter06Pipeline(world);
    test::simulate(world, pipeline, kSeconds);
    CHECK((world.bodies[box].transform.position - start).norm() < 1e-3);
}

// Not met yet (the page gives the numbers): the 65 kg ball lands on the 1 kg box at 6 m/s, and
// without chapter 8's joint nothing keeps it there.
TEST_CASE("the contract's two-box-stack keeps its deepest overlap under twice the slop", "[ch06][stacking][!mayfail]") {
    World world = loadSceneFile("scenes/two-box-stack.json");
    REQUIRE(world.name == "two-box-stack");
    Pipeline pipeline = makeChapter06Pipeline(world);
    double deepest = 0;
    test::simulate(world, pipeline, kSeconds,
                   [&](const World& w) { deepest = std::max(deepest, static_cast<double>(measureDeepestPenetration(w))); });
    INFO("deepest " << deepest << " m");
    CHECK(deepest < 2 * world.settings.slop);
    CHECK(deepest > 0);  // the ball did land on the box
}

TEST_CASE("without warm starting the same stacks do measurably worse", "[ch06][stacking][warm]") {
    StackingConfig cold;
    cold.warmStarting = false;
    for (World (*build)() : {+[] { return buildBoxStack(16); }, +[] { return buildHeavyOnLight(); }}) {
        const World world = build();
        const StackingMeasure warm = measureStacking(world, {}, kSeconds);
        const StackingMeasure coldMeasure = measureStacking(world, cold, kSeconds);
        INFO(world.name << ": drift " << warm.maxDrift << " m warm, " << coldMeasure.maxDrift << " m cold; sink "
                        << warm.maxSink << " m warm, " << coldMeasure.maxSink << " m cold");
        CHECK(coldMeasure.maxDrift + coldMeasure.maxSink > 3 * (warm.maxDrift + warm.maxSink) + 1e-3);
    }
}
