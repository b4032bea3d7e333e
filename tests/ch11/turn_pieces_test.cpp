// Chapter 11's pieces: a frame's solve builds its rows again wherever a body a contact touches has
// turned kMostTurnPerPiece, so that a thin body spinning on the floor cannot be pushed through
// arms and an inverse inertia it no longer has.
#include "11_wide_solve/chapter.h"
#include "11_wide_solve/solve_steps.h"
#include "support/spun_on_floor.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace stepwise;

TEST_CASE("thin boxes spun on a floor never hold more energy than they started with", "[ch11][fast]") {
    // With the frame's rows built once (one piece a frame), a needle spun at (0, 120, 150) rad/s
    // went from 152 J to 15,000 J in its seventh frame: a half turn a frame leaves its arms
    // pointing elsewhere and its heavy axis where its light one was.
    for (const char* halfExtents : test::kThinBoxes)
        for (const Vec3& spin : test::kSpins)
            for (const Real bounce : {Real(0), Real(0.9)})
                for (const SolverPath path : {SolverPath::Wide, SolverPath::Scalar}) {
                    World world = test::spunOnFloor(halfExtents, spin, bounce);
                    WideSolveOptions wide;
                    wide.solverPath = path;
                    Pipeline pipeline = makeChapter11Pipeline(world, SkipWorkOptions{}, wide);
                    const double start = computeEnergy(world).total();
                    double most = start;
                    int mostFrame = 0;
                    for (int frame = 1; frame <= 300; ++frame) {
                        pipeline.step(world);
                        const double now = computeEnergy(world).total();
                        if (now > most) {
                            most = now;
                            mostFrame = frame;
                        }
                    }
                    INFO("box " << halfExtents << ", spin " << spin.transpose() << " rad/s, restitution " << bounce
                                << ", " << toString(path) << ": " << start
                                << " J at the start, " << most << " J in frame " << mostFrame);
                    CHECK(most <= start * 1.001);
                }
}

TEST_CASE("a touched body turning far splits the frame's solve into pieces, and a quiet one does not", "[ch11][fast]") {
    WideSolveOptions wide;
    wide.profile = std::make_shared<FastSolveStats>();
    SECTION("a needle spinning at 188 rad/s on the floor") {
        World world = loadSceneFromString(R"({"settings": {"ccd": "off", "sleeping": false}, "bodies": [
            {"name": "ground", "type": "static", "shape": {"box": {"half_extents": [10, 0.5, 10]}}, "position": [0, -0.5, 0]},
            {"name": "needle", "shape": {"box": {"half_extents": [0.014, 0.0065, 0.237]}}, "position": [0, 0.0065, 0],
             "mass": 1.05, "angular_velocity": [0, 188, 0]}]})");  // lying on the floor, spinning about the vertical
        Pipeline pipeline = makeChapter11Pipeline(world, SkipWorkOptions{}, wide);
        pipeline.step(world);  // the contact found, the solve of the first frame
        wide.profile->pieces = 0;
        pipeline.step(world);
        const Real turn = world.motionOf(1)->angularVelocity.norm() * world.settings.dt;
        INFO("turned " << turn << " rad in the frame, " << wide.profile->pieces << " pieces, "
                       << world.step.iterationPlan.iterations << " substeps");
        REQUIRE(turn > 4 * kMostTurnPerPiece);  // it turns far in a frame
        CHECK(wide.profile->pieces >= static_cast<int>(std::floor(turn / kMostTurnPerPiece)));
        CHECK(wide.profile->pieces <= world.step.iterationPlan.iterations);
    }
    SECTION("a box resting on the floor") {
        World world = loadSceneFromString(R"({"settings": {"sleeping": false}, "bodies": [
            {"name": "ground", "type": "static", "shape": {"box": {"half_extents": [10, 0.5, 10]}}, "position": [0, -0.5, 0]},
            {"name": "box", "shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}}, "position": [0, 0.5, 0]}]})");
        Pipeline pipeline = makeChapter11Pipeline(world, SkipWorkOptions{}, wide);
        for (int frame = 0; frame < 30; ++frame) pipeline.step(world);
        CHECK(wide.profile->pieces == 30);
    }
}
