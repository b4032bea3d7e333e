// Bounces in the planned solve: restitution may only take energy, however few substeps the
// planner takes and however far a body turns in them.
#include "12_planner/chapter.h"
#include "support/most_energy.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

using namespace stepwise;

TEST_CASE("restitution reverses an approach along the row it was read on", "[ch12][solve]") {
    // Found by fuzz_stepper: a 10 t box 4 m across, restitution 0.9, spinning at 10.5 rad/s (its
    // corners at 36 m/s) above the ground beside a 9 t cylinder; the planner takes two substeps
    // while nothing rests on anything. The sweeps read each point's approach along the solve's
    // rows (the frame-start arms); restitution after the substeps, met along the row as the box
    // is turned now, set a speed the row never had: 193 kJ from nowhere in one frame. Restitution
    // keeps the solve's rows; collisions, whose speed is read and met on one turned row, keep theirs.
    for (SolverPath path : {SolverPath::Wide, SolverPath::Scalar}) {
        World world = loadSceneFile("tests/ch12/data/heavy-spinning-box-bounces.json");
        SpeedOptions options;
        options.solverPath = path;
        Pipeline pipeline = makeChapter12Pipeline(world, options);
        const double start = computeEnergy(world).total();
        const double most = test::mostEnergyOver(world, pipeline, 100);
        INFO((path == SolverPath::Wide ? "wide" : "scalar") << ": energy " << start << " J, most in any frame " << most
                                                            << " J, after 100 frames " << computeEnergy(world).total() << " J");
        CHECK(most <= start);
    }
}
