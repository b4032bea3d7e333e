// Sweep and prune against brute force: the same pairs on random and degenerate scenes, the axis
// the variance picks, the incremental sort against a full one, and bounds that cover a frame.
#include "01_integrators/integrate.h"
#include "03_epa/narrowphase.h"
#include "05_sap/chapter.h"
#include "random_worlds.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace stepwise;
using test::Layout;

namespace {

std::vector<BodyPair> sapPairs(World& world) {
    sweepAndPrune(world);
    return world.candidatePairs;
}

std::vector<BodyPair> brutePairs(World& world) {
    bruteForceBroadphase(world);
    return world.candidatePairs;
}

}  // namespace

TEST_CASE("sweep and prune finds exactly brute force's pairs on 1,000 random scenes", "[ch05][sap]") {
    Random random(505);
    long pairsSeen = 0;
    for (int scene = 0; scene < 1000; ++scene) {
        const Layout layout = static_cast<Layout>(scene % static_cast<int>(Layout::Count));
        const int count = test::pick(random, 60);
        World world = test::randomWorld(random, layout, count);
        INFO("scene " << scene << " (" << toString(layout) << ", " << count << " bodies)");
        const std::vector<BodyPair> expected = brutePairs(world);
        const std::vector<BodyPair> found = sapPairs(world);
        REQUIRE(found == expected);  // the same set, and both in canonical order
        pairsSeen += static_cast<long>(found.size());
        for (const BodyPair& pair : found) {
            CHECK(pair.bodyA < pair.bodyB);
            CHECK(needsContact(world.bodies[pair.bodyA].type == BodyType::Dynamic,
                               world.bodies[pair.bodyB].type == BodyType::Dynamic));
        }
    }
    CHECK(pairsSeen > 10000);  // the scenes are not trivially empty
}

TEST_CASE("the incremental sweep stays equal to brute force while bodies move", "[ch05][sap]") {
    Random random(77);
    for (Layout layout : {Layout::Spread, Layout::HugeGround, Layout::OnePlane, Layout::Fast}) {
        World world = test::randomWorld(random, layout, 120);
        int incremental = 0;
        for (int step = 0; step < 40; ++step) {
            INFO(toString(layout) << ", step " << step);
            // Small random motions keep last step's order nearly right; now and then a big jump.
            const Real reach = step % 10 == 9 ? 8 : Real(0.3);
            for (Body& body : world.bodies)
                if (body.type != BodyType::Static)
                    body.transform.position += Vec3(test::uniformIn(random, -reach, reach), test::uniformIn(random, -reach, reach),
                                                    test::uniformIn(random, -reach, reach));
            const std::vector<BodyPair> found = sapPairs(world);
            incremental += world.broadphase.fullSort ? 0 : 1;
            World copy = world;
            REQUIRE(found == brutePairs(copy));
        }
        CHECK(incremental > 20);  // the incremental path was taken, not only full sorts
    }
}

TEST_CASE("intervals that touch exactly overlap, as Aabb::overlaps says", "[ch05][sap]") {
    // Hand-made bounds: no growth, values exactly equal at the shared faces.
    std::vector<Aabb> bounds(4);
    bounds[0].min = Vec3(0, 0, 0), bounds[0].max = Vec3(1, 1, 1);
    bounds[1].min = Vec3(1, 0, 0), bounds[1].max = Vec3(2, 1, 1);      // touches 0 on x
    bounds[2].min = Vec3(0, 1, 0), bounds[2].max = Vec3(1, 2, 1);      // touches 0 on y
    bounds[3].min = Vec3(2.5, 0, 0), bounds[3].max = Vec3(3, 1, 1);    // apart
    const std::vector<char> dynamic(4, 1);
    for (int axis = 0; axis < 3; ++axis) {
        INFO("axis " << axis);
        std::vector<SweepEndpoint> ends;
        makeEndpoints(bounds, axis, ends);
        fullSortEndpoints(ends);
        std::vector<BodyPair> swept, brute;
        sweepEndpoints(ends, bounds, dynamic, axis, swept);
        sortPairsCanonical(swept, 4);
        bruteForcePairs(bounds, dynamic, brute);
        CHECK(swept == brute);
        CHECK(swept == std::vector<BodyPair>{{0, 1}, {0, 2}, {1, 2}});  // 1 and 2 touch at an edge
    }
}

TEST_CASE("pairs of bodies that are not dynamic are never reported", "[ch05][sap]") {
    World world;
    auto add = [&](BodyType type, const Vec3& at) {
        BodyDef def;
        def.type = type;
        def.shape = Shape::box(Vec3(1, 1, 1));
        def.transform.position = at;
        return addBody(world, def);
    };
    const int ground = add(BodyType::Static, Vec3::Zero());
    const int wall = add(BodyType::Static, Vec3(Real(0.5), 0, 0));
    const int mover = add(BodyType::Kinematic, Vec3(0, Real(0.5), 0));
    const int other = add(BodyType::Kinematic, Vec3(0, Real(0.6), 0));
    const int crate = add(BodyType::Dynamic, Vec3(0, 1, 0));
    for (BroadphaseMode mode : {BroadphaseMode::Sap, BroadphaseMode::Brute}) {
        world.settings.broadphase = mode;
        findCandidatePairs(world);
        CHECK(world.candidatePairs ==
              std::vector<BodyPair>{{ground, crate}, {wall, crate}, {mover, crate}, {other, crate}});
    }
}

TEST_CASE("a body that became non-finite overlaps nothing and breaks nothing", "[ch05][sap]") {
    Random random(3);
    World world = test::randomWorld(random, Layout::Spread, 30);
    world.bodies[7].transform.position = Vec3(std::numeric_limits<Real>::quiet_NaN(), 0, 0);
    world.bodies[9].transform.position = Vec3(0, std::numeric_limits<Real>::infinity(), 0);
    const std::vector<BodyPair> found = sapPairs(world);
    CHECK(found == brutePairs(world));
    for (const BodyPair& pair : found) {
        CHECK(pair.bodyA != 7);
        CHECK(pair.bodyB != 7);
        CHECK(pair.bodyA != 9);
        CHECK(pair.bodyB != 9);
    }
}

TEST_CASE("the variance picks the axis the bodies are laid out along", "[ch05][sap]") {
    for (int along = 0; along < 3; ++along) {
        INFO("laid out along axis " << along);
        World world;
        Random random(11);
        for (int i = 0; i < 50; ++i) {
            BodyDef def;
            def.shape = Shape::sphere(Real(0.4));
            Vec3 position(test::uniformIn(random, -1, 1), test::uniformIn(random, -1, 1), test::uniformIn(random, -1, 1));
            position[along] = static_cast<Real>(3 * i);
            def.transform.position = position;
            addBody(world, def);
        }
        sweepAndPrune(world);
        CHECK(world.broadphase.axis == along);
        const Vec3 variance = world.broadphase.centreVariance;
        CHECK(variance[along] > 100 * variance[(along + 1) % 3]);
    }
}

TEST_CASE("the axis changes only when another spreads the bodies clearly more", "[ch05][sap]") {
    CHECK(chooseSweepAxis(Vec3(1, 2, 3), -1) == 2);
    CHECK(chooseSweepAxis(Vec3(5, 5, 5), -1) == 0);                       // ties: the lower index
    CHECK(chooseSweepAxis(Vec3(10, 1, Real(11.5)), 0) == 0);              // 15% more: keep x
    CHECK(chooseSweepAxis(Vec3(10, 1, Real(12.5)), 0) == 2);              // 25% more: switch to z
    CHECK(chooseSweepAxis(Vec3(0, 0, 0), 1) == 1);
}

TEST_CASE("the incremental sort gives the full sort's order after random motions", "[ch05][sap]") {
    Random random(2024);
    for (int trial = 0; trial < 200; ++trial) {
        const int count = 1 + test::pick(random, 300);
        std::vector<Aabb> bounds(static_cast<std::size_t>(count));
        for (Aabb& box : bounds) {
            const Vec3 centre(test::uniformIn(random, -20, 20), test::uniformIn(random, -20, 20), test::uniformIn(random, -20, 20));
            const Vec3 half = Vec3::Constant(test::uniformIn(random, 0, 2));
            box.min = centre - half, box.max = centre + half;
            if (trial % 7 == 0) box.min.x() = std::round(box.min.x()), box.max.x() = std::round(box.max.x());  // ties
        }
        const int axis = trial % 3;
        std::vector<SweepEndpoint> kept;
        makeEndpoints(bounds, axis, kept);
        fullSortEndpoints(kept);
        // Move everything a little (or, every fifth trial, a lot), then sort both ways.
        const Real reach = trial % 5 == 4 ? 30 : Real(0.5);
        for (Aabb& box : bounds) {
            const Vec3 shift(test::uniformIn(random, -reach, reach), test::uniformIn(random, -reach, reach), test::uniformIn(random, -reach, reach));
            box.min += shift, box.max += shift;
        }
        refreshEndpointValues(bounds, axis, kept);
        const long moves = insertionSortEndpoints(kept, trial % 2 == 0 ? 1L << 40 : 50);
        if (moves < 0) fullSortEndpoints(kept);  // gave up: a full sort finishes, as the stage does
        std::vector<SweepEndpoint> fresh;
        makeEndpoints(bounds, axis, fresh);
        fullSortEndpoints(fresh);
        INFO("trial " << trial << ", " << count << " bodies, moves " << moves);
        REQUIRE(kept.size() == fresh.size());
        for (std::size_t i = 0; i < kept.size(); ++i) {
            REQUIRE(kept[i].body == fresh[i].body);
            REQUIRE(kept[i].value == fresh[i].value);
        }
    }
}

TEST_CASE("a scene at rest is re-sorted incrementally, a changed axis or body count sorts afresh", "[ch05][sap]") {
    Random random(8);
    World world = test::randomWorld(random, Layout::Spread, 40);
    sweepAndPrune(world);
    CHECK(world.broadphase.fullSort);  // the first step has no order to start from
    sweepAndPrune(world);
    CHECK_FALSE(world.broadphase.fullSort);
    CHECK(world.broadphase.sortMoves == 0);
    sweepAndPrune(world, SortMode::Full);
    CHECK(world.broadphase.fullSort);
    BodyDef extra;
    extra.shape = Shape::sphere(1);
    addBody(world, extra);
    sweepAndPrune(world);
    CHECK(world.broadphase.fullSort);
    // Stretch the scene along another axis: the axis changes and the list is rebuilt.
    const int before = world.broadphase.axis;
    const int other = (before + 1) % 3;
    for (std::size_t i = 0; i < world.bodies.size(); ++i) world.bodies[i].transform.position[other] *= 100;
    sweepAndPrune(world);
    CHECK(world.broadphase.axis == other);
    CHECK(world.broadphase.fullSort);
}

TEST_CASE("pairs come out in canonical order whatever order the sweep found them in", "[ch05][sap]") {
    Random random(99);
    for (int size : {0, 1, 10, 500, 5000}) {
        std::vector<BodyPair> pairs;
        const int bodies = 3000;
        for (int i = 0; i < size; ++i) {
            const int a = test::pick(random, bodies), b = test::pick(random, bodies);
            if (a != b) pairs.push_back(BodyPair{std::min(a, b), std::max(a, b)});
        }
        std::vector<BodyPair> expected = pairs;
        std::sort(expected.begin(), expected.end());
        sortPairsCanonical(pairs, bodies);
        CHECK(pairs == expected);
    }
}

TEST_CASE("the bounds are the shape's box grown by the body's motion over a frame", "[ch05][sap]") {
    Random random(31);
    World world = test::randomWorld(random, Layout::Fast, 60);
    world.settings.substeps = 3;
    std::vector<Aabb> bounds;
    std::vector<char> dynamic;
    computeBroadphaseBounds(world, bounds, dynamic);
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const Body& body = world.bodies[i];
        const Aabb tight = computeAabb(body.shape, body.transform);
        const Real grow = boundsGrowth(world, static_cast<int>(i));
        // The one-pass bounds equal the readable definition up to the last bits.
        const Real slack = Real(1e-4) * (1 + tight.max.cwiseAbs().maxCoeff() + grow);
        INFO("body " << i);
        CHECK(((bounds[i].min - (tight.min.array() - grow).matrix()).cwiseAbs().maxCoeff()) <= slack);
        CHECK(((bounds[i].max - (tight.max.array() + grow).matrix()).cwiseAbs().maxCoeff()) <= slack);
        // ... and cover chapter 3's speculative margin over the frame, the most the narrowphase
        // takes a separated pair in from.
        CHECK(2 * grow >= speculativeMargin(world, static_cast<int>(i), static_cast<int>(i), world.settings.substeps - 1));
        CHECK(dynamic[i] == (body.type == BodyType::Dynamic ? 1 : 0));
    }
}

TEST_CASE("a pair that touches by the end of the frame was a candidate at its start", "[ch05][sap]") {
    Random random(404);
    int touchingLater = 0;
    for (int scene = 0; scene < 60; ++scene) {
        World world = test::randomWorld(random, scene % 2 ? Layout::Fast : Layout::Spread, 40);
        sweepAndPrune(world);
        const std::vector<BodyPair> candidates = world.candidatePairs;
        integrate(world, world.settings.dt);  // a whole frame of free motion, gravity included
        CollideOptions options;
        options.separationDistance = false;
        for (int a = 0; a < static_cast<int>(world.bodies.size()); ++a) {
            for (int b = a + 1; b < static_cast<int>(world.bodies.size()); ++b) {
                const Body& bodyA = world.bodies[a];
                const Body& bodyB = world.bodies[b];
                if (!needsContact(bodyA.type == BodyType::Dynamic, bodyB.type == BodyType::Dynamic)) continue;
                if (!collideShapes(bodyA.shape, bodyA.transform, bodyB.shape, bodyB.transform, options).intersect) continue;
                ++touchingLater;
                INFO("scene " << scene << ", pair " << a << "-" << b);
                CHECK(std::binary_search(candidates.begin(), candidates.end(), BodyPair{a, b}));
            }
        }
    }
    CHECK(touchingLater > 100);
}
