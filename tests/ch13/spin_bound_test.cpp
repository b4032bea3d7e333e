// A body the solve may not spin faster than its rows can follow, in the scene the stepper's
// fuzzer found: a needle on a rod to a heavy compound, spun up by its landings.
#include "13_worlds/chapter.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace stepwise;

TEST_CASE("a needle on a rod spun by its landings never gains energy through chapter 13", "[ch13][fast]") {
    // A 0.11 kg box 47 cm long on a 1.5 m distance joint to a 66 kg compound, beside a cylinder
    // and two capsules. Chapter 7's impact stage, after the solve, spun the needle to 378 rad/s;
    // the next solve took it whole into its first substep's rows (built once a frame, with the
    // frame's inverse inertia) and threw the needle off at 1,680 m/s: 2,450 J to 178,000 J in one
    // frame. The solve holds every body's spin as it begins, as it ends and before each position
    // step, to half a turn a solve (kMostTurnPerSolve) and an eighth of a turn a substep.
    World world = loadSceneFile("tests/ch13/data/needle-on-a-rod.json");
    Pipeline pipeline = makeChapter13Pipeline(world);
    const double start = computeEnergy(world).total();
    double most = start;
    for (int frame = 0; frame < 100; ++frame) {
        pipeline.step(world);
        most = std::max(most, computeEnergy(world).total());
    }
    INFO("energy " << start << " J, most in any frame " << most << " J, after 100 frames "
                   << computeEnergy(world).total() << " J");
    CHECK(most <= start);
}
