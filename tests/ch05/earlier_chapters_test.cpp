// The promises of chapters 1 to 4, kept through chapter 5's pipeline: each scenario claim of
// the earlier suites (tests/support/earlier_chapters.h), run with the broadphase stage in front
// of the narrowphase, once with brute force and once with sweep and prune.
#include "05_sap/chapter.h"
#include "support/earlier_chapters.h"

#include <catch2/catch.hpp>

using namespace stepwise;
using namespace stepwise::test::earlier;

namespace {

/// Runs a scenario through chapter 5's pipeline with each broadphase.
void withEachBroadphase(void (*scenario)(const PipelineMaker&)) {
    for (BroadphaseMode mode : {BroadphaseMode::Brute, BroadphaseMode::Sap}) {
        INFO(toString(mode));
        scenario([mode](World& world, ContactSearch search) {
            world.settings.broadphase = mode;
            return makeChapter05Pipeline(world, chooseStepOrder(world), search);
        });
    }
}

}  // namespace

TEST_CASE("chapter 1's scenes move exactly as in chapter 1 through chapter 5's pipeline", "[ch05][earlier]") {
    withEachBroadphase(movesExactlyAsChapter1);
}

TEST_CASE("through chapter 5: Euler's projectile is g h t / 2 off the parabola, the others on it", "[ch05][earlier]") {
    withEachBroadphase(projectileOffParabola);
}

TEST_CASE("through chapter 5: the T-handle flips and keeps |L|", "[ch05][earlier]") { withEachBroadphase(tHandleFlips); }

TEST_CASE("through chapter 5: the two boxes move as in chapter 2, and the narrowphase still agrees with the oracle",
          "[ch05][earlier]") {
    withEachBroadphase(twoBoxesAsChapter2);
}

TEST_CASE("through chapter 5: the contact gallery's contacts are finite, the EPA stepper's match EPA", "[ch05][earlier]") {
    withEachBroadphase(contactGalleryFinite);
}

TEST_CASE("through chapter 5: balls bounce to e^2 h, and e = 1 never rises above its start", "[ch05][earlier]") {
    withEachBroadphase(ballsBounce);
}

TEST_CASE("through chapter 5: head-on collisions conserve momentum and obey the restitution law", "[ch05][earlier]") {
    withEachBroadphase(headOnCollisions);
}

TEST_CASE("through chapter 5: a sliding ball rolls after 2v/(7 mu g) at 5/7 of its speed; ramps hold below atan(mu)",
          "[ch05][earlier]") {
    withEachBroadphase(slidingBallAndRamps);
}

TEST_CASE("through chapter 5: a dropped ball rests at the slop; a 10 kg ball on a 1 kg ball sinks less than twice it",
          "[ch05][earlier]") {
    withEachBroadphase(restingAtSlop);
}

TEST_CASE("through chapter 5: every chapter 4 scene stays finite and above the ground", "[ch05][earlier]") {
    withEachBroadphase(chapter4ScenesFinite);
}
