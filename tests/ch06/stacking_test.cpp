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

// Measured, as the issue asks, and pinned as the page reports it: a mass ratio of 1000 that a few
// rigid sweeps cannot carry. The rigid stabilisations let the 1000 kg box crush the tower within
// 10 s, the top box ending half a metre or more lower; soft_step's springs (static contacts twice as stiff)
// hold it, the top box sagging some 9 cm. If that ever changes, this fails and the page's table
// must change with it.
TEST_CASE("1000 kg on top of 100, 10 and 1 kg: soft_step holds it, the rigid stabilisations let it fall",
          "[ch06][stacking]") {
    const World world = buildMassTower(false);
    for (Stabilisation stabilisation :
         {Stabilisation::Relax, Stabilisation::Baumgarte, Stabilisation::SplitImpulse, Stabilisation::SoftStep}) {
        StackingConfig config;
        config.stabilisation = stabilisation;
        const StackingMeasure measure = measureStacking(world, config, kSeconds);
        INFO(toString(stabilisation) << ": drift " << measure.maxDrift << " m, sink " << measure.maxSink << " m, top "
                                     << measure.topHeightStart << " m -> " << measure.topHeightEnd << " m");
        if (stabilisation == Stabilisation::SoftStep) {
            CHECK(measure.stood);
            CHECK(measure.topHeightEnd > measure.topHeightStart - 0.15);
        } else {
            CHECK(!measure.stood);
            // Crushed: the top box ends half a metre or more lower (where the wreck leaves it: on the
            // ground, or on a box that fell over).
            CHECK(measure.topHeightEnd < measure.topHeightStart - Real(0.5));
        }
    }
}

// Not met (docs/ch06_manifolds.md says so and gives the numbers): the 65 kg ball lands at 6 m/s on
// the 1 kg box and, without its joint (chapter 8 solves it: tests/ch08/contract_scene_test.cpp), nothing keeps it there. Pinned as measured:
// the deepest overlap exceeds the contract's twice the slop but stays within the band the page
// reports, and the ball ends resting on the ground, off the box.
TEST_CASE("the contract's two-box-stack: the ball rolls off the box, its deepest overlap as the page reports",
          "[ch06][stacking]") {
    World world = loadSceneFile("scenes/two-box-stack.json");
    REQUIRE(world.name == "two-box-stack");
    const int ball = world.findBody("ball");
    REQUIRE(ball >= 0);
    Pipeline pipeline = makeChapter06Pipeline(world);
    double deepest = 0;
    test::simulate(world, pipeline, kSeconds,
                   [&](const World& w) { deepest = std::max(deepest, static_cast<double>(measureDeepestPenetration(w))); });
    const double ballHeight = world.bodies[ball].transform.position.y();
    INFO("deepest " << deepest << " m; the ball ends at height " << ballHeight << " m");
    CHECK(deepest > 2 * world.settings.slop);  // the contract's target is not met ...
    CHECK(deepest < 0.08);                     // ... by the margin the page gives (4-5 cm)
    CHECK(std::abs(ballHeight - world.bodies[ball].shape.radius) < 2 * world.settings.slop);  // on the ground
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
