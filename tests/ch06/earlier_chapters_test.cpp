// The promises of chapters 1 to 4, kept through chapter 6's pipeline: each scenario claim of
// the earlier suites (tests/support/earlier_chapters.h), run with manifolds, warm starting and the
// default stabilisation, once with up to four points per pair and once with chapter 3's one.
#include "06_manifolds/chapter.h"
#include "support/earlier_chapters.h"

#include <catch2/catch.hpp>

using namespace stepwise;
using namespace stepwise::test::earlier;

namespace {

/// Runs a scenario through chapter 6's pipeline with each broadphase.
void withEachManifold(void (*scenario)(const PipelineMaker&)) {
    for (BroadphaseMode mode : {BroadphaseMode::Brute, BroadphaseMode::Sap}) {
        INFO(toString(mode));
        scenario([mode](World& world, ContactSearch search) {
            world.settings.broadphase = mode;
            return makeChapter05Pipeline(world, chooseStepOrder(world), search);
        });
    }
}

}  // namespace

TEST_CASE("chapter 1's scenes move exactly as in chapter 1 through chapter 6's pipeline", "[ch06][earlier]") {
    withEachManifold(movesExactlyAsChapter1);
}

TEST_CASE("through chapter 6: Euler's projectile is g h t / 2 off the parabola, the others on it", "[ch06][earlier]") {
    withEachManifold(projectileOffParabola);
}

TEST_CASE("through chapter 6: the T-handle flips and keeps |L|", "[ch06][earlier]") { withEachManifold(tHandleFlips); }

TEST_CASE("through chapter 6: the two boxes move as in chapter 2, and the narrowphase still agrees with the oracle",
          "[ch06][earlier]") {
    withEachManifold(twoBoxesAsChapter2);
}

TEST_CASE("through chapter 6: the contact gallery's contacts are finite, the EPA stepper's match EPA", "[ch06][earlier]") {
    withEachManifold(contactGalleryFinite);
}

TEST_CASE("through chapter 6: balls bounce to e^2 h, and e = 1 never rises above its start", "[ch06][earlier]") {
    withEachManifold(ballsBounce);
}

TEST_CASE("through chapter 6: head-on collisions conserve momentum and obey the restitution law", "[ch06][earlier]") {
    withEachManifold(headOnCollisions);
}

TEST_CASE("through chapter 6: a sliding ball rolls after 2v/(7 mu g) at 5/7 of its speed; ramps hold below atan(mu)",
          "[ch06][earlier]") {
    withEachManifold(slidingBallAndRamps);
}

TEST_CASE("through chapter 6: a dropped ball rests at the slop; a 10 kg ball on a 1 kg ball sinks less than twice it",
          "[ch06][earlier]") {
    withEachManifold(restingAtSlop);
}

TEST_CASE("through chapter 6: every chapter 4 scene stays finite and above the ground", "[ch06][earlier]") {
    withEachManifold(chapter4ScenesFinite);
}
