// Chapter 11's pieces through the planner, whose plans for a body alone on the floor are one or two
// substeps a frame: a piece is at least a substep, so a frame whose touched body turns far takes
// more substeps than the plan's (substepsForTurns).
#include "11_wide_solve/solve_steps.h"
#include "12_planner/chapter.h"
#include "support/spun_on_floor.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace stepwise;

TEST_CASE("thin boxes spun on a floor never hold more energy than they started with, through the planner", "[ch12]") {
    for (const char* halfExtents : test::kThinBoxes)
        for (const Vec3& spin : test::kSpins)
            for (const Real bounce : {Real(0), Real(0.9)}) {
                World world = test::spunOnFloor(halfExtents, spin, bounce);
                Pipeline pipeline = makeChapter12Pipeline(world);
                const double start = computeEnergy(world).total();
                double most = start;
                int mostFrame = 0, mostSubsteps = 0;
                for (int frame = 1; frame <= 300; ++frame) {
                    pipeline.step(world);
                    mostSubsteps = std::max(mostSubsteps, world.step.iterationPlan.iterations);
                    const double now = computeEnergy(world).total();
                    if (now > most) {
                        most = now;
                        mostFrame = frame;
                    }
                }
                INFO("box " << halfExtents << ", spin " << spin.transpose() << " rad/s, restitution " << bounce << ": "
                            << start << " J at the start, " << most << " J in frame " << mostFrame << "; at most "
                            << mostSubsteps << " substeps a frame");
                CHECK(most <= start * 1.001);
            }
}

TEST_CASE("a needle spinning on the floor takes more substeps than the planner's, one piece each", "[ch12]") {
    // Resting on the world alone, the planner gives a frame one substep (kRestingSubstep); the
    // needle turns pi in it, and a piece is at least a substep.
    World world = loadSceneFromString(R"({"settings": {"ccd": "off", "sleeping": false}, "bodies": [
        {"name": "ground", "type": "static", "shape": {"box": {"half_extents": [10, 0.5, 10]}}, "position": [0, -0.5, 0]},
        {"name": "needle", "shape": {"box": {"half_extents": [0.014, 0.0065, 0.237]}}, "position": [0, 0.0065, 0],
         "mass": 1.05, "angular_velocity": [0, 188, 0]}]})");
    Pipeline pipeline = makeChapter12Pipeline(world);
    pipeline.step(world);
    pipeline.step(world);
    const Real turn = world.motionOf(1)->angularVelocity.norm() * world.settings.dt;
    INFO("turned " << turn << " rad in a frame, " << world.step.iterationPlan.iterations << " substeps");
    REQUIRE(turn > 4 * kMostTurnPerPiece);  // it turns far in a frame
    CHECK(world.step.iterationPlan.iterations >= static_cast<int>(std::floor(turn / kMostTurnPerPiece)));
}
