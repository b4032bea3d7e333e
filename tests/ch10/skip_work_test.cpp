// Chapter 10's shortcuts change the cost, not the answer: the sweep on grown boxes returns the pairs
// chapter 5's sweep returns, and a pair kept apart is one chapter 6 would not make a contact of.
#include "04_pgs/scenes.h"
#include "05_sap/chapter.h"
#include "06_manifolds/manifold.h"
#include "10_skip_work/chapter.h"
#include "10_skip_work/scenes.h"
#include "math/random.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace stepwise;

namespace {

Pipeline fastPipeline(const World& world) {
    SkipWorkOptions options;
    options.sleeping = false;
    return makeChapter10Pipeline(world, options);
}

}  // namespace
TEST_CASE("the sweep on grown boxes finds chapter 5's pairs, and skips the sweep when nothing left its box",
          "[ch10][broadphase]") {
    // Big enough to settle inside its grown boxes, small enough for chapter 8's solve under the sanitizers.
    World world = buildMixedPile(120);
    world.settings.sleeping = false;
    Pipeline pipeline = fastPipeline(world);
    int skipped = 0;
    for (int frame = 0; frame < 240; ++frame) {
        World fresh = world;
        sweepAndPrune(fresh);
        sweepAndPruneEnlarged(world);
        REQUIRE(world.candidatePairs == fresh.candidatePairs);
        skipped += world.broadphase.sweepSkipped ? 1 : 0;
        pipeline.step(world);
    }
    CHECK(skipped > 0);  // the pile settles inside its grown boxes before the end

    World pyramid = buildPyramidRow(1, 10);
    sweepAndPruneEnlarged(pyramid);
    CHECK_FALSE(pyramid.broadphase.sweepSkipped);
    sweepAndPruneEnlarged(pyramid);
    CHECK(pyramid.broadphase.sweepSkipped);
    // A body moved past the margin: a sweep again, and the moved box's pairs follow it.
    pyramid.bodies[1].transform.position.x() += 2 * pyramid.settings.boundsMargin;
    sweepAndPruneEnlarged(pyramid);
    CHECK_FALSE(pyramid.broadphase.sweepSkipped);
    World fresh = pyramid;
    sweepAndPrune(fresh);
    CHECK(pyramid.candidatePairs == fresh.candidatePairs);
}

TEST_CASE("no pair kept apart by the gap cache is one chapter 6 would make a contact of", "[ch10][cache]") {
    // Big enough to settle inside its grown boxes, small enough for chapter 8's solve under the sanitizers.
    World world = buildMixedPile(120);
    world.settings.sleeping = false;
    Pipeline pipeline = fastPipeline(world);
    long keptApart = 0;
    for (int frame = 0; frame < 300; ++frame) {
        pipeline.step(world);
        keptApart += static_cast<long>(world.pairGaps.size());
        if (frame % 20 != 19) continue;
        // The same pairs through the cache and through chapter 6 alone (which asks every pair): each
        // record chapter 6 makes must be in the cached list.
        World cached = world;
        sweepAndPrune(cached);
        World fresh = cached;
        ContactCacheScratch scratch;
        updateManifoldsCached(cached, 1, ManifoldOptions{}, ContactCacheRule{}, scratch);
        updateManifolds(fresh, 1, ManifoldOptions{});
        for (const Contact& contact : fresh.contacts) {
            if (contact.missedSteps > 0) continue;  // kept from the record alone, not found now
            INFO("frame " << frame << ", pair " << contact.bodyA << "-" << contact.bodyB);
            CHECK(findContact(cached.contacts, contact.pair()) != nullptr);
        }
    }
    CHECK(keptApart > 0);
}

TEST_CASE("stillApart answers as the arc cosine's test does, at the edge of the test", "[ch10][cache]") {
    // The bounds that spare the arc cosine may only decide where the exact test agrees: poses whose
    // gap left is within a hair of the distance kept, over turns from tiny to a half turn.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1, 1);
    int decidedBothWays[2] = {0, 0};
    for (int trial = 0; trial < 20000; ++trial) {
        PairGap gap;
        gap.gap = Real(0.5);
        gap.radiusB = Real(0.2 + 0.8 * std::abs(unit(random)));
        const Transform a{Vec3::Zero(), Quat::Identity()};
        const Vec3 axis = Vec3(Real(unit(random)), Real(unit(random)), Real(unit(random))).normalized();
        const double angle = std::pow(10.0, -6 + 6.5 * std::abs(unit(random)));  // 1e-6 to 3 rad
        const Transform b{Vec3(Real(0.01 * unit(random)), 0, 0), Quat(Eigen::AngleAxis<Real>(Real(std::min(angle, 3.1)), axis))};
        const Real cosHalf = std::min(Real(1), std::abs(b.rotation.coeffs().dot(gap.builtRelativeRotation.coeffs())));
        const Real left = gap.gap - ((b.position - gap.builtRelativePosition).norm() + 2 * math::acos(cosHalf) * gap.radiusB) -
                          Real(0.001);
        for (const Real keep : {left, std::nextafter(left, Real(1)), std::nextafter(left, Real(-1)), left * Real(1.0001)}) {
            const bool exact = left >= keep;
            CHECK(stillApart(gap, a, b, keep) == exact);
            ++decidedBothWays[exact ? 1 : 0];
        }
    }
    CHECK(decidedBothWays[0] > 0);
    CHECK(decidedBothWays[1] > 0);
}

TEST_CASE("a gap shrinks by at most what B moved in A's frame", "[ch10][cache]") {
    PairGap gap;
    gap.gap = Real(0.5);
    gap.radiusB = 1;
    const Transform a{Vec3::Zero(), Quat::Identity()};
    Transform b{Vec3(2, 0, 0), Quat::Identity()};
    gap.builtRelativePosition = b.position;
    CHECK(stillApart(gap, a, b, Real(0.1)));
    b.position.x() -= Real(0.3);  // 0.5 - 0.3 - 1 mm allowance = 0.199 left
    CHECK(stillApart(gap, a, b, Real(0.19)));
    CHECK_FALSE(stillApart(gap, a, b, Real(0.2)));
    b.position.x() += Real(0.3);
    b.rotation = Quat(Eigen::AngleAxis<Real>(Real(0.3), Vec3::UnitZ()));  // 0.3 rad at radius 1
    CHECK_FALSE(stillApart(gap, a, b, Real(0.2)));
    CHECK(stillApart(gap, a, b, Real(0.19)));
    // Moving A with B changes nothing: only the pose of B in A's frame counts.
    const Transform movedA{Vec3(5, 5, 5), Quat(Eigen::AngleAxis<Real>(1, Vec3::UnitY()))};
    const Transform movedB{movedA.apply(Vec3(2, 0, 0)), movedA.rotation};
    CHECK(stillApart(gap, movedA, movedB, Real(0.49)));
}

